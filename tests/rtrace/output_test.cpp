// SPDX-License-Identifier: MIT
#include "rtrace/output.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "core/error.h"

namespace rt {
namespace {

OutputSpec SpecOf(const std::string& letters, std::vector<std::string>* warnings = nullptr,
                  RtraceOptions o = {}) {
    o.outputSpec = letters;
    return ParseOutputSpec(o, [warnings](const std::string& w) {
        if (warnings) warnings->push_back(w);
    });
}

std::string SpecError(const std::string& letters, RtraceOptions o = {}) {
    try {
        SpecOf(letters, nullptr, o);
    } catch (const Error& e) {
        return e.what();
    }
    return "(no error)";
}

std::string Write(char format, const std::string& letters, const RayResult& r) {
    std::ostringstream out;
    {
        RecordWriter writer(format, out);
        writer.WriteRecord(letters, r);
        writer.Flush();
    }
    return out.str();
}

std::string ReferenceLine(int lineNumber) {
    std::ifstream f(std::string(RT_SOURCE_DIR) + "/scenes/cornell/ref/cam32_ab0_ovlpnNm.txt");
    std::string line;
    for (int i = 0; i < lineNumber && std::getline(f, line); ++i) {
    }
    return line + "\n";
}

TEST(OutputSpecParse, ComponentCounts) {
    EXPECT_EQ(SpecOf("v").components, 3);
    EXPECT_EQ(SpecOf("ovlpnNm").components, 3 + 3 + 1 + 3 + 3 + 3 + 1);
    EXPECT_EQ(SpecOf("wLlRXsmMc~v").components, 1 + 1 + 1 + 1 + 1 + 1 + 1 + 1 + 2 + 0 + 3);
    EXPECT_EQ(SpecOf("vrx").components, 9);
    EXPECT_EQ(SpecOf("vtv").components, 0);  // trace mode has no NCOMP
    EXPECT_EQ(SpecOf("vt").components, 3);   // trailing t ignored
    // Radiance 5.4a: trace mode with an empty trace list has NCOMP, counting
    // the letters the second t dropped from it too.
    EXPECT_EQ(SpecOf("vtt").components, 3);
    EXPECT_EQ(SpecOf("vtLtt").components, 4);
    EXPECT_EQ(SpecOf("vTt").components, 3);
}

/// A second t starts the trace list again, as in Radiance 5.4a (-ovtLtm
/// traces the modifier alone).
TEST(OutputSpecParse, EachTStartsTheTraceListAgain) {
    OutputSpec s = SpecOf("vtLtm");
    EXPECT_EQ(s.fields, "v");
    EXPECT_EQ(s.traceFields, "m");
    EXPECT_FALSE(s.traceShadows);
    s = SpecOf("vtLTm");
    EXPECT_EQ(s.traceFields, "m");
    EXPECT_TRUE(s.traceShadows);
    s = SpecOf("vTLtm");
    EXPECT_TRUE(s.traceShadows);  // once set, a later t does not clear it
    s = SpecOf("vtLT");
    EXPECT_TRUE(s.traceShadows);  // a trailing T still traces shadow rays
    EXPECT_EQ(s.traceFields, "L");
}

TEST(OutputSpecParse, SplitsTraceSection) {
    OutputSpec s = SpecOf("v~TmWv");
    EXPECT_EQ(s.fields, "v~");
    EXPECT_EQ(s.traceFields, "mWv");
    EXPECT_TRUE(s.trace);
    EXPECT_TRUE(s.traceShadows);
    s = SpecOf("otv");
    EXPECT_EQ(s.fields, "o");
    EXPECT_FALSE(s.traceShadows);
    s = SpecOf("vT");
    EXPECT_FALSE(s.trace);
    EXPECT_FALSE(s.traceShadows);
    EXPECT_EQ(s.fields, "v");
}

TEST(OutputSpecParse, CastOnlyLetters) {
    for (char c : std::string("odcLpNswmM~")) EXPECT_TRUE(SpecOf(std::string(1, c)).castOnly) << c;
    for (char c : std::string("vVWlnrxRX")) EXPECT_FALSE(SpecOf(std::string(1, c)).castOnly) << c;
    EXPECT_FALSE(SpecOf("otp").castOnly);
}

TEST(OutputSpecParse, ErrorsAndWarnings) {
    EXPECT_EQ(SpecError(""), "empty output specification");
    EXPECT_EQ(SpecError("vq"), "unrecognized output option 'q'");
    EXPECT_EQ(SpecError("v-"), "unrecognized output option '-'");
    RtraceOptions color;
    color.outputFormat = 'c';
    EXPECT_EQ(SpecError("vv", color), "color format only with -ov, -or, -ox");
    EXPECT_EQ(SpecError("o", color), "color format only with -ov, -or, -ox");
    for (const char* ok : {"v", "r", "x"}) EXPECT_EQ(SpecError(ok, color), "(no error)");
    RtraceOptions irr;
    irr.shading.irradiance = IrradianceMode::Immediate;
    EXPECT_EQ(SpecError("pN", irr), "-I+ and -i+ options require some value output");
    irr = {};
    irr.shading.irradiance = IrradianceMode::AtHit;
    EXPECT_EQ(SpecError("m", irr), "-I+ and -i+ options require some value output");

    std::vector<std::string> w;
    SpecOf("vV", &w);
    EXPECT_EQ(w, std::vector<std::string>{"-oVW options require trace mode"});
    w.clear();
    SpecOf("vR", &w, irr);
    EXPECT_EQ(w, std::vector<std::string>{"-orRxX options incompatible with -I+ and -i+"});
    w.clear();
    RtraceOptions amb;
    amb.ambient.bounces = 1;
    SpecOf("vtV", &w, amb);
    EXPECT_EQ(w, std::vector<std::string>{"-otV accuracy depends on -aa 0 -as 0"});
    w.clear();
    amb.ambient.accuracy = 0;
    amb.ambient.superSamples = 0;
    SpecOf("vtVW", &w, amb);
    EXPECT_TRUE(w.empty());
}

RayResult RedWallHit() {
    // Line 33 of the Cornell reference: a hit on the red wall.
    RayResult r;
    r.value = Rgb(6.703628e-03, 6.916441e-04, 5.320340e-04);
    r.unmirroredLength = 8.953327e+00;
    r.firstLength = 8.953327e+00;
    r.point = Vec3(-4.440892e-16, 1.037216e-01, 5.340647e+00);
    r.normal = Vec3(1, 0, 0);
    r.geometricNormal = Vec3(1, 0, 0);
    r.surfaceName = "red_wall";
    r.modifierName = "red";
    r.materialName = "red";
    return r;
}

TEST(RecordWriterAscii, MatchesRadianceReferenceLines) {
    std::string ref = ReferenceLine(33);
    ASSERT_NE(ref.find("red"), std::string::npos) << ref;
    EXPECT_EQ(Write('a', "vlpnNm", RedWallHit()), ref);

    RayResult miss;  // line 1: a miss from the camera
    miss.origin = Vec3(2.78, -8, 2.74);
    miss.point = miss.origin;
    EXPECT_EQ(Write('a', "vlpnNm", miss), ReferenceLine(1));
}

TEST(RecordWriterAscii, LayoutDetails) {
    RayResult r;
    r.normal = Vec3(-0.0, 0.5, -1);
    r.weight = 0.25;
    EXPECT_EQ(Write('a', "n", r), "-0.000000e+00\t5.000000e-01\t-1.000000e+00\t\n");
    EXPECT_EQ(Write('a', "wsM~", r), "2.500000e-01\t*\t*\t~\t\n");
    EXPECT_EQ(Write('a', "L", r), "1.000000e+10\t\n");
    EXPECT_EQ(Write('a', "c", r), "0.000000e+00\t0.000000e+00\t\n");
    r.value = Rgb(1, 2, 3);
    r.mirrored = Rgb(0.5, 0.5, 0.5);
    r.mirrorLength = 3;
    r.unmirroredLength = 4;
    EXPECT_EQ(Write('a', "xRX", r),
              "5.000000e-01\t1.500000e+00\t2.500000e+00\t3.000000e+00\t4.000000e+00\t\n");
    EXPECT_EQ(Write('a', "l", r), "4.000000e+00\t\n");  // mirrored part not dominant
    r.mirrored = Rgb(1, 2, 3);
    EXPECT_EQ(Write('a', "l", r), "3.000000e+00\t\n");
    EXPECT_EQ(Write('a', "", r), "");  // no fields: nothing at all
    r.value = Rgb(123456789.0, 1e-300, -2.5e-7);
    EXPECT_EQ(Write('a', "v", r), "1.234568e+08\t1.000000e-300\t-2.500000e-07\t\n");
}

TEST(RecordWriterBinary, FloatAndDoubleBytes) {
    RayResult r;
    r.value = Rgb(1, -2, 0.1);
    r.surfaceName = "ball";
    std::string f = Write('f', "vs", r);
    ASSERT_EQ(f.size(), 12u + 5u);
    float fv[3];
    std::memcpy(fv, f.data(), 12);
    EXPECT_EQ(fv[0], 1.0f);
    EXPECT_EQ(fv[1], -2.0f);
    EXPECT_EQ(fv[2], 0.1f);
    EXPECT_EQ(f.substr(12), "ball\t");  // strings stay text in binary modes

    std::string d = Write('d', "vw", r);
    ASSERT_EQ(d.size(), 32u);  // no record terminator
    double dv[4];
    std::memcpy(dv, d.data(), 32);
    EXPECT_EQ(dv[0], 1.0);
    EXPECT_EQ(dv[1], -2.0);
    EXPECT_EQ(dv[2], 0.1);
    EXPECT_EQ(dv[3], 1.0);
}

TEST(RecordWriterRgbe, MatchesSetcolr) {
    using Px = std::array<std::uint8_t, 4>;
    EXPECT_EQ(EncodeRgbe(Rgb(0.3, 0.4, 0.5)), (Px{0x4C, 0x66, 0x80, 0x80}));
    EXPECT_EQ(EncodeRgbe(Rgb::Grey(0.529138)), (Px{135, 135, 135, 128}));
    EXPECT_EQ(EncodeRgbe(Rgb(0, 0, 0)), (Px{0, 0, 0, 0}));
    EXPECT_EQ(EncodeRgbe(Rgb(1e-33, 0, 0)), (Px{0, 0, 0, 0}));
    EXPECT_EQ(EncodeRgbe(Rgb(1, 1, 1)), (Px{128, 128, 128, 129}));
    EXPECT_EQ(EncodeRgbe(Rgb(-1, 2, 0)), (Px{0, 128, 0, 130}));
    RayResult r;
    r.value = Rgb(0.3, 0.4, 0.5);
    r.mirrored = Rgb(0.1, 0.1, 0.1);
    EXPECT_EQ(Write('c', "v", r), std::string("\x4C\x66\x80\x80", 4));
    EXPECT_EQ(Write('c', "x", r), Write('c', "v", [] {
                  RayResult q;
                  q.value = Rgb(0.2, 0.3, 0.4);
                  return q;
              }()));
}

TEST(RecordWriterTrace, IndentsByDepth) {
    std::ostringstream out;
    RecordWriter writer('a', out);
    RayResult shadow;
    shadow.depth = 1;
    shadow.modifierName = "bright";
    RayResult primary;
    primary.modifierName = "white";
    writer.WriteTraceRecord("m", shadow);
    writer.WriteTraceRecord("m", primary);
    writer.Flush();
    EXPECT_EQ(out.str(), "\tbright\t\nwhite\t\n");
}

TEST(RtraceHeader, Layout) {
    setenv("TZ", "UTC", 1);
    tzset();
    std::vector<std::string> cmd = {"rtrace", "-faf", "-ov", "-e", "my file"};
    RtraceOptions o;
    o.outputFormat = 'f';
    std::string h = FormatHeader(cmd, SpecOf("v"), 'f', 1795309683);  // 2026-11-22 01:08:03 UTC
    EXPECT_EQ(h,
              "#?RADIANCE\n"
              "rtrace -faf -ov -e \"my file\"\n"
              "SOFTWARE= lazyrad 0.1.0 (RADIANCE 5.4a compatible)\n"
              "CAPDATE= 2026:11:22 01:08:03\n"
              "GMT= 2026:11:22 01:08:03\n"
              "NCOMP=3\n"
              "BigEndian=0\n"
              "FORMAT=float\n"
              "\n");
    h = FormatHeader(cmd, SpecOf("vtv"), 'a', 0);
    EXPECT_EQ(h.find("NCOMP"), std::string::npos);
    EXPECT_EQ(h.find("BigEndian"), std::string::npos);
    EXPECT_NE(h.find("FORMAT=ascii\n\n"), std::string::npos);
    EXPECT_NE(FormatHeader(cmd, SpecOf("v"), 'c', 0).find("FORMAT=32-bit_rle_rgbe\n\n"),
              std::string::npos);
    EXPECT_NE(FormatHeader(cmd, SpecOf("v"), 'd', 0).find("BigEndian=0\nFORMAT=double\n"),
              std::string::npos);
    EXPECT_EQ(FormatResolution(32, 24), "-Y 24 +X 32\n");
}

}  // namespace
}  // namespace rt
