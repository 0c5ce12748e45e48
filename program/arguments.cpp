// SPDX-License-Identifier: MIT
#include "program/arguments.h"

#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <cstdio>

#include "core/error.h"

namespace rt {
namespace {

// Radiance keeps expanding the same position while it starts with @ or $; a
// file that names itself would loop forever there, so we stop at this depth.
constexpr int kMaxExpansionDepth = 64;

// Radiance's iskip(): returns the position after an integer, or npos.
std::size_t SkipInt(std::string_view s, std::size_t i) {
    while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
    if (i < s.size() && (s[i] == '-' || s[i] == '+')) ++i;
    if (i >= s.size() || !std::isdigit(static_cast<unsigned char>(s[i]))) return std::string_view::npos;
    while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i;
    return i;
}

// Radiance's fskip().
std::size_t SkipReal(std::string_view s) {
    std::size_t i = 0;
    while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
    if (i < s.size() && (s[i] == '-' || s[i] == '+')) ++i;
    std::size_t digits = 0;
    while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i, ++digits;
    if (i < s.size() && s[i] == '.') {
        ++i;
        while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i, ++digits;
    }
    if (digits == 0) return std::string_view::npos;
    if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) return SkipInt(s, i + 1);
    return i;
}

// badarg() accepts a number followed by the end or by a blank.
bool EndsAtDelimiter(std::string_view s, std::size_t end) {
    return end != std::string_view::npos &&
           (end == s.size() || s[end] == ' ' || s[end] == '\t' || s[end] == '\r' ||
            s[end] == '\n');
}

}  // namespace

std::string ProgramName(std::string_view argv0) {
    const std::size_t slash = argv0.find_last_of('/');
    return std::string(slash == std::string_view::npos ? argv0 : argv0.substr(slash + 1));
}

bool IsIntArgument(std::string_view s) { return EndsAtDelimiter(s, SkipInt(s, 0)); }
bool IsRealArgument(std::string_view s) { return EndsAtDelimiter(s, SkipReal(s)); }

bool IsWordArgument(std::string_view s) {
    std::size_t i = 0;
    while (i < s.size() && s[i] == ' ') ++i;
    if (i == s.size()) return false;
    for (; i < s.size(); ++i)
        if (!std::isprint(static_cast<unsigned char>(s[i]))) return false;
    return true;
}

std::vector<std::string> SplitWords(std::string_view text) {
    std::vector<std::string> words;
    std::size_t i = 0;
    while (true) {
        while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
        if (i >= text.size()) break;
        char quote = 0;
        if (text[i] == '"' || text[i] == '\'') quote = text[i++];
        std::size_t start = i;
        while (i < text.size() &&
               (quote ? text[i] != quote : !std::isspace(static_cast<unsigned char>(text[i]))))
            ++i;
        words.emplace_back(text.substr(start, i - start));
        if (quote && i < text.size()) ++i;
    }
    return words;
}

std::optional<std::vector<std::string>> ReadWords(const std::string& path) {
    // stdio rather than a stream: libstdc++'s streams throw on a read error
    // (a directory opens, then fails to read). Radiance's wordfile() takes a
    // failed read as the end of the words, and so does this.
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) return std::nullopt;
    std::string text;
    char buf[4096];
    for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, f)) > 0;) text.append(buf, n);
    std::fclose(f);
    return SplitWords(text);
}

std::vector<std::string> ExpandArgument(const std::string& arg) {
    if (arg.empty() || (arg[0] != '@' && arg[0] != '$')) return {arg};
    if (arg[0] == '@') {
        // A bare '@' names no file; Radiance reports it without a cause.
        const int saved = errno;
        errno = 0;
        std::optional<std::vector<std::string>> words;
        if (arg.size() > 1) words = ReadWords(arg.substr(1));
        const int cause = errno;
        errno = saved;
        if (!words) {
            ThrowSystemError("cannot expand '" + arg + "'" +
                             (cause != 0 ? std::string(": ") + std::strerror(cause) : ""));
        }
        return std::move(*words);
    }
    const char* value = std::getenv(arg.c_str() + 1);
    if (!value) ThrowSystemError("cannot expand '" + arg + "'");
    return SplitWords(value);
}

void ExpandInPlace(std::vector<std::string>& args, std::size_t i) {
    for (int depth = 0; i < args.size() && !args[i].empty() &&
                        (args[i][0] == '@' || args[i][0] == '$');
         ++depth) {
        if (depth == kMaxExpansionDepth) ThrowSystemError("cannot expand '" + args[i] + "'");
        std::vector<std::string> words = ExpandArgument(args[i]);
        args.erase(args.begin() + static_cast<std::ptrdiff_t>(i));
        args.insert(args.begin() + static_cast<std::ptrdiff_t>(i), words.begin(), words.end());
    }
}

}  // namespace rt
