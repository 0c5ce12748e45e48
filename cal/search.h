// SPDX-License-Identifier: MIT
//
// Finding function files as Radiance's getpath() does (radiance-functions.md
// §9.12): the RAYPATH entries in order, then lazyrad's own files. Also the
// context name rtrace gives each file.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rt::cal {

struct SearchPath {
    /// Directories tried in order; "" is the current directory.
    std::vector<std::string> entries;
    /// Tried after `entries`: where lazyrad's own files are installed, if anywhere.
    std::vector<std::string> fallbackDirs;
    /// Last resort: the files of lib/ compiled into lazyrad (cal/builtin_files.h).
    bool builtins = true;

    /// RAYPATH split at ':' (empty entries are the current directory).
    static SearchPath FromRaypath(std::string_view raypath);
    /// $RAYPATH, or Radiance's default ":/usr/local/lib/ray" when unset.
    static SearchPath FromEnvironment();
};

/// The text of a function file and the name to use for it in messages.
struct SourceText {
    std::string name;  // the path opened, or the bare name for a built-in file
    std::string text;
};

/// Radiance's getpath(): the first regular file `name` on `path` (its
/// entries, then its fallback directories; not the built-in files). Names
/// that are absolute or start with '.' or '~' are used as given.
std::optional<std::string> FindFilePath(std::string_view name, const SearchPath& path);

/// Reads `name` from the first place on `path` that has it. Names that are
/// absolute or start with '.' or '~' are used as given, not searched.
/// std::nullopt when it is nowhere; a file that exists but cannot be read
/// throws rt::Error (System).
std::optional<SourceText> FindFunctionFile(std::string_view name, const SearchPath& path);

/// rtrace's context name for a function file as written in a modifier: a
/// trailing ".cal" removed (names longer than 4 characters only), every
/// character other than a letter, digit, '_' or '.' replaced by '_'.
/// "skybright.cal" -> "skybright", "dir/x.cal" -> "dir_x".
std::string ContextNameForFile(std::string_view name);

}  // namespace rt::cal
