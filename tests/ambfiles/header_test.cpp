// SPDX-License-Identifier: MIT
#include "ambfiles/header.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <ctime>

#include "ambfiles/record_codec.h"
#include "tests/ambfiles/test_util.h"

namespace rt {
namespace {

std::vector<std::uint8_t> Bytes(const std::string& s) { return {s.begin(), s.end()}; }

AmbientHeaderParams CornellParams() {
    AmbientHeaderParams p;
    p.bounces = 2;
    p.accuracy = 0.15;
    p.divisions = 512;
    p.superSamples = 256;
    p.resolution = 128;
    p.octreeName = "cornell.oct";
    p.software = "RADIANCE 5.4a 2026-11-22 LBNL (5.2.Unknown)";
    return p;
}

TEST(AmbientHeader, MatchesRadianceHeaderByteForByte) {
    // CAPDATE is local time: pin the zone so it equals GMT, as on the machine that
    // wrote the conformance file.
    setenv("TZ", "UTC", 1);
    tzset();
    std::tm t{};
    t.tm_year = 2026 - 1900;
    t.tm_mon = 10;
    t.tm_mday = 22;
    t.tm_hour = 1;
    t.tm_min = 24;
    t.tm_sec = 37;
    AmbientHeaderParams p = CornellParams();
    p.captureTime = timegm(&t);
    const std::string header = FormatAmbientHeader(p);
    const auto file = testing::ReadBytes(testing::DataPath("cornell_radiance54.amb"));
    ASSERT_EQ(header.size(), testing::kRadianceRecordsOffset);
    EXPECT_EQ(Bytes(header),
              std::vector<std::uint8_t>(file.begin(), file.begin() + static_cast<std::ptrdiff_t>(
                                                                         header.size())));
}

TEST(AmbientHeader, CommandLineLineAsInitambfile) {
    AmbientHeaderParams p;
    p.bounces = 1;
    p.software = "lazyrad test";
    p.ambientValue = Rgb(0.5, 0.25, 1e-7);
    const std::string h = FormatAmbientHeader(p);
    EXPECT_EQ(h.substr(0, h.size() - kAmbientMagicBytes),
              "#?RADIANCE\n"
              "rtrace -av 0.5 0.25 1e-07 -aw 0 -ab 1 -aa 0.1 -ad 1024 -as 512 -ar 256 \n"
              "SOFTWARE= lazyrad test\n"
              "FORMAT=Radiance_ambval\n\n");
    EXPECT_EQ(static_cast<unsigned char>(h[h.size() - 2]), 0x02);
    EXPECT_EQ(static_cast<unsigned char>(h[h.size() - 1]), 0x2F);
    const HeaderParse parse = ParseAmbientHeader(Bytes(h));
    ASSERT_TRUE(parse.header) << parse.problem;
    EXPECT_EQ(parse.header->recordsOffset, h.size());
}

TEST(AmbientHeader, ParsesRadianceFile) {
    const auto file = testing::ReadBytes(testing::DataPath("cornell_radiance54.amb"));
    const HeaderParse parse = ParseAmbientHeader(file);
    ASSERT_TRUE(parse.header) << parse.problem;
    EXPECT_EQ(parse.header->recordsOffset, testing::kRadianceRecordsOffset);
    EXPECT_EQ(parse.header->format, std::string(kAmbientFormat));
    ASSERT_EQ(parse.header->lines.size(), 6u);
    EXPECT_EQ(parse.header->lines[0], "#?RADIANCE");
    EXPECT_EQ(parse.header->lines[5], "FORMAT=Radiance_ambval");
}

TEST(AmbientHeader, AcceptsMissingFormatAndCrLfBlankLine) {
    const std::string magic = "\x02\x2F";
    auto a = ParseAmbientHeader(Bytes("#?RADIANCE\nrtrace -ab 1\n\n" + magic));
    ASSERT_TRUE(a.header) << a.problem;
    EXPECT_FALSE(a.header->format);
    auto b = ParseAmbientHeader(Bytes("#?RADIANCE\r\nFORMAT= Radiance_ambval\r\n\r\n" + magic));
    ASSERT_TRUE(b.header) << b.problem;
    EXPECT_EQ(b.header->recordsOffset, 41u);
}

TEST(AmbientHeader, RejectsWhatIsNotAnAmbientFile) {
    const std::string magic = "\x02\x2F";
    for (const std::string& s :
         {std::string(), std::string("hello world\n\n") + magic,             // no #? line
          std::string("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n") + magic,     // other format
          std::string("#?RADIANCE\nFORMAT=Radiance_ambval\n\n\x02\x2D"),    // 557: pre-5.0
          std::string("#?RADIANCE\nFORMAT=Radiance_ambval\n\n\x02"),        // magic cut short
          std::string("#?RADIANCE\nFORMAT=Radiance_ambval\n")}) {           // no blank line
        const HeaderParse parse = ParseAmbientHeader(Bytes(s));
        EXPECT_FALSE(parse.header) << s;
        EXPECT_FALSE(parse.problem.empty());
        EXPECT_EQ(parse.problem.find('\n'), std::string::npos);
    }
}

}  // namespace
}  // namespace rt
