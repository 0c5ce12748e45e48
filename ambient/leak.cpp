// SPDX-License-Identifier: MIT
#include "ambient/leak.h"

#include <algorithm>
#include <cmath>

#include "core/conventions.h"

namespace rt {

namespace {
constexpr double kSector = kPi / 16;  // 32 sectors around the normal

/// Azimuth of x in [0, 2π).
double Azimuth(double x, double y) {
    const double a = std::atan2(y, x);
    return a < 0 ? a + 2 * kPi : a;
}

/// Bits of every sector the azimuth range [start, end) overlaps, for
/// 0 <= start < end <= 2π.
std::uint32_t SectorBits(double start, double end) {
    const int first = static_cast<int>(start / kSector);
    const int last = std::min(31, static_cast<int>(std::nextafter(end, 0.0) / kSector));
    std::uint32_t bits = 0;
    for (int k = first; k <= last; ++k) bits |= std::uint32_t{1} << k;
    return bits;
}

/// As SectorBits for any range [start, end) with -2π <= start < end and
/// end - start <= 2π: azimuths are taken modulo 2π.
std::uint32_t WrappedSectorBits(double start, double end) {
    if (start < 0) {
        start += 2 * kPi;
        end += 2 * kPi;
    }
    if (end > 2 * kPi) return SectorBits(start, 2 * kPi) | SectorBits(0, end - 2 * kPi);
    return SectorBits(start, end);
}
}  // namespace

// Radiance 5 skips the corral when what lies overhead is near (its "ceiling
// too low" rule), and skips occluders nearer than minarad·a, so a record 5 cm
// from a thin wall still served queries 5 cm behind it, in a closed room that
// must stay black (tests/data/leak). The test ray is exact, so flagging those
// directions too costs rays, never accuracy: neither corral below skips them.

std::uint32_t CorralBits(const Hemisphere& hemisphere, double validityRadius) {
    const auto& horizon = hemisphere.horizonInverseDistance;
    if (!hemisphere.complete || horizon.empty()) return 0;
    // No "ceiling too low" rule, as for the Hessian corral below: a sensor
    // 5 cm outside a wall sees the wall over much of its zenith, and when
    // -ar clamps its record's radius up that record reached through the wall
    // into the closed room for some seeds (tests/data/leak).
    const int columns = static_cast<int>(horizon.size());
    std::uint32_t bits = 0;
    for (int p = 0; p < columns; ++p) {
        const double inverse = horizon[static_cast<size_t>(p)];
        // Something hit inside the validity radius.
        if (!(inverse > kFtiny) || inverse * validityRadius <= 1) continue;
        // Every sector the column's azimuth range [φp, φp+1) overlaps.
        const double start = 2 * kPi * p / columns;
        const double end = 2 * kPi * (p + 1) / columns;
        bits |= SectorBits(start, end);
    }
    return bits;
}

std::uint32_t CorralBits(const HessianHemisphere& hemisphere, const Vec3& u,
                         double validityRadius0, double validityRadius1) {
    const int ns = hemisphere.ns;
    // Too few samples for the perimeter to say where a wall stands.
    if (!hemisphere.complete || ns < 8) return 0;
    // No "ceiling too low" rule here, unlike Radiance 5 and the classic
    // corral: its premise, that a record under something near has a radius
    // too small to reach past it, fails where -ar's minimum radius clamps the
    // radius up. A sensor 5 cm outside a wall has a wall, not a ceiling,
    // over half its central cells, and its record then leaked through the
    // wall (tests/data/leak). The leak rays this adds are few (README).
    const Vec3 v = Cross(hemisphere.frame.n, u);
    const double r0Squared = validityRadius0 * validityRadius0;
    const double r1Squared = validityRadius1 * validityRadius1;
    // Half the angular width of a perimeter cell: its azimuth is known no better.
    const double spread = 0.5 * kPi / ns;
    std::uint32_t bits = 0;
    for (int i = 0; i < ns; ++i) {
        const bool fullRow = i == 0 || i == ns - 1;
        for (int j = 0; j < ns; j += fullRow ? 1 : ns - 1) {
            const HessianCell& c = hemisphere.At(i, j);
            const double inverse = c.inverseDistance;
            if (!(inverse > kFtiny)) continue;
            const double x = Dot(c.offset, u);
            const double y = Dot(c.offset, v);
            // Inside the ellipse: distance below its reach in this direction.
            if ((r0Squared * x * x + r1Squared * y * y) * inverse * inverse <= x * x + y * y)
                continue;
            const double angle = std::atan2(y, x);
            bits |= WrappedSectorBits(angle - spread, angle + spread);
        }
    }
    return bits;
}

bool CorralCovers(const AmbientRecord& record, const Vec3& point) {
    if (record.corral == 0) return false;
    const Vec3 d = point - record.position;
    const double angle = Azimuth(Dot(d, record.uAxis), Dot(d, record.VAxis()));
    const int k = std::min(31, static_cast<int>(angle / kSector));
    return (record.corral >> k) & 1u;
}

LeakTest MakeLeakTest(const Vec3& point, const Vec3& normal, const Vec3& recordPoint,
                      const Vec3& recordNormal, double tolerance) {
    // The ray runs along D + t·Ni; t solves (N·(D + t·Ni))² = c²·|D + t·Ni|²,
    // an elevation of 20° over the query surface (c = cos 70°).
    constexpr double kCos2 = 0.1169778;  // cos²(70°)
    const Vec3 d = recordPoint - point;
    const double nn = Dot(recordNormal, normal);
    const double dn = Dot(d, normal);
    const double dni = Dot(d, recordNormal);
    const double a = nn * nn - kCos2;
    const double b = 2 * (nn * dn - dni * kCos2);
    const double c = dn * dn - LengthSquared(d) * kCos2;
    LeakTest test;
    // Two roots are needed, as in Radiance; otherwise no such ray exists and
    // the record counts as hidden.
    if (a == 0) {
        test.outcome = LeakTest::Outcome::kHidden;
        return test;
    }
    const double discriminant = b * b - 4 * a * c;
    if (!(discriminant > 0)) {
        test.outcome = LeakTest::Outcome::kHidden;
        return test;
    }
    const double root = std::sqrt(discriminant);
    const double t1 = std::max((-b + root) / (2 * a), (-b - root) / (2 * a));
    if (t1 <= tolerance) return test;  // kVisible
    const Vec3 ray = d + recordNormal * t1;
    const double length = Length(ray);
    if (!(length > 0) || !std::isfinite(length)) {
        test.outcome = LeakTest::Outcome::kHidden;
        return test;
    }
    test.outcome = LeakTest::Outcome::kTrace;
    test.dir = ray / length;
    test.length = length;
    return test;
}

}  // namespace rt
