// SPDX-License-Identifier: MIT
#include "cal/library.h"

#include <array>
#include <cmath>

#include "cal/noise.h"

namespace rt::cal {
namespace {

using K = LibraryFunction::Kind;

// Plain function pointers to the C library (errno is how the evaluator sees
// domain and range errors, exactly as calcomp does).
const std::array<LibraryFunction, 26> kLibrary = {{
    {"if", 3, true, false, K::If},
    {"select", 1, true, false, K::Select},
    {"min", 1, true, false, K::Min},
    {"max", 1, true, false, K::Max},
    {"rand", 1, true, false, K::Rand},
    {"floor", 1, true, false, K::Math1, [](double x) { return std::floor(x); }},
    {"ceil", 1, true, false, K::Math1, [](double x) { return std::ceil(x); }},
    {"sqrt", 1, true, false, K::Math1, [](double x) { return std::sqrt(x); }},
    {"exp", 1, true, false, K::Math1, [](double x) { return std::exp(x); }},
    {"log", 1, true, false, K::Math1, [](double x) { return std::log(x); }},
    {"log10", 1, true, false, K::Math1, [](double x) { return std::log10(x); }},
    {"sin", 1, true, false, K::Math1, [](double x) { return std::sin(x); }},
    {"cos", 1, true, false, K::Math1, [](double x) { return std::cos(x); }},
    {"tan", 1, true, false, K::Math1, [](double x) { return std::tan(x); }},
    {"asin", 1, true, false, K::Math1, [](double x) { return std::asin(x); }},
    {"acos", 1, true, false, K::Math1, [](double x) { return std::acos(x); }},
    {"atan", 1, true, false, K::Math1, [](double x) { return std::atan(x); }},
    {"atan2", 2, true, false, K::Math2, nullptr,
     [](double y, double x) { return std::atan2(y, x); }},
    // rtrace: arg(n) is the only '=' library function (never folded).
    {"arg", 1, false, true, K::Arg},
    {"erf", 1, true, true, K::Math1, [](double x) { return std::erf(x); }},
    {"erfc", 1, true, true, K::Math1, [](double x) { return std::erfc(x); }},
    {"noise3", 3, true, true, K::Math3, nullptr, nullptr, &Noise3},
    {"noise3x", 3, true, true, K::Math3, nullptr, nullptr, &Noise3X},
    {"noise3y", 3, true, true, K::Math3, nullptr, nullptr, &Noise3Y},
    {"noise3z", 3, true, true, K::Math3, nullptr, nullptr, &Noise3Z},
    {"fnoise3", 3, true, true, K::Math3, nullptr, nullptr, &FractalNoise3},
}};

}  // namespace

std::span<const LibraryFunction> Library() { return kLibrary; }

int FindLibraryFunction(std::string_view name, bool rtrace) {
    for (std::size_t i = 0; i < kLibrary.size(); ++i) {
        if (kLibrary[i].name == name && (rtrace || !kLibrary[i].rtraceOnly)) {
            return static_cast<int>(i);
        }
    }
    return -1;
}

double HashRandom(double x) {
    x *= 1.0 / (1.0 + x * x) + 2.71828182845904;
    x += 0.785398163397447 - std::floor(x);
    x = 1e5 / x;
    return x - std::floor(x);
}

}  // namespace rt::cal
