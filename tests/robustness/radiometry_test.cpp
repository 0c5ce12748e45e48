// SPDX-License-Identifier: MIT
//
// Stiff cases, radiometry (issue "Numerical stability"), in a closed 1 m cube
// (tests/robustness/scenes/cube_*.rad): a lamp of radiance 1e10 among near-black
// walls must give exactly 1e10 times what a lamp of radiance 1 gives; black
// walls must add exactly no indirect light; walls of reflectance 0.999 must
// give the furnace's analytic answer after 50 bounces. Each case runs
// build/bin/rtrace end to end on seven -I sensors (cube_points.pts, including
// a corner and the lamp-facing ceiling) and seven rays from the cube's middle
// (cube_rays.txt: the walls, and the lamp).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <tuple>
#include <utility>

#include <gtest/gtest.h>

#include "tests/robustness/robustness_run.h"
#include "tests/testing/rtrace_rows.h"

namespace {

using rt::testing::FiniteNonNegative;
using rt::testing::MaxRelativeDifference;
using rt::testing::Rows;
using rt::testing::RtraceRun;
using rt::testing::RunRtrace;
using rt::testing::RobustnessScene;

const std::string kWalls = RobustnessScene("cube_walls.rad");
const std::string kPoints = RobustnessScene("cube_points.pts");
const std::string kRays = RobustnessScene("cube_rays.txt");
constexpr size_t kCount = 7;    // lines of cube_points.pts and of cube_rays.txt
constexpr size_t kLampRay = 5;  // the ray of cube_rays.txt that looks at the lamp

/// Sensors (-I) and rays of `scene` (read before the walls) with `options`;
/// every run must succeed with finite, non-negative rows.
struct Answers {
    Rows sensors, rays;
};
Answers RunCube(const std::string& options, const std::string& scene) {
    Answers a;
    const std::string args = options + " -n 1 " + RobustnessScene(scene) + " " + kWalls;
    for (auto [prefix, input, out] :
         {std::tuple{"-I ", &kPoints, &a.sensors}, std::tuple{"", &kRays, &a.rays}}) {
        const RtraceRun run = RunRtrace(prefix + args, *input);
        EXPECT_EQ(run.status, 0) << args << "\n" << run.err;
        *out = run.Numbers();
        EXPECT_TRUE(FiniteNonNegative(*out, kCount, 3)) << prefix << args << "\n" << run.out;
    }
    return a;
}

Rows Scaled(Rows rows, double factor) {
    for (auto& row : rows) {
        for (double& x : row)
            x *= factor;
    }
    return rows;
}

/// Direct only; two bounces with and without the cache; five bounces; each
/// cheap enough to run for both lamps.
const char* const kSettings[] = {
    "-ab 0",
    "-ab 2 -ad 256 -as 128 -aa .15 -ar 32 -seed 1",
    "-ab 2 -aa 0 -ad 256 -as 128 -seed 1",
    "-ab 5 -ad 64 -as 32 -aa .3 -ar 16 -seed 1",
};

/// Nothing in the calculation may depend on the absolute level of light:
/// every decision (shadow testing, super-sampling, Russian roulette) is
/// relative. The output has 7 significant digits, so equal answers agree to
/// 5e-7 after scaling; they agree to the last digit at all four settings.
/// Bound 2e-6. (At radiance 1 the ceiling sensor, which sees
/// no lamp, gets 6e-5 W/m² of reflected light, and the walls return 3e-5.)
TEST(BrightSource, ScalesWithSourceRadiance) {
    for (const char* options : kSettings) {
        const Answers one = RunCube(options, "cube_near_black_lamp_1.rad");
        const Answers bright = RunCube(options, "cube_near_black_lamp_1e10.rad");
        EXPECT_LT(MaxRelativeDifference(Scaled(bright.sensors, 1e-10), one.sensors), 2e-6)
            << options;
        EXPECT_LT(MaxRelativeDifference(Scaled(bright.rays, 1e-10), one.rays), 2e-6) << options;
        ASSERT_EQ(bright.rays.size(), kCount);
        EXPECT_EQ(bright.rays[kLampRay][1], 1e10) << options;
    }
    // Five bounces with other seeds: the deeper records' hemispheres are
    // dim here (about 1e-10 at the third level), and a threshold on
    // absolute brightness (Radiance's, for Hessian records) broke the
    // scaling at seeds 4 and 5.
    for (const char* seed : {"2", "3", "4", "5"}) {
        const std::string options = std::string("-ab 5 -ad 64 -as 32 -aa .3 -ar 16 -seed ") + seed;
        const Answers one = RunCube(options, "cube_near_black_lamp_1.rad");
        const Answers bright = RunCube(options, "cube_near_black_lamp_1e10.rad");
        EXPECT_LT(MaxRelativeDifference(Scaled(bright.sensors, 1e-10), one.sensors), 2e-6)
            << options;
    }
}

/// Reflectance 0: the walls return exactly 0 to every ray, so indirect
/// light is exactly 0 and -I at any -ab equals -ab 0 to the last digit, even
/// with an ambient value (-av 1 1 1), which black walls reflect as 0 too.
TEST(BlackMaterials, GiveNoIndirectLight) {
    const Answers direct = RunCube("-ab 0", "cube_black.rad");
    ASSERT_EQ(direct.rays.size(), kCount);
    for (size_t i = 0; i < kCount; ++i) {
        EXPECT_EQ(direct.rays[i][1], i == kLampRay ? 10.0 : 0.0) << "ray " << i;
    }
    for (const char* options :
         {"-ab 2 -ad 512 -as 256 -aa .1 -ar 64 -seed 1", "-ab 2 -aa 0 -ad 256 -as 128 -seed 1",
          "-ab 8 -ad 64 -as 32 -aa .1 -ar 64 -seed 1",
          "-ab 2 -ad 512 -as 256 -aa .1 -ar 64 -av 1 1 1 -aw 0 -seed 1"}) {
        const Answers a = RunCube(options, "cube_black.rad");
        EXPECT_EQ(MaxRelativeDifference(a.sensors, direct.sensors), 0) << options;
        EXPECT_EQ(MaxRelativeDifference(a.rays, direct.rays), 0) << options;
    }
}

// ----- the 0.999 furnace -----

constexpr double kRho = 0.999;

/// Every -I sensor gets pi rho^n and every ray rho^(n+1) (with -av 1 1 1):
/// each of the n bounces multiplies the light beyond the last one by rho.
/// Fails once, with the worst value, if any deviates by more than `tolerance`.
void ExpectFurnace(const Answers& a, int n, double tolerance, const std::string& options) {
    ASSERT_EQ(a.sensors.size(), kCount);
    ASSERT_EQ(a.rays.size(), kCount);
    const double sensor = M_PI * std::pow(kRho, n);
    const double ray = std::pow(kRho, n + 1);
    double worst = 0, worstValue = 0, want = 0;
    for (const auto& [rows, expected] : {std::pair{&a.sensors, sensor}, std::pair{&a.rays, ray}}) {
        for (const auto& row : *rows) {
            for (size_t c = 0; c < 3; ++c) {
                const double rel = std::fabs(row[c] / expected - 1);
                if (!(rel <= worst)) {
                    worst = rel;
                    worstValue = row[c];
                    want = expected;
                }
            }
        }
    }
    EXPECT_LT(worst, tolerance) << options << ": " << worstValue << " where " << want
                                << " was expected (sensors pi rho^" << n << ", rays rho^" << n + 1
                                << ")";
}

const std::string kFurnace = "-av 1 1 1 -aw 0 -seed 1 ";

/// -lr 0 -lw 1e-30: no ray is cut short (the weights fall to 0.5^51 = 4e-16
/// with the cache), so all 50 bounces happen. With 50 record levels of
/// coarse records the answers came out exact to the 7 printed digits (seeds
/// 1-3); with -aa .1 -ar 256 (fine records, far slower) 1.3e-4 low. Bound
/// 5e-4. The classic, the Hessian and the mixed records (-ah-, -ah+, -ahm);
/// the Hessian ones only since a hemisphere uniform within rounding gets no
/// translational gradient (hessian.cpp; before, -ah+ rays came out 3.0 and
/// 3.5 where 0.95 was expected). The mixed ones only since a ray leaving a
/// wall within the distance tolerance (1e-6) of a second wall hits that wall
/// (RayCore::Intersect's `leaving`): at seed 1 of the second setting a few
/// records lie that close to a cube edge, their rays towards the other wall
/// passed through it, and the Hessian gradients carried the loss up the
/// levels (6.78 where 2.99 was expected).
TEST(Furnace, FiftyBouncesConverge) {
    for (const char* method : {"-ah- ", "-ah+ ", "-ahm "}) {
        for (const char* options : {"-ab 50 -ad 16 -as 8 -aa .2 -ar 4 -lr 0 -lw 1e-30",
                                    "-ab 50 -ad 64 -as 32 -aa .3 -ar 4 -lr 0 -lw 1e-30"}) {
            ExpectFurnace(RunCube(kFurnace + method + options, "cube_furnace.rad"), 50, 5e-4,
                          method + std::string(options));
        }
    }
}

/// Radiance's rule (radiance-notes §4.1, §4.5): a hemisphere none of whose
/// sample rays may be traced (here: -lr -10 refuses the eleventh
/// reflection) falls back to the ambient value, so -ab 11 gives the -ab 10
/// answer, with the cache and without it.
TEST(Furnace, DepthLimitFallsBackToAmbientValue) {
    for (const char* options : {"-ab 11 -ad 16 -as 8 -aa .3 -ar 4 -lr -10 -lw 1e-30",
                                "-ab 11 -aa 0 -ad 1 -as 0 -lr -10 -lw 1e-30"}) {
        ExpectFurnace(RunCube(kFurnace + options, "cube_furnace.rad"), 10, 5e-4, options);
    }
}

/// Mean over seeds 1 .. `seeds` of the relative error of every sensor and
/// ray against the furnace at -ab n, and the largest single-seed error (each
/// the average over that seed's 14 values).
struct SeedErrors {
    double mean = 0, worst = 0;
};
SeedErrors FurnaceErrorOverSeeds(const std::string& options, int n, int seeds) {
    SeedErrors e;
    for (int seed = 1; seed <= seeds; ++seed) {
        const Answers a = RunCube("-av 1 1 1 -aw 0 -seed " + std::to_string(seed) + " " + options,
                                  "cube_furnace.rad");
        double sum = 0;
        for (const auto& row : a.sensors)
            sum += row[1] / (M_PI * std::pow(kRho, n)) - 1;
        for (const auto& row : a.rays)
            sum += row[1] / std::pow(kRho, n + 1) - 1;
        const double err = sum / static_cast<double>(a.sensors.size() + a.rays.size());
        e.mean += err / seeds;
        e.worst = std::max(e.worst, std::fabs(err));
    }
    return e;
}

/// With the default -lr -10 -lw 2e-3, hemisphere sample rays at the tenth
/// reflection weigh 0.5^10 < 2e-3. Radiance plays Russian roulette with
/// them; lazyrad's earlier attempt to keep those records cacheable (losers as
/// zero samples) was unbiased but noisy: -0.27 % mean, 0.48 % worst seed at
/// -ar 8, and with coarse records (-ar 4, one record per wall and level)
/// the noise compounded down the levels: -ab 10 8.3 % dark on average over
/// seeds 1-6, -ab 50 -lr 0 62 % dark. Hemisphere samples now never play
/// roulette (the weight already sets their number, -ab bounds the depth),
/// and the furnace stays exact to the printed digits. Bound 1e-3 per seed.
TEST(Furnace, DeepBouncesBelowTheWeightLimitStayExact) {
    for (const auto& [options, n, seeds] :
         {std::tuple{"-ab 10 -ad 16 -as 8 -aa .2 -ar 8", 10, 2},
          std::tuple{"-ab 10 -ad 16 -as 8 -aa .3 -ar 4", 10, 3},
          std::tuple{"-ab 50 -ad 16 -as 8 -aa .3 -ar 4 -lr 0", 50, 3}}) {
        const SeedErrors e = FurnaceErrorOverSeeds(options, n, seeds);
        EXPECT_LT(e.worst, 1e-3) << options << ": mean " << e.mean << ", worst seed " << e.worst;
    }
}

/// Without the cache, -ad 1 asks for one sample per hemisphere: 50 bounces
/// are 50 rays per sensor (Radiance: ns = 1), exact to the printed digits.
/// A floor of 1 x 3 divisions per hemisphere would trace 3^50 rays and never
/// finish.
TEST(Furnace, FiftyBouncesWithoutCacheFinish) {
    const std::string options = "-ab 50 -aa 0 -ad 1 -as 0 -lr 0 -lw 1e-30";
    const RtraceRun run = RunRtrace(
        "-I -n 1 " + kFurnace + options + " " + RobustnessScene("cube_furnace.rad") + " " + kWalls,
        kPoints, 60);
    ASSERT_EQ(run.status, 0) << "124 means it did not finish in 60 s\n" << run.err;
    const Rows rows = run.Numbers();
    ASSERT_TRUE(FiniteNonNegative(rows, kCount, 3));
    for (const auto& row : rows) {
        EXPECT_NEAR(row[1], M_PI * std::pow(kRho, 50), 5e-4 * M_PI * std::pow(kRho, 50));
    }
}

}  // namespace
