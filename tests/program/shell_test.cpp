// SPDX-License-Identifier: MIT
#include "program/shell.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/error.h"

namespace rt {
namespace {

TEST(ProgramShell, MapsErrorsToRadianceMessagesAndExitCodes) {
    std::ostringstream err;
    ProgramShell shell("prog", err);
    EXPECT_EQ(shell.Run([] { return 0; }), 0);
    EXPECT_EQ(shell.Run([]() -> int { ThrowUserError("bad"); }), 1);
    EXPECT_EQ(shell.Run([]() -> int { ThrowSystemError("disk"); }), 2);
    EXPECT_EQ(shell.Run([]() -> int { throw Error(Error::Kind::Internal, "bug"); }), 3);
    EXPECT_EQ(shell.Run([]() -> int { throw std::runtime_error("odd"); }), 3);
    EXPECT_EQ(err.str(),
              "prog: fatal - bad\n"
              "prog: system - disk\n"
              "prog: internal - bug\n"
              "prog: internal - odd\n");
}

TEST(ProgramShell, HoldsWarningsUntilMinusWIsKnown) {
    std::ostringstream err;
    ProgramShell quiet("prog", err);
    quiet.Warn()("early");
    EXPECT_EQ(err.str(), "");
    quiet.SetWarnings(false);
    quiet.Warn()("late");
    EXPECT_EQ(err.str(), "");

    ProgramShell loud("prog", err);
    loud.Warn()("early");
    loud.SetWarnings(true);
    loud.Warn()("late");
    EXPECT_EQ(err.str(), "prog: warning - early\nprog: warning - late\n");
}

TEST(ProgramShell, HeldWarningsComeBeforeAFailure) {
    std::ostringstream err;
    ProgramShell shell("prog", err);
    EXPECT_EQ(shell.Run([&]() -> int {
        shell.Warn()("while parsing");
        ThrowUserError("command line error at '-q'");
    }),
              1);
    EXPECT_EQ(err.str(),
              "prog: warning - while parsing\nprog: fatal - command line error at '-q'\n");
}

TEST(ProgramShell, ErrorFileGetsBannerAndMessages) {
    const std::string path = std::string(RT_BINARY_DIR) + "/program_shell_test_errors.log";
    std::remove(path.c_str());
    std::ostringstream err;
    ProgramShell shell("prog", err);
    shell.SetWarnings(true);
    EXPECT_TRUE(shell.OpenErrorFile("", 7, {}));  // no -e: nothing changes
    const std::vector<std::string> args = {"prog", "-e", "my log", "s.rad"};
    ASSERT_TRUE(shell.OpenErrorFile(path, 42, args));
    shell.Warn()("careful");
    EXPECT_EQ(shell.Run([]() -> int { ThrowUserError("bad"); }), 1);
    EXPECT_EQ(err.str(), "");
    std::ifstream f(path);
    const std::string text{std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
    EXPECT_EQ(text,
              "**************\n*** PID    42: prog -e \"my log\" s.rad\n\n"
              "prog: warning - careful\nprog: fatal - bad\n");
    std::remove(path.c_str());

    EXPECT_FALSE(shell.OpenErrorFile("/nonexistent/dir/errors.log", 1, args));
}

}  // namespace
}  // namespace rt
