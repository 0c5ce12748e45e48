// SPDX-License-Identifier: MIT
//
// The fuzz targets' entry point. libFuzzer calls LLVMFuzzerTestOneInput; the
// regression test (fuzz_regression_test.cpp) compiles the same sources with
// RT_FUZZ_ENTRY renamed per target so all three link into one executable.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "core/error.h"

#ifndef RT_FUZZ_ENTRY
#define RT_FUZZ_ENTRY LLVMFuzzerTestOneInput
#endif

extern "C" int RT_FUZZ_ENTRY(const std::uint8_t* data, std::size_t size);

namespace rt::fuzz {

/// For a target's `catch (const rt::Error& e)`: a User or System error is the
/// parser refusing the input, as it should, and so is one of the bad inputs
/// Radiance itself reports as internal (Error::InternalByInput); any other
/// Internal one is lazyrad's own invariant broken by input that got past the
/// parser, so a finding.
inline void ExpectRefusal(const rt::Error& e) {
    if (!e.RefusesInput()) {
        std::fprintf(stderr, "fuzz: internal error: %s\n", e.what());
        std::abort();
    }
}

}  // namespace rt::fuzz
