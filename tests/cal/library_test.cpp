// SPDX-License-Identifier: MIT
//
// The built-in library itself: the table against radiance-functions.md §9.9,
// rand(), and the noise functions' properties and values (§9.9.1, §9.13
// item 19).
#include "cal/library.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

#include "cal/noise.h"

namespace rt::cal {
namespace {

TEST(CalLibrary, EveryFunctionOfRtrace) {
    const std::set<std::string> expected = {
        "if",  "select", "min",  "max",    "rand",    "floor",   "ceil",    "sqrt",   "exp",
        "log", "log10",  "sin",  "cos",    "tan",     "asin",    "acos",    "atan",   "atan2",
        "arg", "erf",    "erfc", "noise3", "noise3x", "noise3y", "noise3z", "fnoise3"};
    std::set<std::string> names;
    for (const LibraryFunction& f : Library()) {
        names.insert(std::string(f.name));
        EXPECT_EQ(FindLibraryFunction(f.name, true), &f - Library().data());
        EXPECT_EQ(f.constant, f.name != "arg") << f.name;  // arg(n) is never folded
    }
    EXPECT_EQ(names, expected);
    EXPECT_EQ(FindLibraryFunction("noise3", false), -1);  // rtrace only
    EXPECT_EQ(FindLibraryFunction("abs", true), -1);      // rayinit.cal's, not built in
    EXPECT_EQ(FindLibraryFunction("pow", true), -1);
}

TEST(CalLibrary, HashRandom) {
    // §9.13 item 9 (rcalc's %.9g).
    EXPECT_NEAR(HashRandom(1), 0.35008306, 5e-9);
    EXPECT_NEAR(HashRandom(0.5), 0.234347013, 5e-10);
    EXPECT_NEAR(HashRandom(0), 0.954473516, 5e-10);
    EXPECT_NEAR(HashRandom(-3.7), 0.0311368565, 5e-11);
    EXPECT_NEAR(HashRandom(1e6), 0.312365513, 5e-10);
    for (int i = -1000; i < 1000; ++i) {
        const double r = HashRandom(i * 0.37);
        EXPECT_GE(r, 0.0);
        EXPECT_LT(r, 1.0);
    }
}

TEST(CalNoise, ZeroOnTheLatticeAndBounded) {
    for (int x = -3; x <= 3; ++x) {
        for (int y = -3; y <= 3; ++y) EXPECT_EQ(Noise3(x, y, 7 - x), 0.0);
    }
    for (int i = 0; i < 5000; ++i) {
        const double x = std::sin(i * 1.1) * 50, y = std::cos(i * 0.7) * 50, z = i * 0.013;
        EXPECT_LE(std::fabs(Noise3(x, y, z)), 1.1);
        EXPECT_LE(std::fabs(FractalNoise3(x, y, z)), 1.5);
    }
    EXPECT_EQ(Noise3(NAN, 0, 0), 0.0);
    EXPECT_TRUE(std::isfinite(FractalNoise3(1e300, -1e300, NAN)));
}

TEST(CalNoise, GradientIsTheBackwardDifference) {
    const double x = 1.3, y = 2.7, z = -0.4, e = 0.0005;
    EXPECT_DOUBLE_EQ(Noise3X(x, y, z), (Noise3(x, y, z) - Noise3(x - e, y, z)) / e);
    EXPECT_DOUBLE_EQ(Noise3Y(x, y, z), (Noise3(x, y, z) - Noise3(x, y - e, z)) / e);
    EXPECT_DOUBLE_EQ(Noise3Z(x, y, z), (Noise3(x, y, z) - Noise3(x, y, z - e)) / e);
}

TEST(CalNoise, SpecValues) {
    EXPECT_DOUBLE_EQ(Noise3(0.5, 0.5, 0.5), -0.25);
    EXPECT_NEAR(Noise3(1.3, 2.7, -0.4), -0.1102238, 5e-8);
    EXPECT_NEAR(Noise3(-7.25, 100.5, 3.125), 0.4606968, 5e-8);
    EXPECT_NEAR(FractalNoise3(0.5, 0.5, 0.5), -0.3412551, 5e-8);
    EXPECT_NEAR(FractalNoise3(1.3, 2.7, -0.4), -0.07206283, 5e-9);
    EXPECT_NEAR(FractalNoise3(-7.25, 100.5, 3.125), 0.5449893, 5e-8);
}

}  // namespace
}  // namespace rt::cal
