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
    if (bytes < (std::size_t{4} << 20)) return false;
    // mallopt takes an int: at most 1 GiB is reserved (more is grown as usual).
    const int pad = static_cast<int>(std::min(bytes, std::size_t{1} << 30));
    // One block larger than all the heap's free memory must extend it: by
    // itself plus the pad. It stays below the raised mmap threshold unless
    // the heap already holds more than 32 MiB free, when nothing happens.
    const std::size_t probe = mallinfo2().fordblks + 4096;
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
    // What is freed stays in the heap, advised (the top chunk is never given
    // back, which a batch program does not miss).
    mallopt(M_TRIM_THRESHOLD, std::numeric_limits<int>::max());
    mallopt(M_TOP_PAD, pad);
    const auto before = reinterpret_cast<std::uintptr_t>(sbrk(0));
    void* block = std::malloc(probe);
    const auto after = reinterpret_cast<std::uintptr_t>(sbrk(0));
    std::free(block);
    mallopt(M_TOP_PAD, 128 << 10);  // glibc's default: later growth as before
    if (block == nullptr || after <= before + (std::uintptr_t{4} << 20)) return false;
    AdviseHugePages(reinterpret_cast<const void*>(before), after - before);
    return true;
#else
    static_cast<void>(bytes);
    return false;
#endif
}

}  // namespace rt
