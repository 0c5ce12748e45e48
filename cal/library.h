// SPDX-License-Identifier: MIT
//
// The built-in functions of the function language (radiance-functions.md
// §9.9): calcomp's core library (src/common/calfunc.c) and rtrace's additions
// (src/rt/func.c). The evaluator dispatches on Kind; arguments are evaluated
// lazily through the evaluator, so if() and select() evaluate only what they use.
#pragma once

#include <span>
#include <string_view>

namespace rt::cal {

struct LibraryFunction {
    enum class Kind { If, Select, Min, Max, Rand, Arg, Math1, Math2, Math3 };
    std::string_view name;
    int arity;        // declared argument count (select, min, max: 1)
    bool constant;    // ':' in Radiance: calls with constant arguments are folded
    bool rtraceOnly;  // only with Options::rtraceLibrary
    Kind kind;
    double (*f1)(double) = nullptr;
    double (*f2)(double, double) = nullptr;
    double (*f3)(double, double, double) = nullptr;
};

std::span<const LibraryFunction> Library();

/// Index into Library() of `name`, or -1 (also for an rtrace-only function
/// when `rtrace` is false).
int FindLibraryFunction(std::string_view name, bool rtrace);

/// Radiance's rand(x): a deterministic hash of x into [0, 1).
double HashRandom(double x);

}  // namespace rt::cal
