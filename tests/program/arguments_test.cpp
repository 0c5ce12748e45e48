// SPDX-License-Identifier: MIT
#include "program/arguments.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "core/error.h"

namespace rt {
namespace {

TEST(Arguments, NumberValidation) {
    for (const char* yes : {"12", "-3", " +4", "5 "}) EXPECT_TRUE(IsIntArgument(yes)) << yes;
    for (const char* no : {"4x", "", "+", "1.5"}) EXPECT_FALSE(IsIntArgument(no)) << no;
    for (const char* yes : {"1e-3", ".5", "-2.", "3"}) EXPECT_TRUE(IsRealArgument(yes)) << yes;
    for (const char* no : {"inf", "nan", "1.5.2", "e5", "."}) EXPECT_FALSE(IsRealArgument(no)) << no;
    for (const char* yes : {"file.amb", " lead"}) EXPECT_TRUE(IsWordArgument(yes)) << yes;
    for (const char* no : {"", "   ", "a\tb"}) EXPECT_FALSE(IsWordArgument(no)) << no;
}

TEST(Arguments, SplitWordsHonoursQuotes) {
    EXPECT_EQ(SplitWords("  a 'b c'\n\"d\"e  "), (std::vector<std::string>{"a", "b c", "d", "e"}));
}

TEST(Arguments, ProgramNameDropsTheDirectory) {
    EXPECT_EQ(ProgramName("/opt/lazyrad/bin/rtrace"), "rtrace");
    EXPECT_EQ(ProgramName("rvimage"), "rvimage");
}

TEST(Arguments, ExpandInPlaceFollowsNestedFiles) {
    const std::string dir = std::string(RT_BINARY_DIR) + "/arguments_test_" + std::to_string(getpid());
    const std::string outer = dir + "_outer", inner = dir + "_inner";
    std::ofstream(outer) << "-ab 2 @" << inner << " -x 'a b'\n";
    std::ofstream(inner) << "-aa .1\n";
    std::vector<std::string> args = {"prog", "@" + outer, "scene.rad"};
    ExpandInPlace(args, 1);
    EXPECT_EQ(args, (std::vector<std::string>{"prog", "-ab", "2", "@" + inner, "-x", "a b",
                                              "scene.rad"}));
    ExpandInPlace(args, 3);
    EXPECT_EQ(args, (std::vector<std::string>{"prog", "-ab", "2", "-aa", ".1", "-x", "a b",
                                              "scene.rad"}));
    std::remove(outer.c_str());
    std::remove(inner.c_str());
}

TEST(Arguments, ExpansionFailuresAreSystemErrors) {
    std::vector<std::string> args = {"prog", "@/nonexistent/words"};
    try {
        ExpandInPlace(args, 1);
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), Error::Kind::System);
        EXPECT_EQ(e.ExitCode(), 2);
    }
    // A file that names itself stops after a bounded number of rounds.
    const std::string self = std::string(RT_BINARY_DIR) + "/arguments_self_" + std::to_string(getpid());
    std::ofstream(self) << "@" << self << "\n";
    args = {"prog", "@" + self};
    EXPECT_THROW(ExpandInPlace(args, 1), Error);
    std::remove(self.c_str());
}

}  // namespace
}  // namespace rt
