// The irradiance cache's acceptance and interpolation rules (Ward's
// split-sphere weights, Ward & Heckbert gradients, Radiance's behind and
// level tests) on hand-made records, and -ar/-aw helpers.
#include "ambient/cache.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

namespace rt {
namespace {

AmbientRecord FloorRecord(Vec3 pos, double value, double radius) {
    AmbientRecord r;
    r.position = pos;
    r.normal = Vec3(0, 0, 1);
    r.uAxis = Vec3(1, 0, 0);
    r.value = Rgb::Grey(value);
    r.radius[0] = r.radius[1] = radius;
    r.level = 0;
    r.weight = 1;
    return r;
}

AmbientQuery FloorQuery(Vec3 p, int level = 0, double weight = 1) {
    AmbientQuery q;
    q.point = p;
    q.normal = q.shadingNormal = Vec3(0, 0, 1);
    q.level = level;
    q.rayWeight = weight;
    return q;
}

AmbientCache MakeCache(double accuracy = 0.1) {
    return AmbientCache(Vec3(-10, -10, -10), 20, accuracy, AmbientLimits{0.01, 5});
}

TEST(AmbientCache, AcceptsWithinAccuracyTimesRadius) {
    AmbientCache cache = MakeCache();
    ASSERT_TRUE(cache.Add(FloorRecord({0, 0, 0}, 0.5, 1)));
    auto near = cache.Interpolate(FloorQuery({0.05, 0, 0}));
    ASSERT_TRUE(near);
    EXPECT_DOUBLE_EQ(near->g, 0.5);
    EXPECT_FALSE(cache.Interpolate(FloorQuery({0.1, 0, 0})));  // ε = a: weight 1/a not > 1/a
    EXPECT_FALSE(cache.Interpolate(FloorQuery({0, 0.2, 0})));
}

TEST(AmbientCache, WeightsAreInverseSplitSphereError) {
    AmbientCache cache = MakeCache(0.2);
    cache.Add(FloorRecord({0, 0, 0}, 0.5, 0.8));
    cache.Add(FloorRecord({0.1, 0, 0}, 0.3, 0.8));
    // Query at x = 0.02: ε = 0.025 and 0.1, weights 40 and 10.
    auto v = cache.Interpolate(FloorQuery({0.02, 0, 0}));
    ASSERT_TRUE(v);
    EXPECT_NEAR(v->g, (40 * 0.5 + 10 * 0.3) / 50, 1e-12);
}

/// The candidates are gathered (and prefetched) before they are weighed: with
/// more than fit the inline buffer (32), every one still counts, in order.
TEST(AmbientCache, EveryOverlappingRecordCountsHoweverMany) {
    for (const int n : {1, 31, 32, 33, 100}) {
        AmbientCache cache = MakeCache();
        double sum = 0;
        for (int k = 0; k < n; ++k) {
            const double value = 0.1 + 0.01 * k;
            ASSERT_TRUE(cache.Add(FloorRecord({0, 0, 0}, value, 1)));
            sum += value;
        }
        int used = 0;
        const auto v = cache.Interpolate(FloorQuery({0.02, 0, 0}), &used);
        ASSERT_TRUE(v);
        EXPECT_EQ(used, n);
        EXPECT_NEAR(v->g, sum / n, 1e-12) << n;  // equal weights: the mean
    }
}

/// Radiance 5's weights (RecordWeighting::Hat): (1 − δ/θmax)(1 − ε/a), with
/// ε the elliptical distance alone and δ the chord between the normals.
TEST(AmbientCache, HatWeightsAsRadiance5) {
    AmbientCache cache(Vec3(-10, -10, -10), 20, 0.2, AmbientLimits{0.01, 5}, RecordWeighting::Hat);
    cache.Add(FloorRecord({0, 0, 0}, 0.5, 0.8));
    cache.Add(FloorRecord({0.1, 0, 0}, 0.3, 0.8));
    // Query at x = 0.02: ε = 0.025 and 0.1, weights 1 − 0.025/0.2 and 1 − 0.1/0.2.
    auto v = cache.Interpolate(FloorQuery({0.02, 0, 0}));
    ASSERT_TRUE(v);
    const double w0 = 1 - 0.025 / 0.2, w1 = 1 - 0.1 / 0.2;
    EXPECT_NEAR(v->g, (w0 * 0.5 + w1 * 0.3) / (w0 + w1), 1e-12);
    // Normals 15° apart: accepted under θmax = 10° + 0.2 rad = 21.5°, with the
    // hat's angular factor; at 25° rejected. (Split-sphere weights would
    // reject 15° at this accuracy: sqrt(1 − cos 15°) = 0.18, plus distance.)
    for (const double degrees : {15.0, 25.0}) {
        AmbientCache c(Vec3(-10, -10, -10), 20, 0.2, AmbientLimits{0.01, 5}, RecordWeighting::Hat);
        AmbientRecord r = FloorRecord({0, 0, 0}, 0.5, 0.8);
        const double t = degrees * kPi / 180;
        r.normal = Vec3(std::sin(t), 0, std::cos(t));
        r.uAxis = Vec3(std::cos(t), 0, -std::sin(t));
        c.Add(r);
        EXPECT_EQ(c.Interpolate(FloorQuery({0, 0, 0})).has_value(), degrees < 20) << degrees;
    }
    // Weak rays widen the angle: (θmax − π/2)·w^0.13 + π/2 is 52° at w = 0.01
    // and 27° at w = 0.5.
    {
        AmbientCache c(Vec3(-10, -10, -10), 20, 0.2, AmbientLimits{0.01, 5}, RecordWeighting::Hat);
        AmbientRecord r = FloorRecord({0, 0, 0}, 0.5, 0.8);  // weight 1: eligible for both
        const double t = 40 * kPi / 180;
        r.normal = Vec3(std::sin(t), 0, std::cos(t));
        r.uAxis = Vec3(std::cos(t), 0, -std::sin(t));
        c.Add(r);
        EXPECT_TRUE(c.Interpolate(FloorQuery({0, 0, 0}, 0, 0.01)));
        EXPECT_FALSE(c.Interpolate(FloorQuery({0, 0, 0}, 0, 0.5)));
    }
}

/// A unit normal whose dot product with itself rounds above 1 (the short
/// block's face in a frozen cornell octree had one) gave a negative chord,
/// a NaN hat weight, and a refused record: every query on that face made its
/// own (README, "Frozen octrees"). Both weightings must use such a record.
TEST(AmbientCache, NormalWithDotAboveOneIsStillAccepted) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-1, 1);
    Vec3 n;
    for (int k = 0; k < 100000; ++k) {
        n = Normalize(Vec3(u(rng), u(rng), u(rng)));
        if (Dot(n, n) > 1.0) break;
    }
    ASSERT_GT(Dot(n, n), 1.0) << "no normal with |n|² above 1 found";
    // Any unit vector perpendicular to n.
    const Vec3 axis = Normalize(std::abs(n.x) < 0.9 ? Cross(n, Vec3(1, 0, 0)) : Cross(n, Vec3(0, 1, 0)));
    for (const RecordWeighting weighting : {RecordWeighting::Hat, RecordWeighting::SplitSphere}) {
        AmbientCache c(Vec3(-10, -10, -10), 20, 0.2, AmbientLimits{0.01, 5}, weighting);
        AmbientRecord r = FloorRecord({0, 0, 0}, 0.5, 0.8);
        r.normal = n;
        r.uAxis = axis;
        ASSERT_TRUE(c.Add(r));
        AmbientQuery q = FloorQuery(axis * 0.02);
        q.normal = q.shadingNormal = n;
        int used = 0;
        const auto v = c.Interpolate(q, &used);
        ASSERT_TRUE(v) << static_cast<int>(weighting);
        EXPECT_EQ(used, 1);
        EXPECT_DOUBLE_EQ(v->g, 0.5);
    }
}

/// -ahm: the first level's records are weighed by split spheres, the deeper
/// levels' by Radiance 5's hat. A record 15° off the query's normal passes
/// the hat's 21.5° limit but not the split sphere's error bound (0.18 > 0.2
/// less the distance term), so only the level-1 copy is accepted.
TEST(AmbientCache, EachLevelIsWeighedByItsOwnRule) {
    AmbientCache c(Vec3(-10, -10, -10), 20, 0.2, AmbientLimits{0.01, 5},
                   RecordWeighting::SplitSphere, RecordWeighting::Hat);
    const double t = 15 * kPi / 180;
    for (const int level : {0, 1}) {
        AmbientRecord r = FloorRecord({0, 0, 0}, 0.5, 0.8);
        r.normal = Vec3(std::sin(t), 0, std::cos(t));
        r.uAxis = Vec3(std::cos(t), 0, -std::sin(t));
        r.level = level;
        c.Add(r);
    }
    // 0.02 along x, in front of the tilted record: distance term 0.025.
    EXPECT_FALSE(c.Interpolate(FloorQuery({0.02, 0, 0}, 0)).has_value());
    EXPECT_TRUE(c.Interpolate(FloorQuery({0.02, 0, 0}, 1)).has_value());
}

TEST(AmbientCache, NormalDivergenceCountsInTheError) {
    AmbientCache cache = MakeCache(0.1);
    cache.Add(FloorRecord({0, 0, 0}, 0.5, 1));
    AmbientQuery q = FloorQuery({0, 0, 0});
    // 1 - cos θ = 0.0025 gives sqrt = 0.05 < a: accepted.
    double c = 1 - 0.0025;
    q.normal = q.shadingNormal = Vec3(std::sqrt(1 - c * c), 0, c);
    EXPECT_TRUE(cache.Interpolate(q));
    // 30 degrees: sqrt(1 - cos 30°) = 0.37 > a.
    q.normal = q.shadingNormal = Vec3(0.5, 0, std::sqrt(0.75));
    EXPECT_FALSE(cache.Interpolate(q));
    q.normal = q.shadingNormal = Vec3(0, 0, -1);
    EXPECT_FALSE(cache.Interpolate(q));
}

TEST(AmbientCache, RecordsInFrontOfTheQueryAreRejected) {
    AmbientCache cache = MakeCache(0.5);
    cache.Add(FloorRecord({0, 0, 0.1}, 0.5, 1));  // a shelf 0.1 above the query
    // Query lies 0.1 behind the record's plane: more than minRadius·a + 0.001.
    EXPECT_FALSE(cache.Interpolate(FloorQuery({0, 0, 0})));
    // The other way round (record below the query) is fine.
    AmbientCache other = MakeCache(0.5);
    other.Add(FloorRecord({0, 0, 0}, 0.5, 1));
    EXPECT_TRUE(other.Interpolate(FloorQuery({0, 0, 0.1})));
}

TEST(AmbientCache, LevelAndWeightDecideEligibility) {
    AmbientCache cache = MakeCache();
    AmbientRecord deep = FloorRecord({0, 0, 0}, 0.5, 1);
    deep.level = 1;
    deep.weight = 0.5;
    cache.Add(deep);
    EXPECT_FALSE(cache.Interpolate(FloorQuery({0, 0, 0}, 0, 1)));   // deeper record
    EXPECT_TRUE(cache.Interpolate(FloorQuery({0, 0, 0}, 1, 0.5)));  // same level, same weight
    EXPECT_FALSE(cache.Interpolate(FloorQuery({0, 0, 0}, 1, 0.6)));  // weight < 0.9 · 0.6
    // A shallower record holds a different number of bounces: not used either.
    EXPECT_FALSE(cache.Interpolate(FloorQuery({0, 0, 0}, 2, 0.25)));
    // Levels far beyond the deepest record, and nonsense levels, find nothing.
    EXPECT_FALSE(cache.Interpolate(FloorQuery({0, 0, 0}, 40, 0.5)));
    EXPECT_FALSE(cache.Interpolate(FloorQuery({0, 0, 0}, -1, 0.5)));
    AmbientRecord bad = deep;
    bad.level = -1;
    EXPECT_FALSE(cache.Add(bad));
    // Each depth keeps its own records: a level-5 record beside the level-1 one.
    AmbientRecord deeper = deep;
    deeper.level = 5;
    deeper.value = Rgb::Grey(3);
    EXPECT_TRUE(cache.Add(deeper));
    EXPECT_EQ(cache.Interpolate(FloorQuery({0, 0, 0}, 5, 0.5))->g, 3.0);
    EXPECT_EQ(cache.Interpolate(FloorQuery({0, 0, 0}, 1, 0.5))->g, deep.value.g);
}

TEST(AmbientCache, GradientsExtrapolateToFirstOrder) {
    AmbientCache cache = MakeCache(0.2);
    AmbientRecord r = FloorRecord({0, 0, 0}, 0.5, 1);
    r.posGradient[0] = 0.4;   // +40 % per unit length along x
    r.dirGradient[1] = -0.2;  // per radian of rotation about v = y
    cache.Add(r);
    auto v = cache.Interpolate(FloorQuery({0.1, 0, 0}));
    ASSERT_TRUE(v);
    EXPECT_NEAR(v->g, 0.5 * (1 + 0.04), 1e-12);
    // Tilt the shading normal by 0.05 rad toward +x: Ni × N' = (0, 0.05, 0)·…
    AmbientQuery q = FloorQuery({0, 0, 0});
    q.shadingNormal = Normalize(Vec3(std::sin(0.05), 0, std::cos(0.05)));
    v = cache.Interpolate(q);
    ASSERT_TRUE(v);
    EXPECT_NEAR(v->g, 0.5 * (1 - 0.2 * std::sin(0.05)), 1e-12);
}

TEST(AmbientCache, NeverNegativeEvenWithSteepGradients) {
    AmbientCache cache = MakeCache(0.3);
    AmbientRecord r = FloorRecord({0, 0, 0}, 0.5, 1);
    r.posGradient[0] = -50;
    cache.Add(r);
    cache.Add(FloorRecord({0.3, 0, 0}, 0.2, 1));
    auto v = cache.Interpolate(FloorQuery({0.2, 0, 0}));
    ASSERT_TRUE(v);  // the steep record is left out, the other one answers
    EXPECT_DOUBLE_EQ(v->g, 0.2);
}

TEST(AmbientCache, AnisotropicRecordsUseTheirEllipse) {
    AmbientCache cache = MakeCache(0.1);
    AmbientRecord r = FloorRecord({0, 0, 0}, 0.5, 0.5);
    r.radius[1] = 1.0;  // longer along v = y
    cache.Add(r);
    EXPECT_FALSE(cache.Interpolate(FloorQuery({0.06, 0, 0})));  // 0.06/0.5 = 0.12 > a
    EXPECT_TRUE(cache.Interpolate(FloorQuery({0, 0.06, 0})));   // 0.06/1.0 = 0.06 < a
}

TEST(AmbientCache, InvalidRecordsAreIgnored) {
    AmbientCache cache = MakeCache();
    AmbientRecord r = FloorRecord({0, 0, 0}, 0.5, 0);
    EXPECT_FALSE(cache.Add(r));
    r.radius[0] = r.radius[1] = 1;
    r.value = Rgb(std::nan(""), 0, 0);
    EXPECT_FALSE(cache.Add(r));
    EXPECT_EQ(cache.size(), 0u);
}

/// Records are stored in blocks; every one must come back, in insertion
/// order, however many blocks they fill.
TEST(AmbientCache, KeepsEveryRecordInOrderAcrossBlocks) {
    AmbientCache cache = MakeCache();
    constexpr int kCount = 1300;  // two and a half blocks
    for (int i = 0; i < kCount; ++i) {
        ASSERT_TRUE(cache.Add(FloorRecord({0.001 * i, 0, 0}, 0.5 + i, 0.5)));
    }
    const std::vector<AmbientRecord> all = cache.Records();
    ASSERT_EQ(all.size(), static_cast<size_t>(kCount));
    ASSERT_EQ(cache.size(), static_cast<size_t>(kCount));
    for (int i = 0; i < kCount; ++i) {
        EXPECT_EQ(all[i], FloorRecord({0.001 * i, 0, 0}, 0.5 + i, 0.5)) << i;
    }
}

/// The octree must find exactly the records a scan of all records finds.
TEST(AmbientCache, IndexAgreesWithExhaustiveScan) {
    std::mt19937 gen(7);
    std::uniform_real_distribution<double> u(-5, 5), rad(0.05, 2), val(0.1, 1);
    AmbientCache cache = MakeCache(0.2);
    std::vector<AmbientRecord> all;
    for (int i = 0; i < 2000; ++i) {
        AmbientRecord r = FloorRecord({u(gen), u(gen), 0}, val(gen), rad(gen));
        r.posGradient[0] = 0.1 * u(gen);
        all.push_back(r);
        cache.Add(r);
    }
    for (int i = 0; i < 40; ++i) {  // the exhaustive side is slow under sanitizers
        Vec3 p(u(gen), u(gen), 0);
        Rgb sum;
        double wsum = 0;
        for (const AmbientRecord& r : all) {
            // Same result through a one-record cache, record by record.
            AmbientCache one = MakeCache(0.2);
            one.Add(r);
            if (auto v = one.Interpolate(FloorQuery(p))) {
                double d = Length(p - r.position) / r.radius[0];
                double w = d > 1e-3 ? 1 / d : 1e3;
                sum += *v * w;
                wsum += w;
            }
        }
        auto got = cache.Interpolate(FloorQuery(p));
        ASSERT_EQ(got.has_value(), wsum > 1e-6) << p;
        if (got) {
            EXPECT_NEAR(got->g, sum.g / wsum, 1e-9);
        }
    }
}

TEST(AmbientLimits, FollowRadianceSetambres) {
    AmbientLimits l = AmbientLimits::FromResolution(256, 4.00002);
    EXPECT_NEAR(l.minRadius, 0.015625, 1e-6);
    EXPECT_NEAR(l.maxRadius, 0.800004, 1e-9);  // min(64·min, 0.2·size)
    AmbientLimits none = AmbientLimits::FromResolution(0, 10);
    EXPECT_DOUBLE_EQ(none.minRadius, 1e-5);
    EXPECT_DOUBLE_EQ(none.maxRadius, 2.0);
}

TEST(AmbientValueAverage, LogMeanWithAssumedReflectance) {
    EXPECT_EQ(AveragedAmbientValue(Rgb(1, 1, 1), 0, 10, 3), Rgb(1, 1, 1));
    EXPECT_EQ(AveragedAmbientValue(Rgb(1, 1, 1), 5, 0, 0), Rgb(1, 1, 1));
    // One record of brightness e (ln = 1), aw 1, av 1: exp((0 + 1 + ln .5)/2).
    Rgb v = AveragedAmbientValue(Rgb(1, 1, 1), 1, 1.0, 1);
    EXPECT_NEAR(v.g, std::exp((1 + std::log(0.5)) / 2), 1e-12);
    // Zero -av: grey from the records alone.
    EXPECT_NEAR(AveragedAmbientValue(Rgb(), 1, 1.0, 1).g, std::exp(1 + std::log(0.5)), 1e-12);
}

}  // namespace
}  // namespace rt
