// SPDX-License-Identifier: MIT
//
// Radiance's machine-independent binary numbers, as pure functions over bytes:
// big-endian integers and 5-byte reals (src/common/portio.c putint/getint,
// putflt/getflt) and the 4-byte RGBE colour (src/common/color.c setcolr,
// colr_color). radiance-notes.md §5.3-§5.4. No I/O here.
#pragma once

#include "core/rgbe.h"

#include <array>
#include <cstddef>
#include <cstdint>

#include "core/rgb.h"

namespace rt {

inline constexpr std::size_t kPortableFloatBytes = 5;  // 4-byte mantissa + 1-byte exponent
inline constexpr std::size_t kRgbeBytes = 4;           // R, G, B mantissas + shared exponent

/// The `nbytes` (1..8) low-order bytes of `value`, most significant first, as putint().
void PutPortableInt(std::int64_t value, std::size_t nbytes, std::uint8_t* out);
/// getint(): the first byte sign-extended, then each further byte shifted in.
std::int64_t GetPortableInt(const std::uint8_t* in, std::size_t nbytes);

/// putflt(): mantissa = trunc(frexp(f)·(2^31−1)) as 4 bytes, then the exponent byte;
/// exponents > 127 saturate to ±(2^31−1)·2^127, exponents < −128 give zero. NaN is
/// written as the positive saturated value (Radiance's behaviour is undefined there)
/// so that a reader's validity checks reject it.
void PutPortableFloat(double f, std::uint8_t* out);
/// getflt(): (m ± ½)/(2^31−1)·2^e, and exactly 0 for a zero mantissa.
double GetPortableFloat(const std::uint8_t* in);

}  // namespace rt
