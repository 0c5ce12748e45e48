// SPDX-License-Identifier: MIT
//
// Fatal signals as Radiance 5.4a's rtrace reports them (rtmain.c onsig()):
// "rtrace: signal - Terminate" or "- Broken pipe" on standard error and exit
// status 3, where the default action would end the process silently with
// 143 or 141. Checked by hand against the real rtrace: `kill -TERM` during a
// run, and `rtrace ... | head -c 10` on a long output.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "tests/robustness/robustness_run.h"
#include "tests/testing/shell.h"

namespace {

using rt::testing::kRtrace;
using rt::testing::kSourceDir;
using rt::testing::ReadText;
using rt::testing::RobustnessTempPath;
using rt::testing::RunShell;

const std::string kCornell = kSourceDir + "/scenes/cornell/cornell.rad";

/// Runs rtrace with `options` on the cornell box, gives it one ray and waits
/// for its answer (-x 1 flushes it: the program has started and installed
/// its handlers), then terminates it while it waits for more rays. Returns
/// the exit status as the shell printed it; stderr goes to `err`.
std::string TerminateMidRun(const std::string& options, const std::string& err) {
    const std::string fifo = RobustnessTempPath("rays.fifo");
    const std::string out = RobustnessTempPath("term.out");
    const std::string script =
        "rm -f " + fifo + " " + out + "; mkfifo " + fifo + "; " + kRtrace + " -h -ab 0 -x 1 " +
        options + " " + kCornell + " < " + fifo + " > " + out + " 2> " + err +
        " & p=$!; exec 3> " + fifo + "; echo '2.78 -5 2.74 0 1 0' >&3; i=0; while [ ! -s " +
        out + " ] && [ $i -lt 600 ]; do sleep 0.1; i=$((i+1)); done; kill -TERM $p; wait $p; "
        "echo $?; exec 3>&-; rm -f " + fifo;
    return RunShell(script).out;
}

TEST(FatalSignals, TerminateIsReportedWithExitStatusThree) {
    const std::string err = RobustnessTempPath("term.err");
    EXPECT_EQ(TerminateMidRun("", err), "3\n");
    EXPECT_EQ(ReadText(err), "rtrace: signal - Terminate\n");
    // With -e the message goes to the end of that file, after the banner.
    const std::string file = RobustnessTempPath("term.e");
    std::remove(file.c_str());
    EXPECT_EQ(TerminateMidRun("-e " + file, err), "3\n");
    EXPECT_EQ(ReadText(err), "");
    const std::string messages = ReadText(file);
    EXPECT_TRUE(messages.starts_with("**************\n*** PID ")) << messages;
    EXPECT_TRUE(messages.ends_with("\n\nrtrace: signal - Terminate\n")) << messages;
}

TEST(FatalSignals, BrokenPipeIsReportedWithExitStatusThree) {
    // Far more output than a pipe holds, to a reader that stops after 10 bytes.
    const std::string rays = RobustnessTempPath("many.rays");
    {
        std::ofstream f(rays);
        for (int i = 0; i < 100000; ++i) f << "2.78 -5 2.74 0 1 0\n";
    }
    const std::string err = RobustnessTempPath("pipe.err");
    const rt::testing::ShellResult r =
        RunShell("bash -c '" + kRtrace + " -h -ab 0 " + kCornell + " < " + rays + " 2> " + err +
                 " | head -c 10 > /dev/null; echo ${PIPESTATUS[0]}'");
    EXPECT_EQ(r.out, "3\n");
    EXPECT_EQ(ReadText(err), "rtrace: signal - Broken pipe\n");
}

}  // namespace
