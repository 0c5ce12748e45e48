// SPDX-License-Identifier: MIT
//
// Transparent huge pages for the few large arrays a big model needs.
#pragma once

#include <cstddef>
#include <vector>

namespace rt {

/// Asks the kernel to back the 2 MiB-aligned part of [data, data + bytes)
/// with transparent huge pages (madvise MADV_HUGEPAGE), before it is first
/// written. On the virtual machines lazyrad is measured on, a first touch
/// costs about 10 µs per 4 KiB page, and a 110 000-polygon model's start-up
/// touched some 23 000 of them: half its time (docs/measured-choices.md).
/// Arrays of less than 2 MiB, systems without THP, and failures are left
/// as they are: it is only advice, and changes no value.
void AdviseHugePages(const void* data, std::size_t bytes);

/// Makes the heap's next `bytes` of allocations come from memory advised into
/// transparent huge pages, for a program whose many small blocks (records,
/// index nodes, a polygon's vertices, names, the readers' lists) would
/// otherwise fault in one 4 KiB page at a time. What glibc's tunable
/// glibc.malloc.hugetlb=1 does, which a program cannot set for itself: malloc
/// is told to keep what is freed (M_TRIM_THRESHOLD), to serve blocks up to
/// 32 MiB from the heap (M_MMAP_THRESHOLD, so larger lists land there too),
/// and to grow the heap by `bytes` at once (M_TOP_PAD, for one growth that
/// this forces); the free memory left below the next 2 MiB boundary is set
/// aside, so that the blocks that follow start on a whole huge page, and the
/// new part is advised. Only address space is taken: pages are backed as they
/// are first written. Returns whether the heap grew and was advised: false
/// below 4 MiB, outside glibc's malloc (a sanitizer's allocator), or when the
/// heap cannot grow (malloc then maps memory as usual). Changes no value the
/// program computes.
bool ReserveHeapInHugePages(std::size_t bytes);

/// What rtrace and rvimage reserve as they start, before anything is read: a
/// small scene, its ray core and some tens of thousands of ambient records
/// (about 200 bytes each) fit in it. Larger scenes reserve more as they load
/// (scene/build.cpp). Unwritten, it is address space only; each 2 MiB page
/// written is backed whole.
inline constexpr std::size_t kProgramHeapReserve = std::size_t{16} << 20;

/// The same for a vector's whole allocation (its capacity), right after it
/// is reserved.
template <class T>
void AdviseHugePages(const std::vector<T>& v) {
    AdviseHugePages(v.data(), v.capacity() * sizeof(T));
}

}  // namespace rt
