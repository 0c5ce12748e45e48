// SPDX-License-Identifier: MIT
//
// AdviseHugePages: the advice reaches the kernel for the 2 MiB-aligned part
// of a large array (its mapping becomes eligible for transparent huge pages),
// and small, null or unaligned ranges are left alone without harm.
#include "core/huge_pages.h"

#include <gtest/gtest.h>
#include <sys/mman.h>

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

/// The VmFlags of the mapping holding `p` in /proc/self/smaps ("" if none).
std::string VmFlagsOf(const void* p) {
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
        if (inside && line.rfind("VmFlags:", 0) == 0) return line;
    }
    return "";
}

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

}  // namespace
}  // namespace rt
