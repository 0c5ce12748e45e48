// SPDX-License-Identifier: MIT
#include "core/dircode.h"

#include <cmath>

namespace rt {
namespace {

// (2^13 − ½)·√2: the largest stored magnitude, 1/√2, maps to just under 2^13.
constexpr double kScale = 11584.5;
constexpr std::uint32_t kNegX = 0x01, kNegY = 0x02, kNegZ = 0x04;
constexpr std::uint32_t kFirstIsX = 0x08;   // F1X: first stored component is x, else y
constexpr std::uint32_t kSecondIsZ = 0x10;  // F2Z: second is z, else the larger of x/y
constexpr int kFirstShift = 5, kSecondShift = 18;
constexpr std::uint32_t kMask = 0x1fff;
constexpr double kClamp = 1 << 24;

}  // namespace

std::uint32_t EncodeDirection(const Vec3& v) {
    std::uint32_t code = 0;
    std::uint32_t a[3];
    for (int i = 0; i < 3; ++i) {
        double m = v[i];
        if (m < 0) {
            m = -m;
            code |= kNegX << i;
        }
        // The clamp only keeps the float->int conversion defined for wild (non-unit,
        // non-finite) input; for unit vectors it never applies.
        const double scaled = m * kScale + 0.5;
        a[i] = scaled < kClamp ? static_cast<std::uint32_t>(scaled)
                               : (std::isnan(scaled) ? 0 : static_cast<std::uint32_t>(kClamp));
    }
    if ((a[0] | a[1] | a[2]) == 0) return kZeroDirectionCode;
    std::uint32_t larger;
    if (a[0] <= a[1]) {
        code |= kFirstIsX | ((a[0] & kMask) << kFirstShift);
        larger = a[1];
    } else {
        code |= (a[1] & kMask) << kFirstShift;
        larger = a[0];
    }
    if (a[2] <= larger) {
        code |= kSecondIsZ | ((a[2] & kMask) << kSecondShift);
    } else {
        code |= (larger & kMask) << kSecondShift;
    }
    return code != 0 ? code : kFirstIsX;
}

Vec3 DecodeDirection(std::uint32_t code) {
    if (code == kZeroDirectionCode) return {};
    const double d1 = ((code >> kFirstShift) & kMask) * (1.0 / kScale);
    const double d2 = ((code >> kSecondShift) & kMask) * (1.0 / kScale);
    const double der = std::sqrt(1.0 - d1 * d1 - d2 * d2);
    Vec3 v;
    if (code & kFirstIsX) {
        v.x = d1;
        if (code & kSecondIsZ) {
            v.y = der;
            v.z = d2;
        } else {
            v.y = d2;
            v.z = der;
        }
    } else {
        v.y = d1;
        if (code & kSecondIsZ) {
            v.x = der;
            v.z = d2;
        } else {
            v.x = d2;
            v.z = der;
        }
    }
    if (code & kNegX) v.x = -v.x;
    if (code & kNegY) v.y = -v.y;
    if (code & kNegZ) v.z = -v.z;
    return v;
}

}  // namespace rt
