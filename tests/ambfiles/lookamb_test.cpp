// SPDX-License-Identifier: MIT
//
// Runs the built lookamb and compares with `lookamb -d -h` output of real Radiance.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdio>
#include <sstream>

#include "tests/ambfiles/test_util.h"

namespace rt {
namespace {

using testing::DataPath;
using testing::ReadText;
using testing::TempDir;

const std::string kLookamb = RT_BINARY_DIR "/bin/lookamb";

struct ToolRun {
    int status = -1;
    std::string out;
};

ToolRun Shell(const std::string& command) {
    ToolRun r;
    std::FILE* p = popen(command.c_str(), "r");
    if (p == nullptr) return r;
    char buf[65536];
    std::size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, p)) > 0) r.out.append(buf, n);
    const int st = pclose(p);
    r.status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
    return r;
}

std::vector<std::string> Lines(const std::string& s) {
    std::vector<std::string> lines;
    std::istringstream in(s);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

// Same numbers to printed precision: fields equal as text, or as numbers when one
// side prints "-0.000000" (a tiny negative) and the other "0.000000".
void ExpectSameDump(const std::string& a, const std::string& b) {
    const auto la = Lines(a), lb = Lines(b);
    ASSERT_EQ(la.size(), lb.size());
    for (std::size_t i = 0; i < la.size(); ++i) {
        if (la[i] == lb[i]) continue;
        std::istringstream fa(la[i]), fb(lb[i]);
        double x, y;
        int fields = 0;
        while (fa >> x) {
            ASSERT_TRUE(fb >> y) << "line " << i;
            EXPECT_NEAR(x, y, 1.5e-6 * std::max(1.0, std::fabs(x))) << "line " << i;
            ++fields;
        }
        EXPECT_EQ(fields, 21) << "line " << i;
    }
}

TEST(Lookamb, DataDumpEqualsRadiance) {
    const ToolRun r = Shell(kLookamb + " -d -h " + DataPath("cornell_radiance54.amb"));
    EXPECT_EQ(r.status, 0);
    EXPECT_EQ(r.out, ReadText(DataPath("cornell_radiance54.amb.txt")));  // byte for byte
}

TEST(Lookamb, LabelledDumpCopiesHeaderWithAsciiFormat) {
    const ToolRun r = Shell(kLookamb + " " + DataPath("cornell_radiance54.amb"));
    EXPECT_EQ(r.status, 0);
    const auto lines = Lines(r.out);
    ASSERT_GT(lines.size(), 16u);
    EXPECT_EQ(lines[0], "#?RADIANCE");
    EXPECT_EQ(lines[5], "FORMAT=ascii");
    EXPECT_EQ(lines[6], "");
    EXPECT_EQ(lines[7], "Position:\t1.432673\t1.333954\t0.232935");
    EXPECT_EQ(lines[14], "Corral:\t\t       0");
    EXPECT_EQ(lines[15], "");
    EXPECT_EQ(lines.size(), 7 + 9 * testing::kRadianceRecordCount);
}

TEST(Lookamb, ReverseRoundTripsBothLayouts) {
    TempDir dir;
    const std::string src = DataPath("cornell_radiance54.amb");
    const std::string expected = ReadText(DataPath("cornell_radiance54.amb.txt"));
    for (const std::string& d : {std::string("-d "), std::string()}) {
        const std::string bin = dir.File("back" + d.substr(0, 2) + ".amb");
        const ToolRun back =
            Shell(kLookamb + " " + d + src + " | " + kLookamb + " -r " + d + "> " + bin);
        EXPECT_EQ(back.status, 0);
        // The copied header is Radiance's, FORMAT switched back.
        EXPECT_EQ(ReadText(bin).substr(0, testing::kRadianceRecordsOffset),
                  ReadText(src).substr(0, testing::kRadianceRecordsOffset));
        const ToolRun again = Shell(kLookamb + " -d -h " + bin);
        EXPECT_EQ(again.status, 0);
        ExpectSameDump(again.out, expected);
    }
}

// -u is lazyrad's synonym for Radiance's -r: the same bytes.
TEST(Lookamb, UIsASynonymForReverse) {
    TempDir dir;
    const std::string src = DataPath("cornell_radiance54.amb");
    const std::string viaR = dir.File("r.amb"), viaU = dir.File("u.amb");
    EXPECT_EQ(Shell(kLookamb + " -d " + src + " | " + kLookamb + " -d -r > " + viaR).status, 0);
    EXPECT_EQ(Shell(kLookamb + " -d " + src + " | " + kLookamb + " -d -u > " + viaU).status, 0);
    EXPECT_FALSE(ReadText(viaR).empty());
    EXPECT_EQ(ReadText(viaR), ReadText(viaU));
}

TEST(Lookamb, ReverseWithoutHeaderWritesNewOne) {
    const ToolRun r = Shell(kLookamb + " -d -h " + DataPath("cornell_radiance54.amb") + " | " +
                        kLookamb + " -d -r -h | " + kLookamb + " -h");
    EXPECT_EQ(r.status, 0);
    EXPECT_EQ(Lines(r.out).size(), 9 * testing::kRadianceRecordCount);
    const ToolRun hdr = Shell("printf '' | " + kLookamb + " -h -r -d | head -c 11");
    EXPECT_EQ(hdr.out, "#?RADIANCE\n");
}

TEST(Lookamb, StopsAtDamage) {
    EXPECT_EQ(Lines(Shell(kLookamb + " -d -h " + DataPath("bad_garbage_record.amb")).out).size(),
              100u);
    EXPECT_EQ(Lines(Shell(kLookamb + " -d -h " + DataPath("bad_truncated_tail.amb")).out).size(),
              testing::kRadianceRecordCount - 1);
}

TEST(Lookamb, FormatErrorOnOtherFiles) {
    TempDir dir;
    testing::WriteBytes(dir.File("text.amb"), {'h', 'i', '\n', '\n', 0x02, 0x2F});
    const ToolRun r = Shell(kLookamb + " " + dir.File("text.amb") + " 2>&1");
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.out.find("format error on input"), std::string::npos) << r.out;
    EXPECT_EQ(Shell(kLookamb + " -x 2>/dev/null").status, 1);
    EXPECT_EQ(Shell(kLookamb + " " + dir.File("missing.amb") + " 2>/dev/null").status, 1);
}

}  // namespace
}  // namespace rt
