// SPDX-License-Identifier: MIT
#include "cal/search.h"

#include <sys/stat.h>

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>
#include <system_error>

#include "cal/builtin_files.h"
#include "core/error.h"

namespace rt::cal {
namespace {

bool IsRegularFile(const std::string& path) {
    struct stat info {};
    return ::stat(path.c_str(), &info) == 0 && S_ISREG(info.st_mode);
}

std::string Join(const std::string& dir, std::string_view name) {
    if (dir.empty()) return std::string(name);
    return dir.back() == '/' ? dir + std::string(name) : dir + "/" + std::string(name);
}

}  // namespace

SearchPath SearchPath::FromRaypath(std::string_view raypath) {
    SearchPath path;
    for (;;) {
        const std::size_t colon = raypath.find(':');
        path.entries.emplace_back(raypath.substr(0, colon));
        if (colon == std::string_view::npos) break;
        raypath.remove_prefix(colon + 1);
    }
    return path;
}

SearchPath SearchPath::FromEnvironment() {
    const char* raypath = std::getenv("RAYPATH");
    return FromRaypath(raypath != nullptr ? raypath : ":/usr/local/lib/ray");
}

std::optional<std::string> FindFilePath(std::string_view name, const SearchPath& path) {
    if (name.empty()) return std::nullopt;
    const auto present = [](std::string candidate) -> std::optional<std::string> {
        if (IsRegularFile(candidate)) return candidate;
        return std::nullopt;
    };
    // Radiance's getpath(): absolute names and names starting with '.' or '~'
    // are taken as they are.
    if (name.front() == '/' || name.front() == '.') return present(std::string(name));
    if (name.front() == '~') {
        const std::size_t slash = name.find('/');
        const char* home = std::getenv("HOME");
        if (slash != 1 || home == nullptr) return present(std::string(name));
        return present(std::string(home) + std::string(name.substr(1)));
    }
    for (const std::string& dir : path.entries) {
        if (auto found = present(Join(dir, name))) return found;
    }
    for (const std::string& dir : path.fallbackDirs) {
        if (auto found = present(Join(dir, name))) return found;
    }
    return std::nullopt;
}

std::optional<SourceText> FindFunctionFile(std::string_view name, const SearchPath& path) {
    if (const std::optional<std::string> found = FindFilePath(name, path)) {
        std::ifstream in(*found, std::ios::binary);
        if (!in) ThrowSystemError("cannot open function file \"" + *found + "\"");
        std::ostringstream text;
        text << in.rdbuf();
        if (in.bad()) ThrowSystemError("cannot read function file \"" + *found + "\"");
        return SourceText{*found, text.str()};
    }
    if (path.builtins) {
        if (const std::optional<std::string_view> text = FindBuiltinFile(name)) {
            return SourceText{std::string(name), std::string(*text)};
        }
    }
    return std::nullopt;
}

std::string ContextNameForFile(std::string_view name) {
    std::string context(name);
    if (context.size() > 4 && context.ends_with(".cal")) context.resize(context.size() - 4);
    for (char& c : context) {
        const bool keep = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                          (c >= '0' && c <= '9') || c == '_' || c == '.';
        if (!keep) c = '_';
    }
    return context;
}

}  // namespace rt::cal
