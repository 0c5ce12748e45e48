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

/// The same for a vector's whole allocation (its capacity), right after it
/// is reserved.
template <class T>
void AdviseHugePages(const std::vector<T>& v) {
    AdviseHugePages(v.data(), v.capacity() * sizeof(T));
}

}  // namespace rt
