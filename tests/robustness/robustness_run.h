// SPDX-License-Identifier: MIT
//
// Helpers of the robustness suite (tests/robustness/*_test.cpp): run build/bin/rtrace
// with warnings on, keeping standard output, standard error and the exit status
// apart; read its rows as numbers or words; compare two runs; write small input
// files into the test's temporary directory.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include <gtest/gtest.h>
#include <unistd.h>

#include "tests/testing/rtrace_rows.h"
#include "tests/testing/shell.h"

namespace rt::testing {

/// A file of tests/robustness/scenes/.
inline std::string RobustnessScene(const std::string& name) {
    return kSourceDir + "/tests/robustness/scenes/" + name;
}

/// The start of every RobustnessTempPath of this process.
inline std::string RobustnessTempPrefix() {
    return "lazyrad_robustness_" + std::to_string(getpid()) + "_";
}

/// A path in GoogleTest's temporary directory, unique to this process (ctest
/// runs each test in its own process, possibly in parallel).
inline std::string RobustnessTempPath(const std::string& name) {
    return ::testing::TempDir() + RobustnessTempPrefix() + name;
}

/// Removes this process's RobustnessTempPath files when the tests end.
class RobustnessTempCleanup : public ::testing::Environment {
public:
    void TearDown() override {
        std::error_code ec;
        for (const auto& entry : std::filesystem::directory_iterator(::testing::TempDir(), ec)) {
            if (entry.path().filename().string().rfind(RobustnessTempPrefix(), 0) == 0) {
                std::filesystem::remove(entry.path(), ec);
            }
        }
    }
};
/// Registered once per test program (an inline variable is one object).
inline ::testing::Environment* const kRobustnessTempCleanup =
    ::testing::AddGlobalTestEnvironment(new RobustnessTempCleanup);

inline std::string ReadText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// Writes `text` to RobustnessTempPath(name) and returns that path.
inline std::string WriteTempFile(const std::string& name, const std::string& text) {
    const std::string path = RobustnessTempPath(name);
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

struct RtraceRun {
    int status = -1;  // exit status; 124 when `timeout` stopped it, -1 if it could not run
    std::string out;  // standard output
    std::string err;  // standard error (warnings and errors)

    /// The numbers at the start of every output line (RunRows' rule).
    Rows Numbers() const {
        Rows rows;
        std::istringstream lines(out);
        for (std::string line; std::getline(lines, line);) {
            std::istringstream in(line);
            std::vector<double> v;
            double x;
            while (in >> x)
                v.push_back(x);
            rows.push_back(v);
        }
        return rows;
    }

    /// The blank-separated words of every output line.
    std::vector<std::vector<std::string>> Words() const {
        std::vector<std::vector<std::string>> rows;
        std::istringstream lines(out);
        for (std::string line; std::getline(lines, line);) {
            std::istringstream in(line);
            rows.emplace_back(std::istream_iterator<std::string>(in),
                              std::istream_iterator<std::string>());
        }
        return rows;
    }
};

/// Runs `rtrace -h ARGS < INPUT` with warnings on (unlike RunRows); INPUT is
/// absolute or relative to the source tree. With `timeoutSeconds` > 0 the run
/// is stopped after that long (status 124).
inline RtraceRun RunRtrace(const std::string& args, const std::string& input,
                           int timeoutSeconds = 0) {
    const std::string path = input.front() == '/' ? input : kSourceDir + "/" + input;
    const std::string errPath = RobustnessTempPath("stderr.txt");
    std::string command = kRtrace + " -h " + args + " < " + path + " 2> " + errPath;
    if (timeoutSeconds > 0)
        command = "timeout " + std::to_string(timeoutSeconds) + " " + command;
    const ShellResult r = RunShell(command);
    RtraceRun run;
    run.status = r.status;
    run.out = r.out;
    run.err = ReadText(errPath);
    std::remove(errPath.c_str());
    return run;
}

/// `rows` has `count` rows of at least `columns` numbers, all finite and >= 0.
inline ::testing::AssertionResult FiniteNonNegative(const Rows& rows, size_t count,
                                                    size_t columns) {
    if (rows.size() != count) {
        return ::testing::AssertionFailure() << rows.size() << " rows, expected " << count;
    }
    for (size_t i = 0; i < rows.size(); ++i) {
        if (rows[i].size() < columns) {
            return ::testing::AssertionFailure()
                   << "row " << i << " has " << rows[i].size() << " numbers";
        }
        for (size_t j = 0; j < columns; ++j) {
            const double x = rows[i][j];
            if (!std::isfinite(x) || x < 0) {
                return ::testing::AssertionFailure() << "row " << i << " column " << j << ": " << x;
            }
        }
    }
    return ::testing::AssertionSuccess();
}

/// Largest |a − b| / |b| over the first `columns` numbers of every row (0 when
/// both are 0, infinite when only b is); infinite if the shapes differ.
inline double MaxRelativeDifference(const Rows& a, const Rows& b, size_t columns = 3) {
    if (a.size() != b.size())
        return std::numeric_limits<double>::infinity();
    double worst = 0;
    for (size_t i = 0; i < a.size(); ++i) {
        if (a[i].size() < columns || b[i].size() < columns) {
            return std::numeric_limits<double>::infinity();
        }
        for (size_t j = 0; j < columns; ++j) {
            const double d = std::fabs(a[i][j] - b[i][j]);
            if (d == 0)
                continue;
            const double rel =
                b[i][j] != 0 ? d / std::fabs(b[i][j]) : std::numeric_limits<double>::infinity();
            worst =
                std::max(worst, std::isnan(rel) ? std::numeric_limits<double>::infinity() : rel);
        }
    }
    return worst;
}

/// The lines first..last (1-based, inclusive) of a text file.
inline std::string FileLines(const std::string& path, int first, int last) {
    std::ifstream in(path);
    std::string out;
    int n = 0;
    for (std::string line; std::getline(in, line);) {
        ++n;
        if (n >= first && n <= last)
            out += line + "\n";
    }
    return out;
}

}  // namespace rt::testing
