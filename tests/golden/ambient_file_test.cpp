// End-to-end ambient files and -n through build/bin/rtrace and lookamb:
// records written by one run are reused by the next, several processes can
// share one file, the result is a valid Radiance ambient file, and -n keeps
// output in input order.
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/testing/shell.h"

namespace {

const std::string kSource = RT_SOURCE_DIR;
const std::string kRtrace = std::string(RT_BINARY_DIR) + "/bin/rtrace";
const std::string kLookamb = std::string(RT_BINARY_DIR) + "/bin/lookamb";

std::string Shell(const std::string& cmd, int* status = nullptr) {
    const rt::testing::ShellResult r = rt::testing::RunShell(cmd);
    if (status) *status = r.status;
    return r.out;
}

std::string TempPath(const std::string& name) {
    std::string p = ::testing::TempDir() + "lazyrad_" + std::to_string(getpid()) + "_" + name;
    std::filesystem::remove(p);
    return p;
}

/// Number of records `lookamb -d -h` prints (it stops at the first invalid one).
int RecordCount(const std::string& amb) {
    std::istringstream dump(Shell(kLookamb + " -d -h " + amb));
    int n = 0;
    std::string line;
    while (std::getline(dump, line)) ++n;
    return n;
}

const std::string kCornellOpts = "-h -w -I -ab 2 -ad 128 -as 0 -aa .2 -ar 32 ";

TEST(AmbientFile, SecondRunReusesRecordsAndFileStaysValid) {
    const std::string amb = TempPath("reuse.amb");
    const std::string scene = kSource + "/scenes/cornell/cornell.rad";
    const std::string points = kSource + "/scenes/cornell/floor.pts";
    int status = 0;
    std::string first = Shell(kRtrace + " -t 1000 " + kCornellOpts + "-af " + amb + " " + scene +
                                " < " + points + " 2>&1 >/dev/null",
                            &status);
    ASSERT_EQ(status, 0) << first;
    const int records = RecordCount(amb);
    EXPECT_GT(records, 84);
    // Whole records only, after the header.
    std::ifstream in(amb, std::ios::binary);
    std::string all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const size_t body = all.find("\n\n") + 2 + 2;  // blank line, then the 2-byte magic
    EXPECT_EQ((all.size() - body) % 67, 0u);
    EXPECT_EQ(static_cast<long long>((all.size() - body) / 67), records);

    // The second run finds every value it needs in the file and adds nothing.
    std::string second = Shell(kRtrace + " -t 1000 " + kCornellOpts + "-af " + amb + " " + scene +
                                 " < " + points + " 2>&1 >/dev/null",
                             &status);
    ASSERT_EQ(status, 0) << second;
    EXPECT_NE(second.find("records per level 0 (+" + std::to_string(records) + " from the ambient file)"),
              std::string::npos)
        << second;
    EXPECT_EQ(RecordCount(amb), records);
    std::filesystem::remove(amb);
}

TEST(AmbientFile, ConcurrentProcessesShareOneFile) {
    const std::string amb = TempPath("shared.amb");
    const std::string scene = kSource + "/scenes/cornell/cornell.rad";
    const std::string points = kSource + "/scenes/cornell/floor.pts";
    std::vector<pid_t> pids;
    for (int i = 0; i < 4; ++i) {
        pid_t pid = fork();
        if (pid == 0) {
            std::string cmd = kRtrace + " -seed " + std::to_string(i) + " " + kCornellOpts +
                              "-af " + amb + " " + scene + " < " + points + " > /dev/null";
            execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
            _exit(127);
        }
        pids.push_back(pid);
    }
    for (pid_t pid : pids) {
        int st = 0;
        waitpid(pid, &st, 0);
        EXPECT_TRUE(WIFEXITED(st) && WEXITSTATUS(st) == 0);
    }
    // Every record valid and whole: lookamb reads them all.
    const int records = RecordCount(amb);
    EXPECT_GT(records, 84);
    std::ifstream in(amb, std::ios::binary);
    std::string all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const size_t body = all.find("\n\n") + 4;
    EXPECT_EQ(static_cast<long long>((all.size() - body) / 67), records);
    EXPECT_EQ((all.size() - body) % 67, 0u);
    std::filesystem::remove(amb);
}

TEST(AmbientFile, NotAnAmbientFileIsRefusedAndLeftAlone) {
    const std::string path = TempPath("notes.txt");
    std::ofstream(path) << "my notes, not an ambient file\n";
    int status = 0;
    std::string err = Shell("echo '1 1 0.001 0 0 1' | " + kRtrace + " " + kCornellOpts + "-af " +
                              path + " " + kSource + "/scenes/cornell/cornell.rad 2>&1 >/dev/null",
                          &status);
    EXPECT_NE(status, 0);
    EXPECT_NE(err.find(path), std::string::npos) << err;
    std::ifstream in(path);
    std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(content, "my notes, not an ambient file\n");
    std::filesystem::remove(path);
}

TEST(Multiprocessing, OutputKeepsInputOrder) {
    // -ab 0 is deterministic, so -n 2 must print exactly what -n 1 prints.
    const std::string cmd = " -h -ab 0 -ovlpnNm " + kSource + "/scenes/cornell/cornell.rad < " +
                            kSource + "/scenes/cornell/cam32.rays";
    std::string one = Shell(kRtrace + " -n 1" + cmd);
    std::string two = Shell(kRtrace + " -n 2" + cmd);
    ASSERT_FALSE(one.empty());
    EXPECT_EQ(one, two);
}

TEST(Multiprocessing, EveryThreadsWarningsArePrinted) {
    // A pattern whose function fails for every ray: each thread warns once
    // (the first time it meets the error), so two threads that both trace
    // rays print the warning twice. Only the first thread's warnings used to
    // be printed.
    const std::string dir = TempPath("warn_dir");
    std::filesystem::create_directories(dir);
    std::ofstream(dir + "/bad.cal") << "badval = log(-1 - Dx*Dx);\n";
    std::ofstream(dir + "/w.rad") << "void brightfunc bad 2 badval bad.cal 0 0\n"
                                     "bad plastic grey 0 0 5 .5 .5 .5 0 0\n"
                                     "grey sphere ball 0 0 4 0 0 0 1\n"
                                     "void light lamp 0 0 3 10 10 10\n"
                                     "lamp sphere bulb 0 0 4 0 0 5 0.5\n";
    {
        std::ofstream rays(dir + "/rays.txt");
        for (int i = 0; i < 200; ++i) rays << "0 0 3 0 0 -1\n";
    }
    const auto count = [](const std::string& text) {
        int n = 0;
        for (size_t at = 0; (at = text.find("compute error for brightfunc", at)) != std::string::npos;
             ++at) {
            ++n;
        }
        return n;
    };
    const std::string run = "cd " + dir + " && " + kRtrace + " -h -ab 1 -ad 512 -aa 0 ";
    EXPECT_EQ(count(Shell(run + "-n 1 w.rad < rays.txt 2>&1 >/dev/null")), 1);
    EXPECT_EQ(count(Shell(run + "-n 2 w.rad < rays.txt 2>&1 >/dev/null")), 2);
    std::filesystem::remove_all(dir);
}

TEST(Multiprocessing, TwoThreadsShareTheCacheAndKeepAccuracy) {
    const std::string opts = " -h -w -I -ab 2 -ad 256 -as 128 -aa .2 -ar 64 " + kSource +
                             "/scenes/cornell/cornell.rad < " + kSource + "/scenes/cornell/floor.pts";
    std::istringstream out(Shell(kRtrace + " -n 2" + opts));
    std::ifstream ref(kSource + "/scenes/cornell/ref/floor_I_ab2.txt");
    double sumSq = 0;
    int n = 0;
    double r, g, b, e, rr, rg, rb;
    while (out >> r >> g >> b && ref >> rr >> rg >> rb >> e) {
        double rel = (0.265 * r + 0.670 * g + 0.065 * b) / (0.265 * rr + 0.670 * rg + 0.065 * rb) - 1;
        sumSq += rel * rel;
        ++n;
    }
    ASSERT_EQ(n, 84);
    // Same bound as the one-thread guard (ambient_golden_test.cpp).
    EXPECT_LT(std::sqrt(sumSq / n), 0.03);
}

}  // namespace

namespace {

/// Radiance's rule: with -aa 0 there is no cache, so the file is not opened
/// (and not created), with Radiance's warning naming it.
TEST(AmbientFile, ZeroAccuracyDoesNotOpenTheFile) {
    const std::string amb = TempPath("unused.amb");
    int status = 0;
    std::string err = Shell("echo '1 1 0.001 0 0 1' | " + kRtrace + " -h -I -ab 1 -aa 0 -af " +
                                amb + " " + kSource + "/scenes/cornell/cornell.rad 2>&1 >/dev/null",
                            &status);
    EXPECT_EQ(status, 0);
    EXPECT_NE(err.find("rtrace: warning - zero ambient accuracy so \"" + amb + "\" not opened"),
              std::string::npos)
        << err;
    EXPECT_FALSE(std::filesystem::exists(amb));
}

}  // namespace
