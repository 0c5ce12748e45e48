// SPDX-License-Identifier: MIT
#include "core/huge_pages.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <limits>

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif
#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace rt {

void AdviseHugePages(const void* data, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    constexpr std::uintptr_t kHuge = std::uintptr_t{2} << 20;
    const auto begin = reinterpret_cast<std::uintptr_t>(data);
    const std::uintptr_t first = (begin + kHuge - 1) & ~(kHuge - 1);
    const std::uintptr_t last = (begin + bytes) & ~(kHuge - 1);
    if (data == nullptr || last <= first) return;
    // Ignored when it fails (THP disabled, an old kernel): nothing depends on it.
    static_cast<void>(madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE));
#else
    static_cast<void>(data);
    static_cast<void>(bytes);
#endif
}

bool ReserveHeapInHugePages(std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE) && defined(__GLIBC__) && \
    !defined(__SANITIZE_ADDRESS__)
    constexpr std::uintptr_t kHuge = std::uintptr_t{2} << 20;
    if (bytes < (std::size_t{4} << 20)) return false;
    // mallopt takes an int: at most 1 GiB is reserved (more is grown as usual).
    const int pad = static_cast<int>(std::min(bytes, std::size_t{1} << 30));
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
    // What is freed stays in the heap, advised (the top chunk is never given
    // back, which a batch program does not miss).
    mallopt(M_TRIM_THRESHOLD, std::numeric_limits<int>::max());
    mallopt(M_TOP_PAD, pad);
    // One block larger than all the heap's free memory must extend it: by
    // itself plus the pad. It stays below the raised mmap threshold unless
    // the heap already holds more than 32 MiB free, when nothing happens.
    // Freed, it joins the heap's top chunk, from which new blocks are cut.
    const auto before = reinterpret_cast<std::uintptr_t>(sbrk(0));
    const auto heapFree = mallinfo2();  // fordblks: all free; keepcost: the top chunk
    void* block = std::malloc(heapFree.fordblks + 4096);
    const auto after = reinterpret_cast<std::uintptr_t>(sbrk(0));
    // The block was cut from the start of the top chunk, and malloc wrote
    // the rest's header right after it, already in the grown part: that
    // page is touched, unadvised.
    const std::uintptr_t touched = before - heapFree.keepcost + heapFree.fordblks + 4096 + 64;
    const bool grew = block != nullptr;
    std::free(block);
    mallopt(M_TOP_PAD, 128 << 10);  // glibc's default: later growth as before
    if (!grew || after <= before + (std::uintptr_t{4} << 20)) return false;
    // The top chunk ends at the break and is mallinfo2().keepcost bytes long.
    // A block that fills it up to the next 2 MiB boundary above every page
    // written so far makes what follows start on a whole, untouched huge
    // page: without it, up to 2 MiB of a small program's blocks would still
    // come from the unaligned head, 4 KiB pages that cannot be huge. The
    // filler is kept for good; only its first bytes are written (they chain
    // the fillers, so that they stay reachable), the rest is address space,
    // never backed. A glibc chunk for n bytes spans n + 8 rounded up to 16
    // (at least 32) from the top chunk's 16-aligned start.
    const auto topStart = after - mallinfo2().keepcost;
    const std::uintptr_t aligned = (std::max(topStart + 32, touched) + kHuge - 1) & ~(kHuge - 1);
    if (aligned >= after) return true;  // grown, but no whole huge page left
    // Advised before the filler's split writes the new top chunk's header at
    // `aligned`: a page first touched unadvised would make its whole 2 MiB
    // range 4 KiB pages.
    AdviseHugePages(reinterpret_cast<const void*>(aligned), after - aligned);
    static void* fillers = nullptr;
    if (void* filler = std::malloc(aligned - topStart - sizeof(std::size_t))) {
        *static_cast<void**>(filler) = fillers;
        fillers = filler;
    }
    return true;
#else
    static_cast<void>(bytes);
    return false;
#endif
}

}  // namespace rt
