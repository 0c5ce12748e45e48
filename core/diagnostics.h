// SPDX-License-Identifier: MIT
//
// Warnings go through a sink the caller owns (no global error state, unlike
// Radiance's error()): the rtrace front end prints them as
// "rtrace: warning - <text>" unless -w- is given; tests collect them.
#pragma once

#include <functional>
#include <string>

namespace rt {

using WarningSink = std::function<void(const std::string& message)>;

}  // namespace rt
