// SPDX-License-Identifier: MIT
//
// Runs the built imgcmp on pictures written by image/: exit codes and output.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "image/exr.h"
#include "image/hdr.h"

namespace rt {
namespace {

std::string Temp(const std::string& name) {
    return (std::filesystem::temp_directory_path() /
            ("lazyrad_imgcmp_" + std::to_string(::getpid()) + "_" + name))
        .string();
}

int RunImgcmp(const std::string& args, std::string* out = nullptr) {
    const std::string cmd = std::string(RT_BINARY_DIR) + "/bin/imgcmp " + args + " 2>/dev/null";
    FILE* pipe = popen(cmd.c_str(), "r");
    std::string text;
    char buf[256];
    std::size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, pipe)) > 0)
        text.append(buf, n);
    const int rc = pclose(pipe);
    if (out)
        *out = text;
    return WEXITSTATUS(rc);
}

TEST(Imgcmp, ComparesExrWithHdrAndHonoursLimits) {
    Image a(8, 8);
    for (int y = 0; y < 8; ++y) {
        for (int x = 0; x < 8; ++x)
            a.Set(x, y, Rgb::Grey(0.5));
    }
    Image b = a;
    b.Set(3, 4, Rgb::Grey(0.6));  // d = 0.1/0.55 at one pixel of 64
    const std::string exr = Temp("a.exr"), hdr = Temp("b.hdr");
    WriteExr(exr, a);
    WriteHdr(hdr, b);  // 0.5 and 0.6 are within RGBE rounding of themselves
    std::string out;
    EXPECT_EQ(RunImgcmp(exr + " " + exr, &out), 0);
    EXPECT_EQ(out, "rms 0 max 0 at 0 0\n");
    EXPECT_EQ(RunImgcmp(exr + " " + hdr + " -max 0.2 -rms 0.05", &out), 0);
    EXPECT_EQ(out.rfind("rms 0.02", 0), 0u) << out;
    EXPECT_NE(out.find("at 3 4"), std::string::npos) << out;
    EXPECT_EQ(RunImgcmp(exr + " " + hdr + " -max 0.1"), 1);
    EXPECT_EQ(RunImgcmp(exr + " " + hdr + " -rms 0.01"), 1);
    EXPECT_EQ(RunImgcmp(exr + " /nonexistent.hdr"), 2);
    EXPECT_EQ(RunImgcmp(exr), 2);
    WriteHdr(hdr, Image(4, 4));
    EXPECT_EQ(RunImgcmp(exr + " " + hdr), 2);  // size mismatch
    std::filesystem::remove(exr);
    std::filesystem::remove(hdr);
}

}  // namespace
}  // namespace rt
