// SPDX-License-Identifier: MIT
//
// imgcmp: compares two pictures (OpenEXR or Radiance RGBE, chosen by content)
// with rt::CompareImages (image/compare.h defines the measures) for golden
// tests. Usage:  imgcmp a b [-rms r] [-max m] [-floor f]
// Prints "rms <r> max <m> at <x> <y>" on stdout. Exit status: 0 within the
// given limits, 1 over a limit, 2 on any error (unreadable file, size mismatch,
// bad arguments).
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "core/error.h"
#include "image/exr.h"
#include "image/compare.h"
#include "image/hdr.h"

namespace {

constexpr int kExitOverLimit = 1;
constexpr int kExitError = 2;

[[noreturn]] void Usage() {
    std::fprintf(stderr, "Usage: imgcmp a b [-rms r] [-max m] [-floor fraction]\n");
    std::exit(kExitError);
}

double ParseLimit(const std::vector<std::string>& args, std::size_t& i) {
    if (i + 1 >= args.size())
        Usage();
    const std::string& word = args[++i];
    char* end = nullptr;
    const double value = std::strtod(word.c_str(), &end);
    if (end == word.c_str() || *end != '\0' || !(value >= 0))
        Usage();
    return value;
}

}  // namespace

int main(int argc, char** argv) {
    const std::vector<std::string> args(argv + 1, argv + argc);
    std::vector<std::string> files;
    double rmsLimit = -1, maxLimit = -1;
    rt::CompareOptions options;
    for (std::size_t i = 0; i < args.size(); ++i) {
        if (args[i] == "-rms") {
            rmsLimit = ParseLimit(args, i);
        } else if (args[i] == "-max") {
            maxLimit = ParseLimit(args, i);
        } else if (args[i] == "-floor") {
            options.floorFraction = ParseLimit(args, i);
        } else if (args[i].size() > 1 && args[i][0] == '-') {
            Usage();
        } else {
            files.push_back(args[i]);
        }
    }
    if (files.size() != 2)
        Usage();
    try {
        const rt::Image a = rt::ReadImage(files[0]);
        const rt::Image b = rt::ReadImage(files[1]);
        const rt::CompareResult r = rt::CompareImages(a, b, options);
        std::printf("rms %.6g max %.6g at %d %d\n", r.rmsRelative, r.maxRelative, r.maxX, r.maxY);
        bool over = false;
        if (rmsLimit >= 0 && !(r.rmsRelative <= rmsLimit)) {
            std::fprintf(stderr, "imgcmp: rms %.6g over limit %g\n", r.rmsRelative, rmsLimit);
            over = true;
        }
        if (maxLimit >= 0 && !(r.maxRelative <= maxLimit)) {
            std::fprintf(stderr, "imgcmp: max %.6g over limit %g at pixel %d %d\n", r.maxRelative,
                         maxLimit, r.maxX, r.maxY);
            over = true;
        }
        return over ? kExitOverLimit : 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "imgcmp: %s\n", e.what());
        return kExitError;
    }
}
