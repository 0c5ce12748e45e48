// SPDX-License-Identifier: MIT
//
// MakeClassicRecord (ambient/hemisphere.cpp): the classic record radius
// (harmonic mean distance, gradient limit, [minRadius, maxRadius] clamps,
// 1/sqrt(weight)), the gradient cap, the record frame, and failure cases.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>

#include "ambient/hemisphere.h"
#include "core/conventions.h"
#include "tests/ambient/hemisphere_test_scenes.h"

namespace rt {
namespace {

using testing::ConstantEnvironment;
using testing::FrameAround;
using testing::Options;

const Vec3 kNormal = Normalize(Vec3(-0.2, 0.4, 0.9));

AmbientLimits Limits(double minRadius, double maxRadius) {
    AmbientLimits l;
    l.minRadius = minRadius;
    l.maxRadius = maxRadius;
    return l;
}

/// A complete hemisphere with the given distance statistics and gradients,
/// built by hand to test the radius rules alone.
Hemisphere Synthetic(double inverseDistanceSum, int count, const Vec3& posGradient = Vec3(),
                     const Vec3& dirGradient = Vec3()) {
    Hemisphere h;
    h.complete = true;
    h.value = Rgb(0.2, 0.3, 0.4);
    h.rows = 3;
    h.columns = 9;
    h.raysTraced = 27;
    h.inverseDistanceSum = inverseDistanceSum;
    h.distanceCount = count;
    h.frame = FrameAround(kNormal);
    h.posGradient = posGradient;
    h.dirGradient = dirGradient;
    return h;
}

TEST(RecordMaker, FillsEveryField) {
    const Vec3 gPos = FrameAround(kNormal).u * 0.3 - FrameAround(kNormal).v * 0.2;
    const Vec3 gDir = FrameAround(kNormal).u * -0.1 + FrameAround(kNormal).v * 0.05;
    const Hemisphere h = Synthetic(27.0 / 2.0, 27, gPos, gDir);
    const auto rec = MakeClassicRecord(Vec3(1, 2, 3), kNormal, h, 2, 1.0, Limits(0.01, 10));
    ASSERT_TRUE(rec);
    EXPECT_EQ(rec->position, Vec3(1, 2, 3));
    EXPECT_EQ(rec->normal, kNormal);
    EXPECT_EQ(rec->uAxis, h.frame.u);
    EXPECT_EQ(rec->value, h.value);
    EXPECT_EQ(rec->level, 2);
    EXPECT_EQ(rec->weight, 1.0);
    EXPECT_EQ(rec->corral, 0u);
    // Harmonic mean 2, |g|·R = 0.72 < 1 so the gradient is kept as it is.
    EXPECT_DOUBLE_EQ(rec->radius[0], 2.0);
    EXPECT_EQ(rec->radius[0], rec->radius[1]);
    EXPECT_NEAR(rec->posGradient[0], 0.3, 1e-12);
    EXPECT_NEAR(rec->posGradient[1], -0.2, 1e-12);
    EXPECT_NEAR(rec->dirGradient[0], -0.1, 1e-12);
    EXPECT_NEAR(rec->dirGradient[1], 0.05, 1e-12);
    // The stored 2D gradients rebuild the 3D ones in the record's own frame.
    const Vec3 rebuilt = rec->uAxis * rec->posGradient[0] + rec->VAxis() * rec->posGradient[1];
    EXPECT_NEAR(Length(rebuilt - gPos), 0.0, 1e-12);
}

// A weak record's radius grows by 1/sqrt(weight); its gradient is then
// capped so that |g|·R <= 1 holds for the radius actually stored.
TEST(RecordMaker, CapsGradientForTheFinalRadius) {
    const Vec3 gPos = FrameAround(kNormal).u * 0.3 - FrameAround(kNormal).v * 0.2;
    const Hemisphere h = Synthetic(27.0 / 2.0, 27, gPos, Vec3());
    const auto rec = MakeClassicRecord(Vec3(1, 2, 3), kNormal, h, 2, 0.25, Limits(0.01, 10));
    ASSERT_TRUE(rec);
    EXPECT_DOUBLE_EQ(rec->radius[0], 4.0);  // 2 / sqrt(0.25)
    const double g = std::hypot(rec->posGradient[0], rec->posGradient[1]);
    EXPECT_NEAR(g * rec->radius[0], 1.0, 1e-12);
    // Direction kept.
    EXPECT_NEAR(rec->posGradient[0] / rec->posGradient[1], 0.3 / -0.2, 1e-12);
}

// Every direction hits a sphere of radius d around the point: the harmonic
// mean distance is d exactly.
TEST(RecordMaker, RadiusIsHarmonicMeanDistanceForConstantDistance) {
    for (double d : {0.05, 0.7, 3.0}) {
        Rng rng(4);
        const Hemisphere h = SampleHemisphere(kNormal, Options(1024, 512), rng,
                                              ConstantEnvironment(Rgb::Grey(1), d));
        const auto rec = MakeClassicRecord(Vec3(), kNormal, h, 0, 1.0, Limits(0.001, 100));
        ASSERT_TRUE(rec);
        EXPECT_NEAR(rec->radius[0], d, 1e-12 * d);
    }
}

// Under an infinite ceiling at height H, d = H/cosθ; for cosine-weighted
// directions E[1/d] = E[cosθ]/H = (2/3)/H, so R = 1.5·H (stratified estimate
// within 0.2%).
TEST(RecordMaker, RadiusUnderInfiniteCeilingIsOneAndAHalfHeights) {
    const double height = 0.8;
    const AmbientTraceFn trace = [&](const Vec3& d) {
        return std::optional<AmbientSample>(AmbientSample{Rgb::Grey(1), height / Dot(d, kNormal)});
    };
    for (std::uint64_t seed = 0; seed < 5; ++seed) {
        Rng rng(seed);
        const Hemisphere h = SampleHemisphere(kNormal, Options(1024, 512), rng, trace);
        const auto rec = MakeClassicRecord(Vec3(), kNormal, h, 0, 1.0, Limits(0.001, 100));
        ASSERT_TRUE(rec);
        EXPECT_NEAR(rec->radius[0], 1.5 * height, 0.002 * 1.5 * height);
    }
}

TEST(RecordMaker, RadiusIsClampedAfterDividingBySqrtWeight) {
    // Harmonic mean 2.
    EXPECT_DOUBLE_EQ(
        MakeClassicRecord(Vec3(), kNormal, Synthetic(5, 10), 0, 1, Limits(0.1, 3))->radius[0], 2.0);
    // To the maximum, before and after the weight.
    EXPECT_DOUBLE_EQ(
        MakeClassicRecord(Vec3(), kNormal, Synthetic(5, 10), 0, 1, Limits(0.1, 1.5))->radius[0],
        1.5);
    EXPECT_DOUBLE_EQ(
        MakeClassicRecord(Vec3(), kNormal, Synthetic(5, 10), 1, 0.25, Limits(0.1, 3))->radius[0],
        3.0);
    EXPECT_DOUBLE_EQ(
        MakeClassicRecord(Vec3(), kNormal, Synthetic(5, 10), 1, 0.64, Limits(0.1, 3))->radius[0],
        2.5);
    // To the minimum (R = 0.02 < 0.1), then / sqrt(weight).
    EXPECT_DOUBLE_EQ(
        MakeClassicRecord(Vec3(), kNormal, Synthetic(500, 10), 0, 1, Limits(0.1, 3))->radius[0],
        0.1);
    EXPECT_DOUBLE_EQ(
        MakeClassicRecord(Vec3(), kNormal, Synthetic(500, 10), 2, 0.25, Limits(0.1, 3))->radius[0],
        0.2);
    // A weight above 1 cannot take the radius under the minimum.
    EXPECT_DOUBLE_EQ(
        MakeClassicRecord(Vec3(), kNormal, Synthetic(500, 10), 0, 4, Limits(0.1, 3))->radius[0],
        0.1);
}

TEST(RecordMaker, NothingNearbyGivesMaximumRadius) {
    // Radiance's FTINY rule: Σ 1/d <= 1e-6 (all misses at FHUGE) means max radius.
    EXPECT_DOUBLE_EQ(
        MakeClassicRecord(Vec3(), kNormal, Synthetic(27 / kFhuge, 27), 0, 1, Limits(0.1, 3))
            ->radius[0],
        3.0);
    EXPECT_DOUBLE_EQ(
        MakeClassicRecord(Vec3(), kNormal, Synthetic(0, 27), 0, 1, Limits(0.1, 3))->radius[0], 3.0);
}

TEST(RecordMaker, LargeGradientLimitsRadius) {
    const Vec3 u = FrameAround(kNormal).u;
    // Harmonic mean 2, |g| = 2: |g|²R² = 16 > 1 so R = 1/|g| = 0.5; g unchanged.
    const auto rec =
        MakeClassicRecord(Vec3(), kNormal, Synthetic(5, 10, u * 2.0), 0, 1, Limits(0.1, 3));
    ASSERT_TRUE(rec);
    EXPECT_DOUBLE_EQ(rec->radius[0], 0.5);
    EXPECT_NEAR(rec->posGradient[0], 2.0, 1e-12);
    EXPECT_NEAR(rec->radius[0] * std::hypot(rec->posGradient[0], rec->posGradient[1]), 1.0, 1e-12);
}

TEST(RecordMaker, GradientIsCappedAtMinimumRadius) {
    const Frame f = FrameAround(kNormal);
    const Vec3 g = f.u * 30.0 + f.v * 40.0;  // |g| = 50: 1/|g| = 0.02 < minRadius 0.1
    const auto rec = MakeClassicRecord(Vec3(), kNormal, Synthetic(5, 10, g), 0, 1, Limits(0.1, 3));
    ASSERT_TRUE(rec);
    EXPECT_DOUBLE_EQ(rec->radius[0], 0.1);
    // Scaled to |g| = 1/R = 10, same direction.
    EXPECT_NEAR(rec->posGradient[0], 6.0, 1e-12);
    EXPECT_NEAR(rec->posGradient[1], 8.0, 1e-12);
    // The rotational gradient is not capped.
    const auto rec2 =
        MakeClassicRecord(Vec3(), kNormal, Synthetic(5, 10, g, f.v * 70.0), 0, 1, Limits(0.1, 3));
    EXPECT_NEAR(rec2->dirGradient[1], 70.0, 1e-12);
}

TEST(RecordMaker, IncompleteHemisphereGivesNothing) {
    Hemisphere h = Synthetic(5, 10);
    h.complete = false;
    EXPECT_FALSE(MakeClassicRecord(Vec3(), kNormal, h, 0, 1, Limits(0.1, 3)));

    int calls = 0;
    const AmbientTraceFn trace = [&](const Vec3&) -> std::optional<AmbientSample> {
        if (++calls == 3)
            return std::nullopt;
        return AmbientSample{Rgb::Grey(1), 1.0};
    };
    Rng rng(1);
    EXPECT_FALSE(MakeClassicRecord(Vec3(), kNormal,
                                   SampleHemisphere(kNormal, Options(256, 0), rng, trace), 0, 1,
                                   Limits(0.1, 3)));
}

TEST(RecordMaker, BadWeightOrLimitsGiveNothing) {
    EXPECT_FALSE(MakeClassicRecord(Vec3(), kNormal, Synthetic(5, 10), 0, 0, Limits(0.1, 3)));
    EXPECT_FALSE(MakeClassicRecord(Vec3(), kNormal, Synthetic(5, 10), 0, -1, Limits(0.1, 3)));
    EXPECT_FALSE(MakeClassicRecord(Vec3(), kNormal, Synthetic(5, 10), 0,
                                   std::numeric_limits<double>::quiet_NaN(), Limits(0.1, 3)));
    EXPECT_FALSE(MakeClassicRecord(Vec3(), kNormal, Synthetic(5, 10), 0, 1, AmbientLimits{}));
}

bool AllFinite(const AmbientRecord& r) {
    return IsFinite(r.value) && std::isfinite(r.radius[0]) && std::isfinite(r.radius[1]) &&
           std::isfinite(r.posGradient[0]) && std::isfinite(r.posGradient[1]) &&
           std::isfinite(r.dirGradient[0]) && std::isfinite(r.dirGradient[1]) && r.radius[0] > 0;
}

TEST(RecordMaker, AllMissOrBlackEnvironmentsGiveFiniteRecords) {
    const AmbientLimits limits = AmbientLimits::FromResolution(256, 4.0);
    const double inf = std::numeric_limits<double>::infinity();
    const double huge = std::numeric_limits<double>::max();
    for (double distance : {kFhuge, huge, inf}) {
        for (const Rgb& radiance : {Rgb(), Rgb::Grey(1e-300), Rgb(0.5, 0.5, 0.5)}) {
            Rng rng(8);
            const Hemisphere h = SampleHemisphere(kNormal, Options(1024, 512), rng,
                                                  ConstantEnvironment(radiance, distance));
            const auto rec = MakeClassicRecord(Vec3(1, 1, 1), kNormal, h, 0, 1, limits);
            ASSERT_TRUE(rec);
            EXPECT_TRUE(AllFinite(*rec)) << *rec;
            EXPECT_DOUBLE_EQ(rec->radius[0], limits.maxRadius);
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(rec->value[c], radiance[c], 1e-12 * radiance[c]);
        }
    }
    // Black but with something nearby: radius from the distances, zero gradients.
    Rng rng(9);
    const Hemisphere h =
        SampleHemisphere(kNormal, Options(1024, 512), rng, ConstantEnvironment(Rgb(), 0.2));
    const auto rec = MakeClassicRecord(Vec3(), kNormal, h, 0, 1, limits);
    ASSERT_TRUE(rec);
    EXPECT_TRUE(AllFinite(*rec));
    EXPECT_NEAR(rec->radius[0], 0.2, 1e-12);
    EXPECT_EQ(rec->posGradient[0], 0.0);
    EXPECT_EQ(rec->dirGradient[1], 0.0);
}

TEST(RecordMaker, NonFiniteGradientsAreDropped) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const auto rec = MakeClassicRecord(
        Vec3(), kNormal, Synthetic(5, 10, Vec3(nan, 0, 0), Vec3(0, nan, 0)), 0, 1, Limits(0.1, 3));
    ASSERT_TRUE(rec);
    EXPECT_TRUE(AllFinite(*rec));
    EXPECT_DOUBLE_EQ(rec->radius[0], 2.0);
}

}  // namespace
}  // namespace rt
