// SPDX-License-Identifier: MIT
//
// Helpers shared by the cal tests: channel values, message collection, and a
// Program set up as rtrace sets it up (ray variables, lazyrad's rayinit).
#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "cal/program.h"
#include "core/error.h"

namespace rt::cal::testing {

/// Channel n is values[n - 1] (0 past the end).
struct Channels : ChannelSource {
    std::vector<double> values;
    double Channel(int n) const override {
        return static_cast<std::size_t>(n) <= values.size()
                   ? values[static_cast<std::size_t>(n) - 1]
                   : 0.0;
    }
};

/// Only lazyrad's built-in files: tests never depend on RAYPATH or ../shared.
inline SearchPath BuiltinsOnly() { return SearchPath{}; }

/// A Program with rtrace's globals, collecting warnings.
struct RtraceProgram {
    std::shared_ptr<std::vector<std::string>> warnings =
        std::make_shared<std::vector<std::string>>();
    Program program{Options{}, [w = warnings](const std::string& m) { w->push_back(m); }};
    RtraceProgram() {
        program.DefineRayVariables();
        program.LoadRayinit(BuiltinsOnly());
    }
};

/// The message of the rt::Error `f` throws, or "" (and a test failure) if none.
template <typename F>
std::string ErrorOf(F&& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    ADD_FAILURE() << "expected an rt::Error";
    return {};
}

}  // namespace rt::cal::testing
