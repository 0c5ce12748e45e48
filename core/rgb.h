// SPDX-License-Identifier: MIT
//
// RGB colour triple (radiance, irradiance or a coefficient) with Radiance's
// bright() and intens() measures (radiance-notes.md §0).
#pragma once

#include <algorithm>
#include <cmath>
#include <ostream>

namespace rt {

struct Rgb {
    double r = 0, g = 0, b = 0;

    constexpr Rgb() = default;
    constexpr Rgb(double r_, double g_, double b_) : r(r_), g(g_), b(b_) {}
    static constexpr Rgb Grey(double v) { return {v, v, v}; }

    constexpr double operator[](int i) const { return i == 0 ? r : (i == 1 ? g : b); }
    constexpr double& operator[](int i) { return i == 0 ? r : (i == 1 ? g : b); }

    constexpr Rgb operator+(const Rgb& o) const { return {r + o.r, g + o.g, b + o.b}; }
    constexpr Rgb operator-(const Rgb& o) const { return {r - o.r, g - o.g, b - o.b}; }
    constexpr Rgb operator*(const Rgb& o) const { return {r * o.r, g * o.g, b * o.b}; }
    constexpr Rgb operator*(double s) const { return {r * s, g * s, b * s}; }
    constexpr Rgb operator/(double s) const { return {r / s, g / s, b / s}; }
    constexpr Rgb& operator+=(const Rgb& o) { r += o.r; g += o.g; b += o.b; return *this; }
    constexpr Rgb& operator*=(const Rgb& o) { r *= o.r; g *= o.g; b *= o.b; return *this; }
    constexpr Rgb& operator*=(double s) { r *= s; g *= s; b *= s; return *this; }
    constexpr bool operator==(const Rgb&) const = default;
};

constexpr Rgb operator*(double s, const Rgb& c) { return c * s; }

/// Radiance's bright(): luminance-weighted brightness (CIE Y of its primaries).
constexpr double Bright(const Rgb& c) {
    return 0.265074126 * c.r + 0.670114631 * c.g + 0.064811243 * c.b;
}
/// Radiance's intens(): the largest channel.
constexpr double Intens(const Rgb& c) { return std::max({c.r, c.g, c.b}); }
inline bool IsFinite(const Rgb& c) {
    return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b);
}

inline std::ostream& operator<<(std::ostream& os, const Rgb& c) {
    return os << "rgb(" << c.r << ", " << c.g << ", " << c.b << ")";
}

}  // namespace rt
