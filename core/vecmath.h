// SPDX-License-Identifier: MIT
//
// Double-precision 3-vectors (geometry and integration, as Radiance's RREAL)
// and an orthonormal frame. Plain value types; free functions for the algebra.
#pragma once

#include <algorithm>
#include <cmath>
#include <ostream>

namespace rt {

struct Vec3 {
    double x = 0, y = 0, z = 0;

    constexpr Vec3() = default;
    constexpr Vec3(double x_, double y_, double z_) : x(x_), y(y_), z(z_) {}

    constexpr double operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
    constexpr double& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }

    constexpr Vec3 operator+(const Vec3& o) const { return {x + o.x, y + o.y, z + o.z}; }
    constexpr Vec3 operator-(const Vec3& o) const { return {x - o.x, y - o.y, z - o.z}; }
    constexpr Vec3 operator-() const { return {-x, -y, -z}; }
    constexpr Vec3 operator*(double s) const { return {x * s, y * s, z * s}; }
    constexpr Vec3 operator/(double s) const { return {x / s, y / s, z / s}; }
    constexpr Vec3& operator+=(const Vec3& o) { x += o.x; y += o.y; z += o.z; return *this; }
    constexpr Vec3& operator-=(const Vec3& o) { x -= o.x; y -= o.y; z -= o.z; return *this; }
    constexpr Vec3& operator*=(double s) { x *= s; y *= s; z *= s; return *this; }
    constexpr bool operator==(const Vec3&) const = default;
};

constexpr Vec3 operator*(double s, const Vec3& v) { return v * s; }
constexpr double Dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
constexpr Vec3 Cross(const Vec3& a, const Vec3& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
constexpr double LengthSquared(const Vec3& v) { return Dot(v, v); }
inline double Length(const Vec3& v) { return std::sqrt(Dot(v, v)); }
/// Unit vector along v; v must not be zero (callers check, as Radiance's normalize()).
inline Vec3 Normalize(const Vec3& v) { return v / Length(v); }
inline Vec3 Abs(const Vec3& v) { return {std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)}; }
/// Largest absolute component (the infinity norm).
inline double MaxAbs(const Vec3& v) {
    return std::max(std::fabs(v.x), std::max(std::fabs(v.y), std::fabs(v.z)));
}
inline bool IsFinite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
/// std::fmin and std::fmax per component (a NaN loses to a number), written
/// out: GCC calls libm for them, and a large scene's bounds take a call per
/// vertex coordinate (docs/measured-choices.md).
inline double FMin(double a, double b) { return b < a || a != a ? b : a; }
inline double FMax(double a, double b) { return b > a || a != a ? b : a; }
inline Vec3 Min(const Vec3& a, const Vec3& b) {
    return {FMin(a.x, b.x), FMin(a.y, b.y), FMin(a.z, b.z)};
}
inline Vec3 Max(const Vec3& a, const Vec3& b) {
    return {FMax(a.x, b.x), FMax(a.y, b.y), FMax(a.z, b.z)};
}

inline std::ostream& operator<<(std::ostream& os, const Vec3& v) {
    return os << "(" << v.x << ", " << v.y << ", " << v.z << ")";
}

/// Axis-aligned box; empty when lo > hi.
struct Bounds3 {
    Vec3 lo{1e300, 1e300, 1e300};
    Vec3 hi{-1e300, -1e300, -1e300};

    bool Empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
    void Extend(const Vec3& p) { lo = Min(lo, p); hi = Max(hi, p); }
    void Extend(const Bounds3& b) { lo = Min(lo, b.lo); hi = Max(hi, b.hi); }
};

inline Vec3 Perpendicular(const Vec3& n);

/// Orthonormal frame with z along a given unit normal (Mitsuba's Frame).
struct Frame {
    Vec3 u, v, n;

    /// The frame around unit `n` with u = Perpendicular(n), v = n × u.
    static Frame Around(const Vec3& n) {
        const Vec3 u = Perpendicular(n);
        return {u, Cross(n, u), n};
    }

    Vec3 ToWorld(const Vec3& local) const { return u * local.x + v * local.y + n * local.z; }
    Vec3 ToLocal(const Vec3& w) const { return {Dot(w, u), Dot(w, v), Dot(w, n)}; }
};

/// Radiance's getperpendicular() without randomisation: a unit vector
/// perpendicular to unit `n`, built from the first axis (z, y, x order) whose
/// component of n is below 0.6 (radiance-notes.md §0).
inline Vec3 Perpendicular(const Vec3& n) {
    Vec3 v;
    for (int i = 2; i >= 0; --i) {
        if (std::fabs(n[i]) < 0.6) {
            v[i] = 1.0;
            break;
        }
    }
    return Normalize(Cross(v, n));
}

/// cos and sin of x for |x| <= π/4, by their Taylor series to x^16 (error
/// below 2e-16): a fraction of the cost of std::sin and std::cos, whose
/// general range reduction the hemisphere samplers would otherwise pay once
/// per ray (docs/measured-choices.md).
inline void SinCosSmall(double x, double& c, double& s) {
    // Both series in x² by Estrin's scheme (pairs, then pairs of pairs): a
    // dependency chain three deep instead of a Horner chain of eight, which
    // is what the samplers wait on.
    const double z = x * x;
    const double z2 = z * z;
    const double z4 = z2 * z2;
    const double s0 = 1.0 - z * (1.0 / 6), s1 = 1.0 / 120 - z * (1.0 / 5040);
    const double s2 = 1.0 / 362880 - z * (1.0 / 39916800);
    const double s3 = 1.0 / 6227020800 - z * (1.0 / 1307674368000);
    s = x * ((s0 + s1 * z2) + (s2 + s3 * z2) * z4);
    const double c0 = 1.0 - z * 0.5, c1 = 1.0 / 24 - z * (1.0 / 720);
    const double c2 = 1.0 / 40320 - z * (1.0 / 3628800);
    const double c3 = 1.0 / 479001600 - z * (1.0 / 87178291200);
    c = (c0 + c1 * z2) + (c2 + c3 * z2) * z4 + (1.0 / 20922789888000) * (z4 * z4);
}

/// cos and sin of x for 0 <= x <= 2π (an azimuth): the nearest multiple of
/// π/2 taken off, SinCosSmall for the rest (|r| <= π/4), and the quarter turns
/// put back by swapping and negating. Within a few ulps of std::cos and
/// std::sin (the reduction's rounding, at most 2π·1e-16 absolute), for a
/// fraction of their cost.
inline void SinCos(double x, double& c, double& s) {
    constexpr double kHalfPi = 1.5707963267948966;
    const int quarter = static_cast<int>(x * (1.0 / kHalfPi) + 0.5);  // nearest, x >= 0
    double cr, sr;
    SinCosSmall(x - quarter * kHalfPi, cr, sr);
    switch (quarter & 3) {
        case 0: c = cr; s = sr; break;
        case 1: c = -sr; s = cr; break;
        case 2: c = -cr; s = -sr; break;
        default: c = sr; s = -cr; break;
    }
}

}  // namespace rt
