// SPDX-License-Identifier: MIT
//
// lazyrad's own function files (the folder lib/ of the source tree), compiled
// into the program so that a machine without Radiance finds them. The table is
// generated at build time by cal/embed_files.cmake.
#pragma once

#include <optional>
#include <span>
#include <string_view>

namespace rt::cal {

struct BuiltinFile {
    std::string_view name;  // file name, e.g. "rayinit.cal"
    std::string_view text;
};

/// Every built-in file, sorted by name.
std::span<const BuiltinFile> BuiltinFiles();

/// The text of the built-in file `name`, if there is one.
std::optional<std::string_view> FindBuiltinFile(std::string_view name);

}  // namespace rt::cal
