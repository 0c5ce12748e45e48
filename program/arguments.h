// SPDX-License-Identifier: MIT
//
// Command-line words as Radiance's programs take them (rtmain.c, rpmain.c,
// words.c, badarg.c): `@file` and `$VAR` expansion, nextword()'s word splitting,
// and badarg()'s checks of integer, real and word values. rtrace's option table
// and rvimage's own options are both parsed with these.
//
//   ExpandInPlace(args, i);                      // throws rt::Error (System)
//   if (!IsIntArgument(args[i + 1])) ...         // "command line error"
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rt {

/// The program's name as messages print it: `argv0` without its directory.
std::string ProgramName(std::string_view argv0);

/// Splits text into white-space separated words; a word starting with a
/// double or single quote runs to the matching quote (Radiance's nextword()).
std::vector<std::string> SplitWords(std::string_view text);

/// The words of the file at `path`; std::nullopt when it cannot be opened.
std::optional<std::vector<std::string>> ReadWords(const std::string& path);

/// Replaces an argument starting with '@' by the words of that file and one
/// starting with '$' by the words of that environment variable. Throws
/// rt::Error(System, "cannot expand '<arg>'...") when there is no such file or
/// variable. Returns the argument itself when it needs no expansion.
std::vector<std::string> ExpandArgument(const std::string& arg);

/// Expands args[i] in place until it no longer starts with '@' or '$' (an
/// expansion may start with another). A file that names itself would expand
/// for ever; past 64 rounds this throws rt::Error(System, "cannot expand").
void ExpandInPlace(std::vector<std::string>& args, std::size_t i);

/// Radiance's isint()/isflt() as used by badarg(): leading blanks, then the
/// number, then end of string or white space.
bool IsIntArgument(std::string_view s);
bool IsRealArgument(std::string_view s);
/// badarg()'s 's' check: not blank, printable characters only.
bool IsWordArgument(std::string_view s);

}  // namespace rt
