// SPDX-License-Identifier: MIT
//
// Runs the built vwrays against ray files made by real Radiance's vwrays.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

using Ray = std::array<double, 6>;

std::string RunVwrays(const std::string& args, int* status = nullptr) {
    const std::string cmd = std::string(RT_BINARY_DIR) + "/bin/vwrays " + args;
    FILE* pipe = popen(cmd.c_str(), "r");
    EXPECT_NE(pipe, nullptr);
    std::string out;
    char buf[4096];
    std::size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, pipe)) > 0)
        out.append(buf, n);
    const int rc = pclose(pipe);
    if (status)
        *status = WEXITSTATUS(rc);
    return out;
}

std::vector<Ray> ParseRays(std::istream& in) {
    std::vector<Ray> rays;
    Ray r;
    while (in >> r[0] >> r[1] >> r[2] >> r[3] >> r[4] >> r[5])
        rays.push_back(r);
    return rays;
}

void ExpectSameRays(const std::string& vf, const std::string& res, const std::string& ref) {
    std::istringstream out(RunVwrays("-fa -vf " + std::string(RT_SOURCE_DIR) + vf + " " + res));
    const std::vector<Ray> ours = ParseRays(out);
    std::ifstream refFile(std::string(RT_SOURCE_DIR) + ref);
    const std::vector<Ray> theirs = ParseRays(refFile);
    ASSERT_FALSE(theirs.empty());
    ASSERT_EQ(ours.size(), theirs.size());
    for (std::size_t i = 0; i < ours.size(); ++i) {
        for (int k = 0; k < 6; ++k) {
            ASSERT_NEAR(ours[i][static_cast<std::size_t>(k)],
                        theirs[i][static_cast<std::size_t>(k)], 1e-5)
                << "ray " << i << " component " << k;
        }
    }
}

TEST(Vwrays, CornellMatchesRadianceVwrays) {
    ExpectSameRays("/scenes/cornell/cornell.vf", "-x 32 -y 32", "/scenes/cornell/cam32.rays");
}

TEST(Vwrays, DaylitRoomMatchesRadianceAfterAspectReduction) {
    ExpectSameRays("/scenes/daylit_room/daylit_room.vf", "-x 32 -y 32",
                   "/scenes/daylit_room/cam32x24.rays");
}

TEST(Vwrays, DimensionsAndBinaryFormats) {
    const std::string vf =
        " -vf " + std::string(RT_SOURCE_DIR) + "/scenes/daylit_room/daylit_room.vf";
    EXPECT_EQ(RunVwrays("-d -x 32 -y 32" + vf), "-x 32 -y 24 -ld-\n");
    EXPECT_EQ(RunVwrays("-d -x 32 -y 32 -va 10" + vf), "-x 32 -y 24 -ld+\n");
    EXPECT_EQ(RunVwrays("-ff -x 32 -y 32" + vf).size(), 32u * 24u * 6u * 4u);
    EXPECT_EQ(RunVwrays("-fd -x 4 -y 4 -vh 10 -vv 10").size(), 16u * 6u * 8u);
    int status = 0;
    (void)RunVwrays("-x 4 -y 4 -vh 190 2>/dev/null", &status);
    EXPECT_EQ(status, 1);
    (void)RunVwrays("-x 4 -y 4 -vf /nonexistent.vf 2>/dev/null", &status);
    EXPECT_NE(status, 0);
    (void)RunVwrays("-x 4 -y 4 -bogus 2>/dev/null", &status);
    EXPECT_EQ(status, 1);
    // A bad view is reported in Radiance's words, without rvimage's "bad view: ".
    EXPECT_EQ(RunVwrays("-x 4 -y 4 -vh 190 2>&1 >/dev/null", &status),
              "vwrays: illegal horizontal view size\n");
    EXPECT_EQ(RunVwrays("-x 4 -y 4 -vo 2 -va 1 2>&1 >/dev/null", &status),
              "vwrays: illegal fore/aft clipping plane\n");
}

TEST(Vwrays, FisheyeCornersAreZeroRays) {
    std::istringstream out(RunVwrays("-fa -x 4 -y 4 -vta -vh 360 -vv 360"));
    const std::vector<Ray> rays = ParseRays(out);
    ASSERT_EQ(rays.size(), 16u);
    for (double c : rays[0])
        EXPECT_EQ(c, 0.0);
    EXPECT_NE(rays[5][4], 0.0);
}

}  // namespace
