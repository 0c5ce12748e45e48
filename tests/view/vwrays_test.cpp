// SPDX-License-Identifier: MIT
//
// Runs the built vwrays against ray files made by real Radiance's vwrays.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
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

/// -pd (depth of field, Radiance's jitteraperture()): the rays of a pixel
/// leave random points of an aperture disc around the view point and all
/// pass through the point the plain ray reaches at the focal distance |vd|:
/// for a perspective view on the plane that far along vd, for a fisheye
/// along the ray (there the start also moves along vd by up to ±π/8 of the
/// aperture). The disc is filled uniformly: the mean squared radius is a
/// quarter of the aperture's, squared, over two.
TEST(Vwrays, ApertureRaysMeetAtTheFocus) {
    const double dia = 0.5, reach = 0.5 * dia;
    const std::string view = " -vp 1 2 3 -vd 0 0 4 -vu 0 1 0 -x 3 -y 3";
    {
        std::istringstream out(RunVwrays("-fa -c 300 -pd 0.5 -vtv -vh 40 -vv 40" + view));
        const std::vector<Ray> rays = ParseRays(out);
        ASSERT_EQ(rays.size(), 9u * 300u);
        double sumR2 = 0;
        for (std::size_t pixel = 0; pixel < 9; ++pixel) {
            double fx = 0, fy = 0;
            for (std::size_t k = 0; k < 300; ++k) {
                const Ray& r = rays[pixel * 300 + k];
                const double dx = r[0] - 1, dy = r[1] - 2, r2 = dx * dx + dy * dy;
                EXPECT_NEAR(r[2], 3.0, 1e-9);
                EXPECT_LE(r2, reach * reach * (1 + 1e-4));
                sumR2 += r2;
                const double t = 4.0 / r[5];  // to the plane z = 3 + 4
                const double x = r[0] + t * r[3], y = r[1] + t * r[4];
                if (k == 0) {
                    fx = x;
                    fy = y;
                }
                EXPECT_NEAR(x, fx, 2e-4) << "pixel " << pixel << " ray " << k;
                EXPECT_NEAR(y, fy, 2e-4) << "pixel " << pixel << " ray " << k;
            }
        }
        // 2700 draws of r², mean reach²/2, standard error about 0.6 %.
        EXPECT_NEAR(sumR2 / rays.size(), reach * reach / 2, 0.03 * reach * reach / 2);
    }
    {
        std::istringstream plain(RunVwrays("-fa -vta -vh 180 -vv 180" + view));
        std::istringstream out(RunVwrays("-fa -c 100 -pd 0.5 -vta -vh 180 -vv 180" + view));
        const std::vector<Ray> centre = ParseRays(plain), rays = ParseRays(out);
        ASSERT_EQ(centre.size(), 9u);
        ASSERT_EQ(rays.size(), 900u);
        for (std::size_t i = 0; i < rays.size(); ++i) {
            const Ray& c = centre[i / 100];
            if (c[3] == 0 && c[4] == 0 && c[5] == 0) continue;  // outside the fisheye
            const Ray& r = rays[i];
            EXPECT_LE(std::fabs(r[2] - 3.0), 3.14159265 / 8 * dia + 1e-9);
            // The focus, 4 along the plain ray, lies on this ray.
            const double f[3] = {1 + 4 * c[3], 2 + 4 * c[4], 3 + 4 * c[5]};
            const double v[3] = {f[0] - r[0], f[1] - r[1], f[2] - r[2]};
            // Its distance from the ray's line, |v × d| (d printed to six digits).
            const double c0 = v[1] * r[5] - v[2] * r[4], c1 = v[2] * r[3] - v[0] * r[5],
                         c2 = v[0] * r[4] - v[1] * r[3];
            EXPECT_LE(std::sqrt(c0 * c0 + c1 * c1 + c2 * c2), 1e-4) << "ray " << i;
        }
    }
}

}  // namespace
