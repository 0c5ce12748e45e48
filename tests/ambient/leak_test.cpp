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
    h.zenithInverseDistance = 0.1;  // a ceiling 10 away
    return h;
}

TEST(Corral, BitsWhereAWallStandsInsideTheValidityRadius) {
    // 32 columns: column 4 spans azimuths [π/4, 5π/16), that is sector 4.
    const std::uint32_t bits = CorralBits(HorizonWall(32, 4, 0.5), 1.0, 100);
    EXPECT_EQ(bits, 1u << 4);
    // 8 columns: column 1 spans [π/4, π/2), sectors 4 to 7.
    EXPECT_EQ(CorralBits(HorizonWall(8, 1, 0.5), 1.0, 100), 0xF0u);
    // Beyond the validity radius a wall sets nothing; one touching the record
    // (closer than 1/maxInverseDistance, which Radiance 5 skips) does.
    EXPECT_EQ(CorralBits(HorizonWall(32, 4, 2.0), 1.0, 100), 0u);
    EXPECT_EQ(CorralBits(HorizonWall(32, 4, 0.005), 1.0, 100), 1u << 4);
    // A ceiling nearer than the validity radius: no corral at all.
    Hemisphere low = HorizonWall(32, 4, 0.5);
    low.zenithInverseDistance = 2;
    EXPECT_EQ(CorralBits(low, 1.0, 100), 0u);
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
