// SPDX-License-Identifier: MIT
//
// AdviseHugePages: the advice reaches the kernel for the 2 MiB-aligned part
// of a large array (its mapping becomes eligible for transparent huge pages),
// and small, null or unaligned ranges are left alone without harm.
#include "core/huge_pages.h"

#include <gtest/gtest.h>
#include <sys/mman.h>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <vector>
#include <fstream>
#include <sstream>
#include <string>

namespace rt {
namespace {

/// The kernel's THP mode ("always", "madvise" or "never"), empty if unknown.
std::string ThpMode() {
    std::ifstream f("/sys/kernel/mm/transparent_hugepage/enabled");
    std::string line;
    std::getline(f, line);
    const auto open = line.find('['), close = line.find(']');
    return open == std::string::npos || close == std::string::npos
               ? ""
               : line.substr(open + 1, close - open - 1);
}

/// A field's line of the mapping holding `p` in /proc/self/smaps ("" if none).
std::string SmapsLineOf(const void* p, const std::string& field) {
    const auto a = reinterpret_cast<std::uintptr_t>(p);
    std::ifstream f("/proc/self/smaps");
    bool inside = false;
    for (std::string line; std::getline(f, line);) {
        std::uintptr_t lo = 0, hi = 0;
        char dash = 0;
        std::istringstream range(line);
        if (range >> std::hex >> lo >> dash >> hi && dash == '-' && line.find(' ') != std::string::npos &&
            line.find(':') > line.find(' ')) {
            inside = a >= lo && a < hi;
            continue;
        }
        if (inside && line.rfind(field, 0) == 0) return line;
    }
    return "";
}

std::string VmFlagsOf(const void* p) { return SmapsLineOf(p, "VmFlags:"); }

TEST(HugePages, LargeRangeIsAdvised) {
    if (ThpMode() != "madvise" && ThpMode() != "always") GTEST_SKIP() << "no transparent huge pages";
    constexpr std::size_t kBytes = std::size_t{8} << 20;
    void* map = mmap(nullptr, kBytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    ASSERT_NE(map, MAP_FAILED);
    // Start off a 2 MiB boundary, as a heap array does.
    char* data = static_cast<char*>(map) + 4096 + 16;
    const std::size_t bytes = kBytes - 8192;
    AdviseHugePages(data, bytes);
    // The aligned middle is advised ("hg" in VmFlags), the unaligned head not.
    const auto middle = (reinterpret_cast<std::uintptr_t>(data) + (std::uintptr_t{2} << 20)) &
                        ~((std::uintptr_t{2} << 20) - 1);
    EXPECT_NE(VmFlagsOf(reinterpret_cast<void*>(middle)).find(" hg"), std::string::npos);
    EXPECT_EQ(VmFlagsOf(data).find(" hg"), std::string::npos);
    std::memset(data, 7, bytes);  // still ordinary memory
    EXPECT_EQ(data[bytes - 1], 7);
    munmap(map, kBytes);
}

TEST(HugePages, SmallNullAndUnalignedRangesAreHarmless) {
    AdviseHugePages(nullptr, 0);
    AdviseHugePages(nullptr, std::size_t{64} << 20);
    char small[100] = {};
    AdviseHugePages(small, sizeof small);
    EXPECT_EQ(VmFlagsOf(small).find(" hg"), std::string::npos);
}

TEST(HugePages, ReservedHeapIsAdvised) {
#if defined(__SANITIZE_ADDRESS__) || !defined(__GLIBC__)
    GTEST_SKIP() << "not glibc's malloc";
#else
    if (ThpMode() != "madvise" && ThpMode() != "always") GTEST_SKIP() << "no transparent huge pages";
    EXPECT_FALSE(ReserveHeapInHugePages(std::size_t{1} << 20));  // too small to bother
    ASSERT_TRUE(ReserveHeapInHugePages(std::size_t{64} << 20));
    // Small blocks, more than the heap held free before: the last ones come
    // from the part just grown, which is advised. Their memory is ordinary.
    std::vector<char*> blocks;
    for (int i = 0; i < 4096; ++i) {
        blocks.push_back(static_cast<char*>(std::malloc(4000)));
        ASSERT_NE(blocks.back(), nullptr);
        std::memset(blocks.back(), i & 0xff, 4000);
    }
    EXPECT_NE(VmFlagsOf(blocks.back()).find(" hg"), std::string::npos);
    EXPECT_EQ(blocks[100][3999], 100);
    for (char* b : blocks) std::free(b);
#endif
}

#if !defined(__SANITIZE_ADDRESS__) && defined(__GLIBC__)
/// Kilobytes of the mapping holding `p` backed by transparent huge pages.
long AnonHugeKbOf(const void* p) {
    std::istringstream line(SmapsLineOf(p, "AnonHugePages:"));
    std::string name;
    long kb = -1;
    line >> name >> kb;
    return kb;
}

/// A counter of /proc/vmstat (-1 if absent).
long VmStat(const std::string& name) {
    std::ifstream f("/proc/vmstat");
    std::string key;
    long value = 0;
    while (f >> key >> value)
        if (key == name) return value;
    return -1;
}

/// Reserves 8 MiB, then checks that a block larger than all memory the heap
/// held free before is cut from a whole huge page: the reservation starts
/// the top chunk on a 2 MiB boundary (glibc puts a chunk's 16-byte header
/// right before the block), and nothing wrote to that page before it was
/// advised. Without the filler the head of the reserve, 4 KiB pages, would
/// come first.
void ExpectReserveStartsOnAWholeHugePage() {
    const std::size_t freeBefore = mallinfo2().fordblks;
    ASSERT_TRUE(ReserveHeapInHugePages(std::size_t{8} << 20));
    auto* block = static_cast<char*>(std::malloc(freeBefore + 4096));
    ASSERT_NE(block, nullptr);
    constexpr std::uintptr_t kHuge = std::uintptr_t{2} << 20;
    EXPECT_EQ((reinterpret_cast<std::uintptr_t>(block) - 16) % kHuge, 0u);
    const long fallbacks = VmStat("thp_fault_fallback");
    std::memset(block, 3, freeBefore + 4096);  // ordinary memory
    EXPECT_EQ(block[freeBefore], 3);
    if (ThpMode() == "madvise" || ThpMode() == "always") {
        EXPECT_NE(VmFlagsOf(block).find(" hg"), std::string::npos);
        // A page written before the advice makes the kernel give its 2 MiB
        // range 4 KiB pages without trying a huge one; when it tries and
        // has none to give, it counts a fallback.
        // Every 2 MiB page the block reaches is whole (the reserve is 8 MiB).
        const long pages = static_cast<long>((freeBefore + 4096 + 16 + kHuge - 1) / kHuge);
        if (VmStat("thp_fault_fallback") == fallbacks) {
            EXPECT_GE(AnonHugeKbOf(block), 2048 * pages);
        }
    }
    std::free(block);
}
#endif

TEST(HugePages, ReservedHeapStartsOnAWholeHugePage) {
#if defined(__SANITIZE_ADDRESS__) || !defined(__GLIBC__)
    GTEST_SKIP() << "not glibc's malloc";
#else
    ExpectReserveStartsOnAWholeHugePage();
#endif
}

TEST(HugePages, ReservedHeapStartsOnAWholeHugePageWhenMegabytesAreFree) {
#if defined(__SANITIZE_ADDRESS__) || !defined(__GLIBC__)
    GTEST_SKIP() << "not glibc's malloc";
#else
    // 3 MiB freed at the top of the heap and kept: the reservation's own
    // growth then writes a header past the first 2 MiB boundary.
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
    mallopt(M_TRIM_THRESHOLD, 64 << 20);
    void* freed = std::malloc(std::size_t{3} << 20);
    ASSERT_NE(freed, nullptr);
    std::free(freed);
    ASSERT_GE(mallinfo2().fordblks, std::size_t{3} << 20);
    ExpectReserveStartsOnAWholeHugePage();
#endif
}

}  // namespace
}  // namespace rt
