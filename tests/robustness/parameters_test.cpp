// SPDX-License-Identifier: MIT
//
// Stiff cases, parameters (issue "Numerical stability"): the cornell box at
// three floor points with extreme ambient and ray-limit settings — -ad 1 and
// 100000, -ab 0 .. 50, -aa 0 .. 2, -ar 0 and 1000000, -lw 0 and 1, -as
// larger than -ad, and `-lr 8 -lw 0 -ab 8 -ad 8` (no weight limit at all).
// No NaN, Inf or negative number, ever, and exit status 0. Where
// Radiance 5.4a clamps or rejects a value (ambient.c setambres/setambacc and
// multambient, the integer check of its option parser;
// /work/shared/docs/radiance-notes.md §1.1, §4.1, §4.2, §4.10), lazyrad must
// do the same.
#include <chrono>
#include <cstdio>
#include <ostream>
#include <string>

#include <gtest/gtest.h>

#include "tests/robustness/robustness_run.h"
#include "tests/testing/rtrace_rows.h"

namespace {

using rt::testing::FiniteNonNegative;
using rt::testing::MaxRelativeDifference;
using rt::testing::Rows;
using rt::testing::RtraceRun;
using rt::testing::RunRtrace;
using rt::testing::WriteTempFile;

const std::string kCornell = rt::testing::kSourceDir + "/scenes/cornell/cornell.rad";

/// Floor points 1, 40 and 84 of scenes/cornell/floor.pts: the lit front
/// corner, the middle, the back corner in the tall block's shadow.
std::string ThreePoints() {
    return WriteTempFile("three.pts",
                         "0.2800 0.2800 0.001 0 0 1\n"
                         "2.5040 3.0600 0.001 0 0 1\n"
                         "5.2840 5.2840 0.001 0 0 1\n");
}

/// Cheap settings; each case overrides some of them (a later
/// option wins, as in Radiance).
const std::string kBase = "-I -n 1 -seed 1 -ab 2 -ad 64 -as 32 -aa .2 -ar 16 ";

struct Sweep {
    const char* name;     // test name suffix
    const char* options;  // added to kBase
};
void PrintTo(const Sweep& sweep, std::ostream* os) {
    *os << sweep.options;
}

class ParameterSweep : public ::testing::TestWithParam<Sweep> {};

/// Exit status 0, no warning, three finite non-negative rows, and never less
/// than the direct light alone (-ab 0): indirect light cannot be negative.
TEST_P(ParameterSweep, OutputIsFiniteAndNonNegative) {
    const std::string points = ThreePoints();
    const auto start = std::chrono::steady_clock::now();
    const RtraceRun run = RunRtrace(kBase + GetParam().options + " " + kCornell, points, 120);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%s: %.2f s\n", GetParam().options, seconds);
    ASSERT_EQ(run.status, 0) << run.err;
    EXPECT_EQ(run.err, "");
    const Rows rows = run.Numbers();
    ASSERT_TRUE(FiniteNonNegative(rows, 3, 3)) << run.out;
    const Rows direct = rt::testing::RunRows(kBase + "-ab 0 " + kCornell, points);
    ASSERT_TRUE(FiniteNonNegative(direct, 3, 3));
    for (size_t i = 0; i < rows.size(); ++i) {
        for (size_t c = 0; c < 3; ++c) {
            EXPECT_GE(rows[i][c], direct[i][c] * (1 - 1e-6)) << "point " << i << " channel " << c;
        }
    }
}

// Every case is cheap, the deep ones too: at -ab 50 the default -lr -10 still
// stops rays at the tenth reflection, and coarse records (-aa .5 -ar 4) keep
// the cache small.
INSTANTIATE_TEST_SUITE_P(
    Cornell, ParameterSweep,
    ::testing::Values(Sweep{"ad1", "-ad 1 -as 0"}, Sweep{"ad1_as512", "-ad 1 -as 512"},
                      Sweep{"ad100000", "-ab 1 -ad 100000 -as 0"},
                      Sweep{"ad100000_as50000", "-ab 1 -ad 100000 -as 50000"},
                      Sweep{"ab0", "-ab 0"}, Sweep{"ab1", "-ab 1"}, Sweep{"ab4", "-ab 4"},
                      Sweep{"ab8", "-ab 8"}, Sweep{"ab50", "-ab 50 -ad 8 -as 0 -aa .5 -ar 4"},
                      Sweep{"ab50_nocache", "-ab 50 -aa 0 -ad 8 -as 0"}, Sweep{"aa0", "-aa 0"},
                      Sweep{"aa01", "-aa .1"}, Sweep{"aa1", "-aa 1"}, Sweep{"aa2", "-aa 2"},
                      Sweep{"ar0", "-ar 0"}, Sweep{"ar1000000", "-ar 1000000"},
                      Sweep{"lw0", "-lw 0 -lr 10"}, Sweep{"lw1", "-lw 1"},
                      Sweep{"as_over_ad", "-ad 16 -as 1024"}),
    [](const ::testing::TestParamInfo<Sweep>& sweep) { return std::string(sweep.param.name); });

/// No weight limit and eight bounces, the other settings at their defaults
/// (-as 512, -aa .1, -ar 256). lazyrad finishes one point in seconds, nearly
/// all of it spent filling the cache (about ten thousand records at each of
/// levels 2-7); the two-minute limit leaves room for sanitizer builds and
/// busy machines. (-lw 0 needs -lr > 0: with Russian roulette it is
/// Radiance's fatal error, ZeroWeightWithRussianRouletteIsAnError.)
TEST(ParameterLimits, ZeroWeightLimitFinishes) {
    const std::string point = WriteTempFile("one.pts", "2.5040 3.0600 0.001 0 0 1\n");
    const auto start = std::chrono::steady_clock::now();
    const RtraceRun run = RunRtrace("-I -n 1 -seed 1 -lr 8 -lw 0 -ab 8 -ad 8 " + kCornell, point, 120);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("-lr 8 -lw 0 -ab 8 -ad 8: %.1f s\n", seconds);
    ASSERT_EQ(run.status, 0) << "124 means it did not finish in 120 s\n" << run.err;
    const Rows rows = run.Numbers();
    ASSERT_TRUE(FiniteNonNegative(rows, 1, 3)) << run.out;
    // The converged -ab 2 answer here is 0.872 (ref/floor_I_ab2.txt line
    // 40, green); six more bounces add some 8 % (0.946 measured).
    EXPECT_GT(rows[0][1], 0.85);
    EXPECT_LT(rows[0][1], 1.1);
}

/// Radiance 5.4a's rayorigin(): with Russian roulette (-lr <= 0, the default
/// -10) a weight limit of 0 or less stops the run at the first ray that
/// carries a coefficient (here the first hemisphere ray), as real Radiance
/// does on `rtrace -I -lw 0 -ab 8 -ad 8`; without such rays (-ab 0 in a
/// box of plastic) the run goes on.
TEST(ParameterLimits, ZeroWeightWithRussianRouletteIsAnError) {
    const std::string point = WriteTempFile("one.pts", "2.5040 3.0600 0.001 0 0 1\n");
    for (const char* options : {"-I -lw 0 -ab 8 -ad 8 ", "-I -lw -1 -lr 0 -ab 1 -ad 8 "}) {
        const RtraceRun run = RunRtrace(std::string("-h ") + options + kCornell, point, 60);
        EXPECT_EQ(run.status, 1) << options;
        EXPECT_EQ(run.err, "rtrace: fatal - zero ray weight in Russian roulette\n") << options;
    }
    const RtraceRun direct = RunRtrace("-h -I -lw 0 -ab 0 " + kCornell, point, 60);
    EXPECT_EQ(direct.status, 0) << direct.err;
    EXPECT_EQ(direct.err, "");
    // A mirror's reflected ray carries a coefficient too (Radiance 5.4a: the
    // same error at -ab 0; with -lr 5 it runs).
    const std::string mirror = WriteTempFile(
        "mirror.rad", "void mirror m 0 0 3 .9 .9 .9\nm polygon p 0 0 12 -1 -1 0 1 -1 0 1 1 0 -1 1 0\n");
    const std::string down = WriteTempFile("down.rays", "0 0 1 0 0 -1\n");
    const RtraceRun reflected = RunRtrace("-h -w- -ab 0 -lw 0 " + mirror, down, 60);
    EXPECT_EQ(reflected.status, 1);
    EXPECT_EQ(reflected.err, "rtrace: fatal - zero ray weight in Russian roulette\n");
    EXPECT_EQ(RunRtrace("-h -w- -ab 0 -lw 0 -lr 5 " + mirror, down, 60).status, 0);
}

// ----- where Radiance clamps or rejects -----

/// setambacc and setambres: a negative -aa is 0 (no cache), a negative -ar
/// is 0 (minimum radius 10·FTINY, maximum 0.2 of the scene cube).
TEST(ParameterClamps, NegativeAccuracyAndResolutionAreZero) {
    const std::string points = ThreePoints();
    for (const std::string option : {"-aa", "-ar"}) {
        const Rows zero = rt::testing::RunRows(kBase + option + " 0 " + kCornell, points);
        ASSERT_TRUE(FiniteNonNegative(zero, 3, 3)) << option;
        EXPECT_EQ(MaxRelativeDifference(
                      rt::testing::RunRows(kBase + option + " -5 " + kCornell, points), zero),
                  0)
            << option;
    }
}

/// multambient: -ad 0 or less means the ambient value (-av) everywhere, as
/// at -ab 0.
TEST(ParameterClamps, NoDivisionsMeansAmbientValue) {
    const std::string points = ThreePoints();
    const Rows value = rt::testing::RunRows(kBase + "-ab 0 -av .1 .2 .3 " + kCornell, points);
    ASSERT_TRUE(FiniteNonNegative(value, 3, 3));
    for (const char* ad : {"-ad 0 ", "-ad -5 "}) {
        EXPECT_EQ(MaxRelativeDifference(
                      rt::testing::RunRows(kBase + ad + "-av .1 .2 .3 " + kCornell, points), value),
                  0)
            << ad;
    }
}

/// -ad, -as and -ar take integers ("i" in Radiance's check): 1e6 is a
/// command line error, exit status 1.
TEST(ParameterClamps, IntegerOptionsRejectRealNumbers) {
    const std::string points = ThreePoints();
    for (const std::string option : {"-ar", "-ad", "-as"}) {
        const RtraceRun run = RunRtrace(kBase + option + " 1e6 " + kCornell, points);
        EXPECT_EQ(run.status, 1) << option;
        EXPECT_EQ(run.out, "") << option;
        EXPECT_EQ(run.err, "rtrace: fatal - command line error at '" + option + "'\n") << option;
    }
}

/// setambient: with -aa 0 the ambient file is not opened, with a warning.
TEST(ParameterClamps, ZeroAccuracyLeavesAmbientFileUnopened) {
    const std::string amb = rt::testing::RobustnessTempPath("zero_accuracy.amb");
    std::remove(amb.c_str());
    const RtraceRun run = RunRtrace(kBase + "-aa 0 -af " + amb + " " + kCornell, ThreePoints());
    EXPECT_EQ(run.status, 0);
    EXPECT_TRUE(FiniteNonNegative(run.Numbers(), 3, 3));
    EXPECT_EQ(run.err, "rtrace: warning - zero ambient accuracy so \"" + amb + "\" not opened\n");
    EXPECT_NE(access(amb.c_str(), F_OK), 0);
}

/// setambient opens the ambient file whenever -aa > 0, whatever -ad says:
/// with -ad 0 Radiance writes the file's header and no records, silently.
TEST(ParameterClamps, NoDivisionsKeepsAmbientFile) {
    const std::string amb = rt::testing::RobustnessTempPath("no_divisions.amb");
    std::remove(amb.c_str());
    const RtraceRun run = RunRtrace(kBase + "-ad 0 -af " + amb + " " + kCornell, ThreePoints());
    EXPECT_EQ(run.status, 0);
    EXPECT_TRUE(FiniteNonNegative(run.Numbers(), 3, 3));
    EXPECT_EQ(run.err, "");
    EXPECT_EQ(rt::testing::ReadText(amb).rfind("#?RADIANCE\n", 0), 0u);
    std::remove(amb.c_str());
}

}  // namespace
