// SPDX-License-Identifier: MIT
//
// Helpers shared by the scene tests: parse/build scene text held in a string,
// collect warnings, capture the message of an expected rt::Error.
#pragma once

#include <gtest/gtest.h>

#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "core/error.h"
#include "scene/loader.h"

namespace rt::testing {

inline SceneLoadOptions ToolOptions() {
    SceneLoadOptions options;
    options.toolDirectory = RT_BINARY_DIR "/bin";
    return options;
}

inline std::vector<SceneObject> ParseText(const std::string& text,
                                          std::vector<std::string>* warnings = nullptr,
                                          const std::string& name = "t.rad",
                                          const SceneLoadOptions& options = ToolOptions()) {
    std::istringstream in(text);
    return ReadSceneObjects(in, name, options, [warnings](const std::string& message) {
        if (warnings != nullptr) warnings->push_back(message);
    });
}

inline Scene BuildText(const std::string& text, std::vector<std::string>* warnings = nullptr) {
    const auto objects = ParseText(text, warnings);
    return BuildScene(objects, [warnings](const std::string& message) {
        if (warnings != nullptr) warnings->push_back(message);
    });
}

/// The message of the rt::Error `action` throws; fails the test if it throws
/// nothing or an error of another kind.
inline std::string ErrorMessage(const std::function<void()>& action,
                                Error::Kind kind = Error::Kind::User) {
    try {
        action();
    } catch (const Error& e) {
        EXPECT_EQ(static_cast<int>(e.kind()), static_cast<int>(kind)) << e.what();
        return e.what();
    }
    ADD_FAILURE() << "no rt::Error thrown";
    return "";
}

inline std::string ParseError(const std::string& text) {
    return ErrorMessage([&] { ParseText(text); });
}

inline std::string BuildError(const std::string& text) {
    return ErrorMessage([&] { BuildText(text); });
}

}  // namespace rt::testing
