// SPDX-License-Identifier: MIT
//
// The function-driven materials (plastic2, metal2, trans2, ashik2, plasfunc,
// transdata, BRTDfunc) and BSDF files (a louvre BSDF, an aBSDF glazing and a
// BSDF proxy) inside a lit room whose window is an antimatter cut
// (rays through it carry a clipped set), through the whole indirect
// calculation: the matrix of tests/direct/ checks them against Radiance at
// -ab 0 and at -ab 1 without a cache; here they meet the ambient cache with
// every record method, deeper bounces, multiple specular samples and two
// threads. No NaN, Inf or negative number, exit status 0, no warning, and
// -I sensors never below their direct light (-ab 0), which the bounces
// can only add to.
#include <cctype>
#include <string>

#include <gtest/gtest.h>

#include "tests/robustness/robustness_run.h"
#include "tests/testing/rtrace_rows.h"

namespace {

using rt::testing::FiniteNonNegative;
using rt::testing::Rows;
using rt::testing::RtraceRun;
using rt::testing::RunRtrace;
using rt::testing::WriteTempFile;

std::string Room() {
    const std::string data = rt::testing::kSourceDir + "/tests/data/brdf/";
    const std::string bsdf = rt::testing::kSourceDir + "/tests/data/bsdf/";
    const std::string text =
        "void plastic wall 0 0 5 .5 .5 .5 0 0\n"
        "wall polygon floor 0 0 12 -2 -2 -1  2 -2 -1  2 2 -1  -2 2 -1\n"
        "wall polygon ceiling 0 0 12 -2 -2 2  -2 2 2  2 2 2  2 -2 2\n"
        "wall polygon south 0 0 12 -2 -2 -1  -2 -2 2  2 -2 2  2 -2 -1\n"
        "wall polygon north 0 0 12 -2 2 -1  2 2 -1  2 2 2  -2 2 2\n"
        "wall polygon west 0 0 12 -2 -2 -1  -2 2 -1  -2 2 2  -2 -2 2\n"
        "wall polygon east 0 0 12 2 -2 -1  2 -2 2  2 2 2  2 2 -1\n"
        "void light l 0 0 3 20 20 20\nl sphere bulb 0 0 4 0 0 1.5 .2\n"
        "void plastic2 satin 4 1 Px 0 . 0 6 .6 .5 .4 .06 .05 .2\n"
        "satin polygon a 0 0 12 -1.8 -1.8 -.9  -.2 -1.8 -.9  -.2 -.2 -.9  -1.8 -.2 -.9\n"
        "void metal2 brushed 4 Py 1 0 . 0 6 .8 .7 .6 .9 .2 .04\n"
        "brushed sphere b 0 0 4 1 1 -.5 .4\n"
        "void trans2 frost 4 0 0 1 . 0 8 .7 .6 .5 .04 .08 .25 .6 .7\n"
        "frost polygon c 0 0 12 -1.9 .5 -1  -1.9 .5 1  -1.9 1.5 1  -1.9 1.5 -1\n"
        "void plasfunc pf 2 lobe " + data + "brdf.cal 0 6 .6 .5 .4 .3 2 .05\n"
        "pf polygon d 0 0 12 .2 -1.8 -.9  1.8 -1.8 -.9  1.8 -.2 -.9  .2 -.2 -.9\n"
        "void transdata td 4 dv " + data + "angle.dat " + data +
        "brdf.cal cz 0 6 .5 .6 .7 .1 .5 .6\n"
        "td polygon e 0 0 12 1.9 -1 -1  1.9 -1 1  1.9 0 1  1.9 0 -1\n"
        "void BRTDfunc glaze 10 brefl brefl brefl btrans btrans btrans bd bd bd2 " + data +
        "brdf.cal 0 12 .1 .15 .2 .05 .05 .05 .2 .2 .2 .08 .5 .4\n"
        "glaze polygon g 0 0 12 -1 -1 .5  1 -1 .5  1 1 .5  -1 1 .5\n"
        "void ashik2 ash 4 1 0 0 . 0 8 .3 .3 .3 .2 .2 .2 60 8\n"
        "ash sphere as1 0 0 4 -1 1 -.7 .3\n"
        "void BSDF blinds 6 0 " + bsdf + "louvre.xml 0 0 1 . 0 0\n"
        "blinds polygon h 0 0 12 1.8 .2 -1  1.8 .2 1  1.8 1.2 1  1.8 1.2 -1\n"
        "void aBSDF frit 5 " + bsdf + "glaze.xml 0 1 0 . 0 0\n"
        "frit polygon i 0 0 12 -1.5 .6 1.2  -.5 .6 1.2  -.5 1.6 1.2  -1.5 1.6 1.2\n"
        "void BSDF proxy 6 .05 " + bsdf + "glaze.xml 0 1 0 . 0 3 .05 .05 .05\n"
        "proxy polygon j 0 0 12 .5 .5 1.5  .5 1.5 1.5  1.5 1.5 1.5  1.5 .5 1.5\n"
        // A window cut in the north wall, a sky beyond it.
        "void antimatter cut 1 wall 0 0\n"
        "cut polygon c1 0 0 12 -.5 1.8 0  .5 1.8 0  .5 1.8 1  -.5 1.8 1\n"
        "cut polygon c2 0 0 12 -.5 2.2 0  -.5 2.2 1  .5 2.2 1  .5 2.2 0\n"
        "cut polygon c3 0 0 12 -.5 1.8 0  -.5 1.8 1  -.5 2.2 1  -.5 2.2 0\n"
        "cut polygon c4 0 0 12 .5 1.8 0  .5 2.2 0  .5 2.2 1  .5 1.8 1\n"
        "cut polygon c5 0 0 12 -.5 1.8 0  -.5 2.2 0  .5 2.2 0  .5 1.8 0\n"
        "cut polygon c6 0 0 12 -.5 1.8 1  .5 1.8 1  .5 2.2 1  -.5 2.2 1\n"
        "void glow skyglow 0 0 4 2 2 2.5 0\nskyglow source sky 0 0 4 0 1 .3 120\n";
    return WriteTempFile("materials_room.rad", text);
}

/// Sensors on the floor under the glazing, beside the materials, and on
/// the materials' own surfaces.
std::string Sensors() {
    return WriteTempFile("materials_room.pts",
                         "0 0 -.99 0 0 1\n-1 -1 -.89 0 0 1\n1 -1 -.89 0 0 1\n"
                         "1.5 1.5 -.99 0 0 1\n-1.89 1 0 1 0 0\n1.89 -.5 0 -1 0 0\n"
                         "0 0 .51 0 0 1\n0 0 .49 0 0 -1\n0 1.5 -.99 0 0 1\n");
}

/// Camera rays onto each material, from both sides where it has two.
std::string Views() {
    return WriteTempFile("materials_room.rays",
                         "0 0 1.9 -.5 -.5 -1\n0 0 1.9 .5 -.5 -1\n0 0 1.9 .5 .5 -1\n"
                         "0 0 0 -1 .5 0\n-1.95 1 0 1 0 0\n0 0 0 1 -.4 0\n"
                         "0 0 1.9 .1 .1 -1\n0 0 0 .1 .2 1\n0 0 -.2 0 1 .3\n");
}

class MaterialsRoom : public ::testing::TestWithParam<const char*> {};

TEST_P(MaterialsRoom, FiniteAndAboveTheDirectLight) {
    const std::string room = Room();
    const std::string sensors = Sensors();
    const std::string base = "-I -seed 3 -ad 256 -as 128 ";  // RunRtrace adds -h
    const RtraceRun direct = RunRtrace(base + "-ab 0 " + room, sensors, 60);
    ASSERT_EQ(direct.status, 0) << direct.err;
    const RtraceRun run = RunRtrace(base + GetParam() + " " + room, sensors, 120);
    ASSERT_EQ(run.status, 0) << run.err;
    EXPECT_EQ(run.err, "");
    const Rows d = direct.Numbers();
    const Rows r = run.Numbers();
    ASSERT_EQ(r.size(), 9u);
    ASSERT_TRUE(FiniteNonNegative(r, 9, 3)) << run.out;
    ASSERT_TRUE(FiniteNonNegative(d, 9, 3)) << direct.out;
    double gained = 0;
    for (std::size_t i = 0; i < r.size(); ++i) {
        for (std::size_t c = 0; c < 3; ++c) {
            EXPECT_GE(r[i][c], d[i][c] * (1 - 1e-6)) << "sensor " << i << " channel " << c;
            gained += r[i][c] - d[i][c];
        }
    }
    EXPECT_GT(gained, 0.0);  // the bounces reach the sensors

    // What the materials themselves send: the same settings without -I.
    const RtraceRun seen = RunRtrace("-seed 3 -ad 256 -as 128 " + std::string(GetParam()) + " " + room,
                                     Views(), 120);
    ASSERT_EQ(seen.status, 0) << seen.err;
    EXPECT_EQ(seen.err, "");
    ASSERT_TRUE(FiniteNonNegative(seen.Numbers(), 9, 3)) << seen.out;
    // The window: the sky through the cut, not the wall.
    EXPECT_NEAR(seen.Numbers().back()[2], 2.5, 1e-9) << seen.out;
}

INSTANTIATE_TEST_SUITE_P(Settings, MaterialsRoom,
                         ::testing::Values("-ab 2 -ahm", "-ab 2 -ah+", "-ab 2 -ah-",
                                           "-ab 2 -aa 0 -ad 64", "-ab 4 -ad 256 -as 64",
                                           "-ab 2 -ss 4 -st 0", "-ab 2 -n 2",
                                           "-ab 2 -bv-"),
                         [](const ::testing::TestParamInfo<const char*>& p) {
                             std::string name;
                             for (const char* c = p.param; *c; ++c) {
                                 name += std::isalnum(static_cast<unsigned char>(*c)) ? *c
                                         : *c == '+'                                   ? 'p'
                                                                                       : '_';
                             }
                             return name;
                         });

}  // namespace
