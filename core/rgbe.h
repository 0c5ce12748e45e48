// SPDX-License-Identifier: MIT
//
// Radiance's 4-byte RGBE colour (color.c setcolr()/colr_color(), radiance-notes
// §5.4): a shared 8-bit exponent and three 8-bit mantissas. Used by ambient
// files, Radiance pictures and rtrace's -fc output, so it lives here once.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "core/rgb.h"

namespace rt {

using Rgbe = std::array<std::uint8_t, 4>;

/// Byte-for-byte what setcolr() writes for values in RGBE's range. Negative
/// channels become 0 and NaN or values below 1e-32 black. Unlike setcolr(),
/// whose exponent byte wraps around, values too large for the format (and
/// infinity) become the largest RGBE value.
inline Rgbe EncodeRgbe(double r, double g, double b) {
    const double mx = std::max({r, g, b});
    if (!(mx > 1e-32)) return {0, 0, 0, 0};  // also NaN
    if (std::isinf(mx)) return {255, 255, 255, 255};
    int e = 0;
    const double d = std::frexp(mx, &e) * 256.0 / mx;  // setcolr()'s operation order
    if (e > 127) return {255, 255, 255, 255};
    auto channel = [d](double c) -> std::uint8_t {
        if (!(c > 0.0)) return 0;
        const double v = c * d;
        return v < 256.0 ? static_cast<std::uint8_t>(v) : 255;
    };
    return {channel(r), channel(g), channel(b), static_cast<std::uint8_t>(e + 128)};
}
inline Rgbe EncodeRgbe(const Rgb& c) { return EncodeRgbe(c.r, c.g, c.b); }

/// colr_color(): each mantissa read at the middle of its interval.
inline Rgb DecodeRgbe(const std::uint8_t* in) {
    if (in[3] == 0) return {};
    const double f = std::ldexp(1.0, static_cast<int>(in[3]) - (128 + 8));
    return {(in[0] + 0.5) * f, (in[1] + 0.5) * f, (in[2] + 0.5) * f};
}
inline Rgb DecodeRgbe(const Rgbe& c) { return DecodeRgbe(c.data()); }

}  // namespace rt
