// SPDX-License-Identifier: MIT
//
// The fuzz targets' entry point. libFuzzer calls LLVMFuzzerTestOneInput; the
// regression test (fuzz_regression_test.cpp) compiles the same sources with
// RT_FUZZ_ENTRY renamed per target so all three link into one executable.
#pragma once

#include <cstddef>
#include <cstdint>

#ifndef RT_FUZZ_ENTRY
#define RT_FUZZ_ENTRY LLVMFuzzerTestOneInput
#endif

extern "C" int RT_FUZZ_ENTRY(const std::uint8_t* data, std::size_t size);
