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
}  // namespace

std::uint32_t CorralBits(const Hemisphere& hemisphere, double validityRadius,
                         double maxInverseDistance) {
    const auto& horizon = hemisphere.horizonInverseDistance;
    if (!hemisphere.complete || horizon.empty()) return 0;
    const double zenith = hemisphere.zenithInverseDistance;
    if (zenith * validityRadius >= 1 || zenith >= maxInverseDistance) return 0;
    const int columns = static_cast<int>(horizon.size());
    std::uint32_t bits = 0;
    for (int p = 0; p < columns; ++p) {
        const double inverse = horizon[static_cast<size_t>(p)];
        // Something hit inside the validity radius. Radiance 5 also skips
        // occluders nearer than minarad·a (1/maxInverseDistance), so a record
        // 5 cm from a thin wall still served queries 5 cm behind it, in a
        // closed room that must stay black (tests/data/leak). The test ray is
        // exact, so flagging those directions too costs rays, never accuracy.
        if (!(inverse > kFtiny) || inverse * validityRadius <= 1) continue;
        // Every sector the column's azimuth range [φp, φp+1) overlaps.
        const double start = 2 * kPi * p / columns;
        const double end = 2 * kPi * (p + 1) / columns;
        const int first = static_cast<int>(start / kSector);
        const int last = std::min(31, static_cast<int>(std::nextafter(end, 0.0) / kSector));
        for (int k = first; k <= last; ++k) bits |= std::uint32_t{1} << k;
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
