// SPDX-License-Identifier: MIT
//
// rtrace's input records (radiance-notes.md §1.5): origin and direction as six
// ascii words (-fa), native floats (-ff) or native doubles (-fd). Replaces
// rtrace.c's getvec().
//
// Deliberate difference from Radiance: Radiance treats the first word that is
// not a number, and a short final record, as the end of input and exits 0.
// lazyrad reports them (and NaN/Inf values) as errors, so a corrupt ray file
// cannot silently produce a short result: "bad ray at line N" (ascii, N the
// 1-based line of the offending word, or of the last word of a truncated
// record) or "bad ray at record N (byte B)" (binary, N 1-based, B the offset
// of the offending value or where a truncated record ends).
#pragma once

#include <cstdint>
#include <istream>
#include <optional>
#include <string>

#include "core/error.h"
#include "core/vecmath.h"

namespace rt {

/// Thrown for malformed input; rtrace prints it as "rtrace: <what()>" (no
/// "fatal - " prefix) and exits 1.
class BadRayError : public Error {
public:
    explicit BadRayError(const std::string& message) : Error(Error::Kind::User, message) {}
};

struct InputRay {
    Vec3 origin;
    Vec3 direction;  // as given: not normalised, possibly zero (a flush request)
};

class RayReader {
public:
    /// `format`: 'a', 'f' or 'd'.
    RayReader(std::istream& in, char format);

    /// The next record; std::nullopt at the end of input between records.
    /// Throws BadRayError.
    std::optional<InputRay> Next();

private:
    std::optional<InputRay> NextAscii();
    std::optional<InputRay> NextBinary();
    /// Reads one white-space separated word into word_; false at end of input.
    bool ReadWord();

    std::istream& in_;
    char format_;
    std::string word_;
    long long line_ = 1;       // current line of the ascii reader
    long long wordLine_ = 0;   // line where word_ started
    std::uint64_t record_ = 0; // records returned so far
    std::uint64_t byte_ = 0;   // bytes consumed by the binary reader
};

}  // namespace rt
