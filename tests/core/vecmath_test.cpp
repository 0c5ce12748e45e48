#include "core/vecmath.h"
#include "core/conventions.h"
#include "core/rgb.h"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

namespace rt {
namespace {

TEST(Vecmath, CrossIsRightHanded) {
    EXPECT_EQ(Cross(Vec3(1, 0, 0), Vec3(0, 1, 0)), Vec3(0, 0, 1));
}

TEST(Vecmath, PerpendicularIsUnitAndOrthogonal) {
    for (Vec3 n : {Vec3(0, 0, 1), Vec3(1, 0, 0), Vec3(0.6, 0.8, 0), Normalize(Vec3(1, 1, 1))}) {
        Vec3 p = Perpendicular(n);
        EXPECT_NEAR(Length(p), 1.0, 1e-12);
        EXPECT_NEAR(Dot(p, n), 0.0, 1e-12);
    }
}

// The samplers' sine and cosine: the series within ±π/4, and the full turn
// by quarter-turn reduction, both within a few ulps of the library's.
TEST(Vecmath, SinCosMatchTheLibrary) {
    double worstSmall = 0, worstTurn = 0;
    for (int k = 0; k <= 400000; ++k) {
        const double x = 2.0 * kPi * k / 400000.0;
        double c, s;
        SinCos(x, c, s);
        worstTurn = std::max({worstTurn, std::fabs(c - std::cos(x)), std::fabs(s - std::sin(x))});
        const double y = 0.25 * kPi * (2.0 * k / 400000.0 - 1.0);
        SinCosSmall(y, c, s);
        worstSmall = std::max({worstSmall, std::fabs(c - std::cos(y)), std::fabs(s - std::sin(y))});
    }
    EXPECT_LT(worstSmall, 3e-16);
    EXPECT_LT(worstTurn, 5e-16);
}

// Min and Max are std::fmin and std::fmax per component, NaN included: a
// NaN coordinate never takes over a bounding box.
TEST(Vecmath, MinMaxAreFminFmax) {
    const double nan = std::nan("");
    const double values[] = {-2.5, -0.0, 0.0, 1.0, 3e300, -INFINITY, INFINITY, nan};
    for (double a : values) {
        for (double b : values) {
            const Vec3 lo = Min(Vec3(a, b, a), Vec3(b, a, a));
            const Vec3 hi = Max(Vec3(a, b, a), Vec3(b, a, a));
            const double wantLo = std::fmin(a, b), wantHi = std::fmax(a, b);
            for (double got : {lo.x, lo.y}) {
                if (std::isnan(wantLo)) EXPECT_TRUE(std::isnan(got));
                else EXPECT_EQ(got, wantLo) << a << " " << b;
            }
            for (double got : {hi.x, hi.y}) {
                if (std::isnan(wantHi)) EXPECT_TRUE(std::isnan(got));
                else EXPECT_EQ(got, wantHi) << a << " " << b;
            }
        }
    }
    Bounds3 box;
    box.Extend(Vec3(1, 2, 3));
    box.Extend(Vec3(nan, -1, 4));
    EXPECT_EQ(box.lo, Vec3(1, -1, 3));
    EXPECT_EQ(box.hi, Vec3(1, 2, 4));
}

TEST(Rgb, BrightUsesRadianceWeights) {
    EXPECT_NEAR(Bright(Rgb(1, 1, 1)), 1.0, 1e-8);
    EXPECT_DOUBLE_EQ(Bright(Rgb(0, 1, 0)), 0.670114631);
    EXPECT_DOUBLE_EQ(Intens(Rgb(0.2, 0.7, 0.1)), 0.7);
}

}  // namespace
}  // namespace rt
