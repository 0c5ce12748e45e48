// SPDX-License-Identifier: MIT
//
// End-to-end helpers for tests that run build/bin/rtrace: the numbers of every
// output line, and the error of irradiance rows against a reference file of
// scenes/*/ref (luminance RMS and maximum, as scenes/README.md defines them).
#pragma once

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace rt::testing {

using Rows = std::vector<std::vector<double>>;

inline const std::string kSourceDir = RT_SOURCE_DIR;
inline const std::string kRtrace = std::string(RT_BINARY_DIR) + "/bin/rtrace";

/// Runs `rtrace -h -w ARGS < INPUT` (INPUT relative to the source tree unless
/// absolute) and returns the numbers of every output line. A non-zero exit
/// status is a test failure.
inline Rows RunRows(const std::string& args, const std::string& input) {
    const std::string path = input.front() == '/' ? input : kSourceDir + "/" + input;
    const std::string cmd = kRtrace + " -h -w " + args + " < " + path;
    Rows rows;
    FILE* p = popen(cmd.c_str(), "r");
    if (!p) {
        ADD_FAILURE() << "cannot run " << cmd;
        return rows;
    }
    char line[4096];
    while (std::fgets(line, sizeof line, p)) {
        std::istringstream in(line);
        std::vector<double> v;
        double x;
        while (in >> x) v.push_back(x);
        rows.push_back(v);
    }
    EXPECT_EQ(pclose(p), 0) << cmd;
    return rows;
}

/// Radiance's luminance weights of an r g b row.
inline double Luminance(const std::vector<double>& v) {
    return 0.265074126 * v[0] + 0.670114631 * v[1] + 0.064811243 * v[2];
}

struct ReferenceError {
    double rms = 0;    // relative RMS error of luminance
    double worst = 0;  // largest relative error
    double bias = 0;   // mean relative error (bench/score.py's "bias")
    size_t count = 0;  // rows compared
};

/// Compares irradiance rows with a reference file (`r g b stderr` lines).
/// The counts must agree; a short reference is a test failure.
inline ReferenceError CompareWithReference(const Rows& rows, const std::string& referencePath) {
    std::ifstream ref(referencePath);
    ReferenceError e;
    double sumSq = 0;
    for (const auto& row : rows) {
        std::vector<double> r(4);
        if (!(ref >> r[0] >> r[1] >> r[2] >> r[3]) || row.size() < 3) {
            ADD_FAILURE() << referencePath << ": reference and output disagree at row " << e.count;
            break;
        }
        const double rel = Luminance(row) / Luminance(r) - 1;
        sumSq += rel * rel;
        e.bias += rel;
        e.worst = std::isfinite(rel) ? std::max(e.worst, std::fabs(rel)) : INFINITY;
        ++e.count;
    }
    e.rms = e.count ? std::sqrt(sumSq / static_cast<double>(e.count)) : INFINITY;
    e.bias = e.count ? e.bias / static_cast<double>(e.count) : INFINITY;
    return e;
}

}  // namespace rt::testing
