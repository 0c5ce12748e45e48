// SPDX-License-Identifier: MIT
//
// Every case of tests/data/cal/rcalc_cases.txt against the values and messages
// real rcalc gave (tests/data/cal/rcalc_expected.tsv, made by
// make_rcalc_data.py): radiance-functions.md §9.13 items 1-13, operators,
// precedence, folding, the library, functions, errors, and rayinit.cal's
// functions (Radiance's rayinit.cal in rcalc, lazyrad's own here).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "tests/cal/cal_test_util.h"

namespace rt::cal {
namespace {

struct Case {
    std::string id, input, program;
    int status = 0;
    std::vector<std::string> values, messages;
};

std::vector<std::string> Split(const std::string& s, const std::string& sep) {
    std::vector<std::string> parts;
    if (s.empty()) return parts;
    std::size_t start = 0;
    for (;;) {
        const std::size_t at = s.find(sep, start);
        parts.push_back(s.substr(start, at - start));
        if (at == std::string::npos) return parts;
        start = at + sep.size();
    }
}

std::vector<Case> ReadCases() {
    std::ifstream in(std::string(RT_SOURCE_DIR) + "/tests/data/cal/rcalc_expected.tsv");
    EXPECT_TRUE(in.good());
    std::vector<Case> cases;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        const std::vector<std::string> f = Split(line, "\t");
        if (f.size() != 6) {
            ADD_FAILURE() << "bad line: " << line;
            continue;
        }
        Case c{f[0], f[1], f[2], std::stoi(f[3]), Split(f[4], " "), Split(f[5], " | ")};
        cases.push_back(c);
    }
    return cases;
}

bool IsDigits(const std::string& s, std::size_t from, std::size_t to) {
    if (to <= from) return false;
    for (std::size_t i = from; i < to; ++i) {
        if (s[i] < '0' || s[i] > '9') return false;
    }
    return true;
}

// Length of a leading "file:line:column: " (file without ':'), or 0.
std::size_t PlacePrefix(const std::string& m) {
    const std::size_t c1 = m.find(':');
    if (c1 == std::string::npos || c1 == 0) return 0;
    const std::size_t c2 = m.find(':', c1 + 1);
    if (c2 == std::string::npos || !IsDigits(m, c1 + 1, c2)) return 0;
    const std::size_t c3 = m.find(": ", c2 + 1);
    if (c3 == std::string::npos || !IsDigits(m, c2 + 1, c3)) return 0;
    return c3 + 2;
}

// Our messages in rcalc's words: no place prefix, and "name: what" order.
std::vector<std::string> InRadianceWords(const std::string& message) {
    const std::string m = message.substr(PlacePrefix(message));
    static const std::vector<std::pair<std::string, std::string>> kNamed = {
        {"undefined variable '", ": undefined variable"},
        {"undefined function '", ": undefined function"},
        {"too few arguments to '", ": too few arguments"},
        {"argument not a function in '", ": argument not a function"},
    };
    for (const auto& [ours, theirs] : kNamed) {
        if (m.starts_with(ours) && m.ends_with("'")) {
            return {m.substr(ours.size(), m.size() - ours.size() - 1) + theirs};
        }
    }
    const std::string bad = "bad constant expression (";
    if (m.starts_with(bad) && m.ends_with(")")) {
        return {m.substr(bad.size(), m.size() - bad.size() - 1), "bad constant expression"};
    }
    return {m};
}

// rcalc's output statements `$N = e` (at the start, or after ';' or a
// comment's '}') become definitions of out.N; returns the channel numbers.
std::vector<int> RenameOutputs(std::string& program) {
    std::vector<int> channels;
    std::string out;
    bool statementStart = true;
    for (std::size_t i = 0; i < program.size();) {
        const char c = program[i];
        if (statementStart && c == '$') {
            std::size_t j = i + 1;
            while (j < program.size() && program[j] >= '0' && program[j] <= '9') ++j;
            std::size_t k = j;
            while (k < program.size() && (program[k] == ' ' || program[k] == '\t')) ++k;
            if (j > i + 1 && k < program.size() && program[k] == '=') {
                channels.push_back(std::stoi(program.substr(i + 1, j - i - 1)));
                out += "out." + program.substr(i + 1, j - i - 1);
                i = j;
                statementStart = false;
                continue;
            }
        }
        if (c == ';' || c == '}') {
            statementStart = true;
        } else if (c != ' ' && c != '\t') {
            statementStart = false;
        }
        out += c;
        ++i;
    }
    program = out;
    std::sort(channels.begin(), channels.end());
    return channels;
}

bool SameNumber(const std::string& expected, double actual) {
    const double e = std::strtod(expected.c_str(), nullptr);
    if (std::isinf(e) || std::isinf(actual)) return e == actual;
    // %.9g rounds to half a unit of the 9th significant digit: at most 5e-9 relative.
    return std::fabs(e - actual) <= 5.0001e-9 * std::max(std::fabs(e), std::fabs(actual)) + 1e-300;
}

void RunCase(const Case& c) {
    SCOPED_TRACE(c.id + ": " + c.program + "  input: " + c.input);
    std::vector<std::string> messages;
    const auto collect = [&messages](const std::string& m) { messages.push_back(m); };
    Options options;
    options.channelCount = 100;
    options.rtraceLibrary = false;  // rcalc has neither arg, noise nor erf
    options.redefinitionWarnings = false;
    options.foldedChannelsAreZero = true;
    Program program(options, collect);
    program.LoadText("PI : 3.14159265358979323846;", "rcalc");  // rcalc's own constant
    if (c.id.starts_with("rayinit.")) program.LoadRayinit(testing::BuiltinsOnly());

    std::string text = c.program;
    const std::vector<int> outputs = RenameOutputs(text);

    std::vector<double> values;
    std::string error;
    try {
        program.LoadText(text, "e.cal");
        testing::Channels channels;
        if (c.input != "-") {
            std::istringstream in(c.input);
            for (double v; in >> v;) channels.values.push_back(v);
        }
        Context context(program);
        context.SetChannels(&channels);
        context.SetWarnings(collect);
        context.NextEvaluation();
        for (const int n : outputs) {
            const std::string name = "out." + std::to_string(n);
            const std::optional<Variable> v = program.FindVariable(name);
            ASSERT_TRUE(v.has_value()) << name;
            values.push_back(program.Evaluate(*v, context));
        }
    } catch (const Error& e) {
        error = e.what();
        messages.push_back(error);
    }

    EXPECT_EQ(error.empty(), c.status == 0) << error;
    if (!error.empty()) {
        // One line, starting with the place: file:line:column.
        EXPECT_TRUE(error.starts_with("e.cal:") && PlacePrefix(error) > 0) << error;
        EXPECT_EQ(error.find('\n'), std::string::npos) << error;
    }
    ASSERT_EQ(values.size(), c.values.size());
    for (std::size_t i = 0; i < values.size(); ++i) {
        EXPECT_TRUE(SameNumber(c.values[i], values[i]))
            << "value " << i + 1 << ": rcalc " << c.values[i] << ", lazyrad " << values[i];
    }
    std::vector<std::string> ours;
    for (const std::string& m : messages) {
        for (const std::string& w : InRadianceWords(m)) ours.push_back(w);
    }
    EXPECT_EQ(ours, c.messages);
}

TEST(RcalcData, EveryCaseAgreesWithRealRcalc) {
    const std::vector<Case> cases = ReadCases();
    EXPECT_GE(cases.size(), 100u);
    for (const Case& c : cases) RunCase(c);
}

}  // namespace
}  // namespace rt::cal
