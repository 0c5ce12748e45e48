// SPDX-License-Identifier: MIT
//
// The one exception type for user, system and internal failures at the edges
// (parsing, opening files, Embree set-up). Hot paths never throw. main() maps
// Error::Kind to Radiance's exit codes (rterror.h: user 1, system 2,
// internal 3; radiance-notes.md §1.12).
#pragma once

#include <stdexcept>
#include <string>

namespace rt {

/// Where in an input a problem is: "file:line" for text, "file: byte N" for binary.
struct FileLoc {
    std::string file;   // file name as given by the user; "<stdin>" or "!cmd" allowed
    int line = 0;       // 1-based line, 0 when unknown or not a text position
    long long byteOffset = -1;  // for binary input, -1 when unused

    std::string ToString() const;
};

class Error : public std::runtime_error {
public:
    enum class Kind { User, System, Internal };

    Error(Kind kind, const std::string& message);
    Error(Kind kind, const FileLoc& loc, const std::string& message);

    /// Radiance reports a few kinds of bad input as INTERNAL errors (exit 3;
    /// m_mist.c's "too many sources in list"). lazyrad keeps the word and the
    /// status, and marks them as the input's, so that the fuzz targets can
    /// tell them from an invariant of lazyrad's own broken by input.
    static Error InternalByInput(const FileLoc& loc, const std::string& message);
    static Error InternalByInput(const std::string& message);

    Kind kind() const { return kind_; }
    /// Radiance's exit status for this kind of error.
    int ExitCode() const;
    /// True for user and system errors and for InternalByInput: the input (or
    /// the system) was refused, rather than lazyrad failing.
    bool RefusesInput() const { return kind_ != Kind::Internal || byInput_; }

private:
    Kind kind_;
    bool byInput_ = false;
};

/// Shorthands for the common case of a user error at a place in an input.
[[noreturn]] void ThrowUserError(const FileLoc& loc, const std::string& message);
[[noreturn]] void ThrowUserError(const std::string& message);
[[noreturn]] void ThrowSystemError(const std::string& message);

}  // namespace rt
