// SPDX-License-Identifier: MIT
#include "ambient/leak.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/conventions.h"

namespace rt {
namespace {

TEST(LeakTest, SamePlaneRecordIsSeenAt20Degrees) {
    // Query and record on one floor, 2 apart: the ray rises at 20° and ends
    // above the record, at 2·tan 20° over it.
    const Vec3 n{0, 0, 1};
    const LeakTest t = MakeLeakTest({0, 0, 0}, n, {2, 0, 0}, n, 1e-6);
    ASSERT_EQ(t.outcome, LeakTest::Outcome::kTrace);
    EXPECT_NEAR(t.dir.z, std::sin(20 * kPi / 180), 1e-6);
    EXPECT_NEAR(t.length, 2 / std::cos(20 * kPi / 180), 1e-6);
    EXPECT_NEAR(t.dir.x * t.length, 2, 1e-9);
}

TEST(LeakTest, RecordHighAboveNeedsNoLift) {
    // Already more than 20° above the query's surface: nothing to lift.
    const LeakTest t = MakeLeakTest({0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {0, 0, 1}, 1e-6);
    EXPECT_EQ(t.outcome, LeakTest::Outcome::kVisible);
}

TEST(LeakTest, RecordOnASideWallCannotBeReached) {
    // A record level with the query on a wall facing sideways: lifting it
    // along its normal never raises the ray off the query's surface.
    const LeakTest t = MakeLeakTest({0, 0, 0}, {0, 0, 1}, {2, 0, 0}, {0, 1, 0}, 1e-6);
    EXPECT_EQ(t.outcome, LeakTest::Outcome::kHidden);
}

/// A complete hemisphere whose horizon row hit something at `distance` in
/// column `wall` only (the others see nothing), framed by u = +x.
Hemisphere HorizonWall(int columns, int wall, double distance) {
    Hemisphere h;
    h.complete = true;
    h.frame = Frame{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    h.horizonInverseDistance.assign(static_cast<size_t>(columns), 0.0);
    h.horizonInverseDistance[static_cast<size_t>(wall)] = 1 / distance;
    return h;
}

TEST(Corral, BitsWhereAWallStandsInsideTheValidityRadius) {
    // 32 columns: column 4 spans azimuths [π/4, 5π/16), that is sector 4.
    const std::uint32_t bits = CorralBits(HorizonWall(32, 4, 0.5), 1.0);
    EXPECT_EQ(bits, 1u << 4);
    // 8 columns: column 1 spans [π/4, π/2), sectors 4 to 7.
    EXPECT_EQ(CorralBits(HorizonWall(8, 1, 0.5), 1.0), 0xF0u);
    // Beyond the validity radius a wall sets nothing; one touching the record
    // (closer than minarad·a, which Radiance 5 skips) does.
    EXPECT_EQ(CorralBits(HorizonWall(32, 4, 2.0), 1.0), 0u);
    EXPECT_EQ(CorralBits(HorizonWall(32, 4, 0.005), 1.0), 1u << 4);
    // Incomplete: none.
    Hemisphere partial = HorizonWall(32, 4, 0.5);
    partial.complete = false;
    EXPECT_EQ(CorralBits(partial, 1.0), 0u);
}

/// A complete 8 × 8 Radiance 5 hemisphere around +z (u = +x) that sees
/// nothing (every cell a miss straight up), to be given occluders by hand.
HessianHemisphere OpenHessianHemisphere() {
    HessianHemisphere h;
    h.complete = true;
    h.ns = 8;
    h.frame = Frame{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    h.cells.assign(64, HessianCell{});
    for (HessianCell& c : h.cells) {
        c.offset = {0, 0, 1000};
        c.inverseDistance = 1e-10;
        c.samples = 1;
    }
    return h;
}

/// Puts an occluder in cell (i, j) at `distance`, azimuth `phi` from u, 10°
/// above the horizon.
void Occlude(HessianHemisphere& h, int i, int j, double phi, double distance) {
    const double e = 10 * kPi / 180;
    HessianCell& c = h.cells[static_cast<std::size_t>(i * h.ns + j)];
    c.offset = Vec3(std::cos(phi) * std::cos(e), std::sin(phi) * std::cos(e), std::sin(e)) *
               distance;
    c.inverseDistance = 1 / distance;
}

// Radiance 5's corral (ambcorral): a perimeter cell whose hit lies inside the
// validity ellipse flags the sectors within π/(2ns) = π/16 of its azimuth.
TEST(Corral, HessianPerimeterCellsInsideTheEllipse) {
    const Vec3 u(1, 0, 0);
    HessianHemisphere h = OpenHessianHemisphere();
    EXPECT_EQ(CorralBits(h, u, 1, 1), 0u);
    // Azimuth 0.3 ± π/16 = [0.104, 0.496]: sectors 0 to 2.
    Occlude(h, 0, 3, 0.3, 0.5);
    EXPECT_EQ(CorralBits(h, u, 1, 1), 0x7u);
    // Azimuth -0.05 ± π/16 wraps: sectors 30, 31 and 0.
    h = OpenHessianHemisphere();
    Occlude(h, 7, 0, -0.05, 0.5);
    EXPECT_EQ(CorralBits(h, u, 1, 1), 0xC0000001u);
    // The ellipse, not a circle: at 0.5 along v it is inside semi-axes
    // (0.4 along u, 1 along v), at 0.5 along u outside.
    h = OpenHessianHemisphere();
    Occlude(h, 0, 0, 0.5 * kPi, 0.5);
    EXPECT_NE(CorralBits(h, u, 0.4, 1), 0u);
    h = OpenHessianHemisphere();
    Occlude(h, 0, 0, 0.0, 0.5);
    EXPECT_EQ(CorralBits(h, u, 0.4, 1), 0u);
    // The frame is the record's u, not the hemisphere's.
    EXPECT_NE(CorralBits(h, Vec3(0, 1, 0), 0.4, 1), 0u);
}

TEST(Corral, HessianOnlyPerimeterCellsEvenUnderALowCeiling) {
    const Vec3 u(1, 0, 0);
    // An occluder seen by an inner cell: not the perimeter, no bits.
    HessianHemisphere h = OpenHessianHemisphere();
    Occlude(h, 1, 1, 0.3, 0.5);
    EXPECT_EQ(CorralBits(h, u, 1, 1), 0u);
    // Central cells (2 <= i, j < 6 of 8) at 1/d = 2: Radiance 5 would call
    // that a ceiling too low for a corral (mean 1/d × R0 = 2 >= 1), but a
    // radius clamped up by -ar reaches past such a ceiling: the bits stay.
    h = OpenHessianHemisphere();
    Occlude(h, 0, 3, 0.5 * kPi, 0.5);  // along v: inside (1, 1) and (0.4, 1)
    const std::uint32_t open = CorralBits(h, u, 1, 1);
    EXPECT_NE(open, 0u);
    for (int i = 2; i < 6; ++i) {
        for (int j = 2; j < 6; ++j)
            Occlude(h, i, j, 1.0, 0.5);
    }
    EXPECT_EQ(CorralBits(h, u, 1, 1), open);
    EXPECT_NE(CorralBits(h, u, 0.4, 1), 0u);
    // Fewer than 8 cells per axis, or incomplete: none.
    h = OpenHessianHemisphere();
    Occlude(h, 0, 3, 0.3, 0.5);
    HessianHemisphere partial = h;
    partial.complete = false;
    EXPECT_EQ(CorralBits(partial, u, 1, 1), 0u);
    HessianHemisphere seven = OpenHessianHemisphere();
    seven.ns = 7;
    seven.cells.resize(49);
    Occlude(seven, 0, 3, 0.3, 0.5);
    EXPECT_EQ(CorralBits(seven, u, 1, 1), 0u);
}

// As for classic hemispheres, an occluder nearer than 1/maxInverseDistance
// (Radiance's minarad·a + 0.001, which Radiance 5 skips) still flags.
TEST(Corral, HessianNearOccludersFlagToo) {
    HessianHemisphere h = OpenHessianHemisphere();
    Occlude(h, 0, 3, 0.3, 0.005);
    EXPECT_EQ(CorralBits(h, Vec3(1, 0, 0), 1, 1), 0x7u);
}

TEST(Corral, CoversTheQueryDirection) {
    AmbientRecord r;
    r.position = {0, 0, 0};
    r.normal = {0, 0, 1};
    r.uAxis = {1, 0, 0};
    r.corral = 1u << 4;  // azimuths [π/4, 5π/16)
    EXPECT_TRUE(CorralCovers(r, {std::cos(0.27 * kPi), std::sin(0.27 * kPi), 0}));
    EXPECT_FALSE(CorralCovers(r, {1, 0, 0}));
    EXPECT_FALSE(CorralCovers(r, {-1, 0, 0}));
    r.corral = 1u << 31;  // just below 2π
    EXPECT_TRUE(CorralCovers(r, {1, -0.01, 0}));
    r.corral = 0;
    EXPECT_FALSE(CorralCovers(r, {1, -0.01, 0}));
}

}  // namespace
}  // namespace rt
