// SPDX-License-Identifier: MIT
//
// The lookup-or-compute loop (IrradianceCache::Evaluate) against analytic
// environments, without a scene: what it returns, when it makes records and
// of which level and weight, the leak test's rays, the counters.
#include "ambient/irradiance_cache.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <optional>

#include "core/conventions.h"

namespace rt {
namespace {

constexpr double kAccuracy = 0.1;

std::shared_ptr<AmbientCache> Store() {
    // A 10-unit cube at -ar 32: radii between 0.3125 and 2.
    return std::make_shared<AmbientCache>(Vec3(-5, -5, -5), 10.0, kAccuracy,
                                          AmbientLimits::FromResolution(32, 10.0));
}

IrradianceSettings Settings() {
    IrradianceSettings s;
    s.accuracy = kAccuracy;
    s.divisions = 256;
    s.superSamples = 0;
    return s;
}

AmbientQuery At(const Vec3& point, const Vec3& normal = {0, 0, 1}) {
    AmbientQuery q;
    q.point = point;
    q.normal = q.shadingNormal = normal;
    q.rayWeight = 1;
    return q;
}

/// FunctionRef refers to callables, not plain functions: lambdas here.
const auto NeverOccluded = [](const Vec3&, const Vec3&, double) { return false; };

/// A uniform environment of radiance `L` at `distance` (a furnace).
struct Furnace {
    double L = 0.7;
    double distance = 3;
    int rays = 0;
    std::optional<AmbientSample> operator()(const Vec3&, const AmbientSampleShare&) {
        ++rays;
        return AmbientSample{Rgb::Grey(L), distance};
    }
};

/// Without a taker (no ambient file), new records go into the cache only.
TEST(IrradianceCache, NewRecordsAreQueuedOnlyWhenAsked) {
    for (const bool queue : {true, false}) {
        auto store = Store();
        const IrradianceCache cache(Settings(), store);
        IrradianceThread thread;
        thread.queueNewRecords = queue;
        IrradianceCounters counters;
        Rng rng(1);
        Furnace env;
        ASSERT_TRUE(
            cache.Evaluate(At({0, 0, 0}), 1.0, thread, counters, rng, env, NeverOccluded).value);
        EXPECT_EQ(store->size(), 1u);
        EXPECT_EQ(thread.newRecords.size(), queue ? 1u : 0u);
    }
}

TEST(IrradianceCache, FurnaceIsExactAndTheRecordIsReused) {
    const IrradianceCache cache(Settings(), Store());
    IrradianceThread thread;
    IrradianceCounters counters;
    Rng rng(1);
    Furnace env;
    const auto first = cache.Evaluate(At({0, 0, 0}), 1.0, thread, counters, rng, env, NeverOccluded);
    ASSERT_TRUE(first.value);
    EXPECT_EQ(first.source, IrradianceResult::Source::Computed);
    EXPECT_NEAR(first.value->g, env.L, 1e-12);  // Ē = L in a furnace
    ASSERT_EQ(thread.newRecords.size(), 1u);
    EXPECT_EQ(thread.newRecords[0].level, 0);
    EXPECT_EQ(thread.newRecords[0].weight, 1.0);
    EXPECT_GT(env.rays, 200);
    // Close by, the record answers without a ray.
    const int raysBefore = env.rays;
    const auto second =
        cache.Evaluate(At({0.01, 0, 0}), 1.0, thread, counters, rng, env, NeverOccluded);
    ASSERT_TRUE(second.value);
    EXPECT_EQ(second.source, IrradianceResult::Source::Extrapolated);
    EXPECT_NEAR(second.value->g, env.L, 1e-12);
    EXPECT_EQ(env.rays, raysBefore);
    EXPECT_EQ(counters.ambientLookups, 2u);
    EXPECT_EQ(counters.ambientHits, 1u);
    EXPECT_EQ(counters.hemispheres, 1u);
    ASSERT_EQ(counters.recordsPerLevel.size(), 1u);
    EXPECT_EQ(counters.recordsPerLevel[0], 1u);
    EXPECT_EQ(thread.depth, 0);
}

TEST(IrradianceCache, WithoutAStoreEveryPointSamplesItsOwnHemisphere) {
    const IrradianceCache cache(Settings(), nullptr);
    IrradianceThread thread;
    IrradianceCounters counters;
    Rng rng(2);
    Furnace env;
    int divisions = 0;
    const auto trace = [&](const Vec3& d, const AmbientSampleShare& share) {
        EXPECT_FALSE(share.caching);
        divisions = share.divisions;
        return env(d, share);
    };
    for (int i = 0; i < 2; ++i) {
        const auto r = cache.Evaluate(At({0, 0, 0}), 1.0, thread, counters, rng, trace,
                                      NeverOccluded);
        ASSERT_TRUE(r.value);
        EXPECT_EQ(r.source, IrradianceResult::Source::Computed);
        EXPECT_NEAR(r.value->g, env.L, 1e-12);
    }
    EXPECT_EQ(counters.hemispheres, 2u);
    EXPECT_EQ(counters.ambientLookups, 0u);
    EXPECT_TRUE(thread.newRecords.empty());
    // The hemisphere is sized so that its sample rays stay near -lw: at weight
    // 1 and intens 1, 0.8/(256·2e-3) = 1.56 > 1, so all of -ad 256: 9 rows ×
    // 28 columns.
    EXPECT_EQ(divisions, 9 * 28);
    // A dark coefficient (intens 0.01) shrinks it to weight 0.0156, about 4
    // divisions: one row of 3.
    cache.Evaluate(At({0, 0, 0}), 0.01, thread, counters, rng, trace, NeverOccluded);
    EXPECT_EQ(divisions, 1 * 3);
}

/// Radiance L(d) = a + b·(d·x) from every direction, at distance 3: the
/// cosine-weighted mean about unit n is Ē(n) = a + (2/3)·b·(n·x).
struct LinearSky {
    double a = 1, b = 0.5;
    std::optional<AmbientSample> operator()(const Vec3& d, const AmbientSampleShare&) const {
        return AmbientSample{Rgb::Grey(a + b * d.x), 3.0};
    }
};

/// A texture or a mesh's smooth normal turns the shading normal away from the
/// surface's, about which the hemisphere is sampled: the value is turned to
/// it by the hemisphere's rotational gradient, with and without the cache and
/// by either record method (Radiance's multambient() and extambient()). Here
/// by 0.1 radian toward +x, under a sky brighter on that side: Ē rises from
/// 1 to 1 + sin(0.1)/3 = 1.0333; the first-order turn gives 1.0333 too.
TEST(IrradianceCache, AHemisphereIsTurnedToTheShadingNormal) {
    const double theta = 0.1;
    const LinearSky sky;
    const double exact = sky.a + 2.0 / 3.0 * sky.b * std::sin(theta);
    for (const RecordMethod method : {RecordMethod::Classic, RecordMethod::Hessian}) {
        for (const bool cached : {true, false}) {
            IrradianceSettings settings = Settings();
            settings.method = method;
            settings.superSamples = 128;
            const IrradianceCache cache(settings, cached ? Store() : nullptr);
            IrradianceThread thread;
            IrradianceCounters counters;
            Rng rng(5);
            AmbientQuery q = At({0, 0, 0});
            q.shadingNormal = Vec3(std::sin(theta), 0, std::cos(theta));
            const auto r = cache.Evaluate(q, 1.0, thread, counters, rng, sky, NeverOccluded);
            ASSERT_TRUE(r.value);
            EXPECT_EQ(r.source, IrradianceResult::Source::Computed);
            // Sampling noise and the gradient estimate: 0.3 % of the 3.3 % turn.
            EXPECT_NEAR(r.value->g, exact, 3e-3)
                << (method == RecordMethod::Classic ? "classic" : "Hessian")
                << (cached ? ", new record" : ", -aa 0");
            // Unturned, the same hemisphere gives the surface normal's 1.
            Rng again(5);
            IrradianceThread fresh;
            const IrradianceCache same(settings, cached ? Store() : nullptr);
            const auto flat = same.Evaluate(At({0, 0, 0}), 1.0, fresh, counters, again, sky,
                                            NeverOccluded);
            EXPECT_NEAR(flat.value->g, sky.a, 3e-3);
        }
    }
}

TEST(IrradianceCache, SamplesOfAHemisphereQueryTheNextLevel) {
    const IrradianceCache cache(Settings(), Store());
    IrradianceThread thread;
    IrradianceCounters counters;
    Rng rng(3);
    Furnace inner;
    int nestedQueries = 0;
    // Each sample of the first hemisphere asks for the irradiance at its own
    // hit point, one level down, as a diffuse surface there would.
    const auto outer = [&](const Vec3& dir, const AmbientSampleShare& share)
        -> std::optional<AmbientSample> {
        EXPECT_TRUE(share.caching);
        EXPECT_EQ(thread.depth, 1);
        ++nestedQueries;
        AmbientQuery q = At(dir * 2.0, -dir);
        q.rayWeight = 0.5;
        const auto r = cache.Evaluate(q, 0.5, thread, counters, rng, inner, NeverOccluded);
        return AmbientSample{*r.value * 0.5, 2.0};
    };
    const auto r = cache.Evaluate(At({0, 0, 0}), 1.0, thread, counters, rng, outer, NeverOccluded);
    ASSERT_TRUE(r.value);
    EXPECT_NEAR(r.value->g, 0.5 * inner.L, 1e-12);
    EXPECT_GT(nestedQueries, 100);
    ASSERT_EQ(counters.recordsPerLevel.size(), 2u);
    EXPECT_EQ(counters.recordsPerLevel[0], 1u);
    EXPECT_GT(counters.recordsPerLevel[1], 1u);  // the level-1 records reuse each other
    EXPECT_LT(counters.recordsPerLevel[1], static_cast<std::uint64_t>(nestedQueries));
    for (const AmbientRecord& rec : thread.newRecords) {
        EXPECT_EQ(rec.weight, rec.level == 0 ? 1.0 : 0.5) << rec;
    }
    EXPECT_EQ(thread.depth, 0);
}

TEST(IrradianceCache, RecordWeightFollowsTheLevelAndWeakRays) {
    EXPECT_EQ(IrradianceCache::RecordWeight(0, 1.0), 1.0);
    EXPECT_EQ(IrradianceCache::RecordWeight(2, 0.25), 0.25);
    EXPECT_EQ(IrradianceCache::RecordWeight(2, 0.1), 0.25);   // not weak enough
    EXPECT_EQ(IrradianceCache::RecordWeight(2, 0.02), 0.025); // 1.25 × the ray's
    EXPECT_EQ(IrradianceCache::RecordWeight(1, 0.9), 0.9);    // never below the ray's
}

TEST(IrradianceCache, FailedHemisphereMakesNoRecordAndNoValue) {
    const IrradianceCache cache(Settings(), Store());
    IrradianceThread thread;
    IrradianceCounters counters;
    Rng rng(4);
    int calls = 0;
    // Every sample ray refused (as by -lr): every division fails.
    const auto refused = [&](const Vec3&, const AmbientSampleShare&) {
        ++calls;
        return std::optional<AmbientSample>();
    };
    const auto r = cache.Evaluate(At({0, 0, 0}), 1.0, thread, counters, rng, refused,
                                  NeverOccluded);
    EXPECT_FALSE(r.value);
    EXPECT_EQ(r.source, IrradianceResult::Source::Failed);
    EXPECT_GT(calls, 0);
    EXPECT_TRUE(thread.newRecords.empty());
    EXPECT_EQ(cache.store()->size(), 0u);
}

/// Hits nearer than the distance tolerance (1e-6) are samples like any other:
/// the ray core returns them only on a surface meeting the record's own at an
/// angle (a wall at a floor point's edge, RayCore::Intersect's `leaving`).
/// Refusing them failed the division and darkened such points; in the 0.999
/// furnace, a few records at cube edges carried that loss up 50 levels.
TEST(IrradianceCache, HitsNearerThanTheToleranceAreSamples) {
    for (const RecordMethod method : {RecordMethod::Classic, RecordMethod::Hessian}) {
        IrradianceSettings settings = Settings();
        settings.method = method;
        const IrradianceCache cache(settings, Store());
        IrradianceThread thread;
        IrradianceCounters counters;
        Rng rng(4);
        const auto touching = [&](const Vec3& dir, const AmbientSampleShare&) {
            return std::optional<AmbientSample>(
                AmbientSample{Rgb::Grey(1), dir.x > 0.5 ? 4e-7 : 1.0});
        };
        const auto r = cache.Evaluate(At({0, 0, 0}), 1.0, thread, counters, rng, touching,
                                      NeverOccluded);
        ASSERT_TRUE(r.value);
        EXPECT_NEAR(r.value->g, 1.0, 1e-12);
        EXPECT_EQ(thread.newRecords.size(), 1u);
    }
}

/// A floor at z = 0 under an open sky with a curb along x = 0.05, 0.01 high:
/// a record at the origin sees the curb only near its horizon, so its radius
/// stays large, and its corral bits mark the curb's side (+x).
const auto FloorAndWall = [](const Vec3& dir,
                             const AmbientSampleShare&) -> std::optional<AmbientSample> {
    if (dir.x > 0) {
        const double t = 0.05 / dir.x;
        if (t * dir.z < 0.01) return AmbientSample{Rgb::Grey(0.1), t};
    }
    return AmbientSample{Rgb::Grey(1.0), 100.0};
};

TEST(IrradianceCache, LeakTestRejectsRecordsBehindAWall) {
    const IrradianceCache cache(Settings(), Store());
    IrradianceThread thread;
    IrradianceCounters counters;
    Rng rng(5);
    const auto made =
        cache.Evaluate(At({0, 0, 0}), 1.0, thread, counters, rng, FloorAndWall, NeverOccluded);
    ASSERT_TRUE(made.value);
    ASSERT_EQ(thread.newRecords.size(), 1u);
    const AmbientRecord record = thread.newRecords[0];
    ASSERT_NE(record.corral, 0u) << record;
    ASSERT_GT(record.radius[0] * kAccuracy, 0.0) << record;
    // Queries beside the record, within its validity, in the middle of a
    // sector whose corral bit is set (toward the curb) and of one whose bit is
    // clear (away from it).
    const auto inSector = [&](bool set) {
        for (int k = 0; k < 32; ++k) {
            if (((record.corral >> k) & 1u) != (set ? 1u : 0u)) continue;
            const double angle = (k + 0.5) * kPi / 16;
            const Vec3 d = record.uAxis * std::cos(angle) + record.VAxis() * std::sin(angle);
            return record.position + d * (0.5 * record.radius[0] * kAccuracy);
        }
        ADD_FAILURE() << "no sector with bit " << set << ": " << record;
        return record.position;
    };
    // Toward the curb the leak ray is traced: clear, the record answers;
    // blocked, it is refused and a new hemisphere made.
    const Vec3 beside = inSector(true);
    int leakRays = 0;
    const auto clear = [&](const Vec3&, const Vec3&, double) {
        ++leakRays;
        return false;
    };
    IrradianceCounters c1;
    const auto seen = cache.Evaluate(At(beside), 1.0, thread, c1, rng, FloorAndWall, clear);
    EXPECT_EQ(seen.source, IrradianceResult::Source::Extrapolated);
    EXPECT_EQ(c1.leakRays, 1u);
    EXPECT_EQ(c1.hemispheres, 0u);
    IrradianceCounters c2;
    const auto blocked = cache.Evaluate(At(beside), 1.0, thread, c2, rng, FloorAndWall,
                                        [&](const Vec3&, const Vec3&, double) {
                                            ++leakRays;
                                            return true;
                                        });
    EXPECT_EQ(blocked.source, IrradianceResult::Source::Computed);
    EXPECT_EQ(c2.leakRays, 1u);
    EXPECT_EQ(c2.hemispheres, 1u);
    // Where no bit is set no ray is needed.
    IrradianceCounters c3;
    const int before = leakRays;
    const auto away = cache.Evaluate(At(inSector(false)), 1.0, thread, c3, rng, FloorAndWall, clear);
    EXPECT_NE(away.source, IrradianceResult::Source::Computed);
    EXPECT_EQ(c3.leakRays, 0u);
    EXPECT_EQ(leakRays, before);
}

/// A smooth environment, brighter toward the zenith: some contrast between
/// neighbouring cells, far less than -aa's 10 % relative error.
struct Smooth {
    int rays = 0;
    std::optional<AmbientSample> operator()(const Vec3& d, const AmbientSampleShare&) {
        ++rays;
        return AmbientSample{Rgb::Grey(1.0 + 0.2 * d.z), 3.0};
    }
};

/// Rays one new Hessian or classic record takes at `level` in Smooth, at
/// -ad 256 -as 128; `deeper` is the deeper levels' method (default: `method`).
int SmoothRecordRays(RecordMethod method, int level,
                     std::optional<RecordMethod> deeper = std::nullopt) {
    IrradianceSettings settings = Settings();
    settings.method = method;
    settings.deeperMethod = deeper;
    settings.superSamples = 128;
    const IrradianceCache cache(settings, Store());
    IrradianceThread thread;
    thread.depth = level;
    IrradianceCounters counters;
    Rng rng(9);
    Smooth env;
    AmbientQuery q = At({0, 0, 0});
    q.rayWeight = std::pow(0.5, level);
    EXPECT_TRUE(cache.Evaluate(q, 0.5, thread, counters, rng, env, NeverOccluded).value);
    return env.rays;
}

// Hessian records below the first level take extra samples only where their
// first pass is rough by -aa (SuperSamplesForContrast): none in a smooth
// environment. The first level, and the classic records at any level, keep
// Radiance's -as·weight.
TEST(IrradianceCache, DeeperHessianRecordsSuperSampleOnlyWhereRough) {
    // Level 0: ns = 16, 256 cells, 128 extra. Level 1 (weight 0.5; one
    // bounce, so no samples moved to the first level): ns = round(sqrt(128))
    // = 11, 121 cells, 64 extra.
    EXPECT_EQ(SmoothRecordRays(RecordMethod::Hessian, 0), 256 + 128);
    // Of the 64 extra, the share the contrast rule leaves is a fraction of
    // one, rounded at random: 0 or 1.
    const int level1 = SmoothRecordRays(RecordMethod::Hessian, 1);
    EXPECT_GE(level1, 121);
    EXPECT_LE(level1, 121 + 1);
    // Classic level 1: rows = round(sqrt(128/π)) = 6, 19 columns, 64 extra.
    EXPECT_EQ(SmoothRecordRays(RecordMethod::Classic, 1), 6 * 19 + 64);
}

// -ahm: the first level's records by the first method, deeper ones by the
// other; the ray counts tell the two samplers apart (classic level 0: 9 rows
// x 28 columns + 128; Hessian level 1: 121 cells and at most one extra).
TEST(IrradianceCache, EachLevelMakesRecordsByItsOwnMethod) {
    EXPECT_EQ(SmoothRecordRays(RecordMethod::Classic, 0, RecordMethod::Hessian), 9 * 28 + 128);
    const int level1 = SmoothRecordRays(RecordMethod::Classic, 1, RecordMethod::Hessian);
    EXPECT_GE(level1, 121);
    EXPECT_LE(level1, 121 + 1);
    EXPECT_EQ(SmoothRecordRays(RecordMethod::Hessian, 1, RecordMethod::Classic), 6 * 19 + 64);
    EXPECT_EQ(SmoothRecordRays(RecordMethod::Hessian, 0, RecordMethod::Classic), 256 + 128);
}

TEST(IrradianceCache, DeeperSampleFractionIsTheShareSquaredWithAFloor) {
    EXPECT_EQ(IrradianceCache::DeeperSampleFraction(1.0), 1.0);
    EXPECT_DOUBLE_EQ(IrradianceCache::DeeperSampleFraction(0.8), 0.64);
    EXPECT_DOUBLE_EQ(IrradianceCache::DeeperSampleFraction(0.6), 0.36);
    EXPECT_EQ(IrradianceCache::DeeperSampleFraction(0.3), IrradianceCache::kMinDeeperFraction);
    EXPECT_EQ(IrradianceCache::DeeperSampleFraction(0.0), IrradianceCache::kMinDeeperFraction);
    EXPECT_EQ(IrradianceCache::DeeperSampleFraction(std::nan("")), 1.0);
}

/// Rays one new record takes at ambient level `level`, in a furnace, when the
/// point's other light is `other` (negative: no OtherRadianceRef) and the
/// thread has made `made` records of that level with mean Ē `typical`.
struct DeeperRecord {
    int rays = 0;
    double value = 0;
    bool otherAsked = false;
};
///
/// With two bounces and `firstLevel` first-level records made before
/// (default none: the first level's hemisphere in progress counts as one, so
/// that `made` >= 32 deeper records give it the whole boost and unlit deeper
/// records kDeeperScale).
DeeperRecord MakeDeeperRecord(int level, double other, int made, double typical,
                              int firstLevel = 0) {
    IrradianceSettings settings = Settings();
    settings.bounces = 2;
    const IrradianceCache cache(settings, Store());
    IrradianceThread thread;
    thread.depth = level;
    thread.madeBright.assign(static_cast<size_t>(level) + 1, {0.0, 0});
    thread.madeBright[0] = {typical * firstLevel, firstLevel};
    thread.madeBright[static_cast<size_t>(level)] = {typical * made, made};
    IrradianceCounters counters;
    Rng rng(5);
    Furnace env;
    DeeperRecord out;
    const auto otherRadiance = [&]() {
        out.otherAsked = true;
        return other;
    };
    const OtherRadianceRef ref(otherRadiance);
    AmbientQuery q = At({0, 0, 0});
    q.rayWeight = std::pow(0.5, level);
    // Coefficient 0.5: the ambient term's guess is 0.5 · typical.
    const auto r = cache.Evaluate(q, 0.5, thread, counters, rng, env, NeverOccluded,
                                  other >= 0 ? &ref : nullptr);
    EXPECT_TRUE(r.value);
    out.rays = env.rays;
    out.value = r.value ? r.value->g : 0;
    EXPECT_EQ(counters.recordsPerLevel.size(), static_cast<size_t>(level) + 1);
    return out;
}

TEST(IrradianceCache, DeeperRecordsTakeFewerRaysWhereOtherLightDominates) {
    const double typical = 0.7;   // the ambient term's guess: 0.5 · 0.7 = 0.35
    const DeeperRecord full = MakeDeeperRecord(1, -1, 100, typical);
    const DeeperRecord dark = MakeDeeperRecord(1, 0.0, 100, typical);  // no other light
    const DeeperRecord even = MakeDeeperRecord(1, 0.0875, 100, typical);  // share 0.8
    const DeeperRecord lit = MakeDeeperRecord(1, 35.0, 100, typical);   // share 1/101
    EXPECT_EQ(dark.rays, full.rays);
    EXPECT_TRUE(even.otherAsked);
    // Classic divisions: rows = round(sqrt(256 · 0.5 · f / π)), columns =
    // round(π · rows), f the share's fraction times kDeeperScale (0.5).
    EXPECT_EQ(full.rays, 5 * 16);  // f = 0.5: rows = round(sqrt(20.4)) = 5
    EXPECT_EQ(even.rays, 4 * 13);  // f = 0.64 · 0.5: rows = round(sqrt(13.0)) = 4
    // f = 1/4 (the floor) · 0.5: rows = round(sqrt(5.1)) = 2, raised to the
    // three rows a cached hemisphere has at least.
    EXPECT_EQ(lit.rays, 3 * 9);
    // Fewer samples of a furnace are still exact.
    for (const DeeperRecord& r : {full, dark, even, lit}) EXPECT_NEAR(r.value, 0.7, 1e-12);
}

// Deeper records without other light give up samples only as far as the
// first level is boosted to pay for them; lamp-lit ones take kDeeperScale of
// their share regardless.
TEST(IrradianceCache, UnlitDeeperRecordsAreCutOnlyAsFarAsTheFirstLevelIsBoosted) {
    using C = IrradianceCache;
    EXPECT_EQ(C::UnlitDeeperScale(1.0), 1.0);
    EXPECT_EQ(C::UnlitDeeperScale(C::kFirstLevelBoost), C::kDeeperScale);
    EXPECT_DOUBLE_EQ(C::UnlitDeeperScale(1.25), 0.75);
    EXPECT_EQ(C::UnlitDeeperScale(0.5), 1.0);
    EXPECT_EQ(C::UnlitDeeperScale(3.0), C::kDeeperScale);
    const double typical = 0.7;
    // 100 deeper records after 99 first-level ones (and the one in
    // progress): ratio 1, no boost.
    const DeeperRecord unboostedDark = MakeDeeperRecord(1, 0.0, 100, typical, 99);
    const DeeperRecord unboostedLit = MakeDeeperRecord(1, 35.0, 100, typical, 99);
    const DeeperRecord boostedDark = MakeDeeperRecord(1, 0.0, 100, typical, 0);
    EXPECT_EQ(unboostedDark.rays, 6 * 19);  // f = 1: rows = round(sqrt(40.7)) = 6
    EXPECT_EQ(boostedDark.rays, 5 * 16);    // f = 0.5
    EXPECT_EQ(unboostedLit.rays, 3 * 9);    // f = 1/4 · 0.5, three rows at least
}

TEST(IrradianceCache, FirstLevelAndUnguessedRecordsAreSampledInFull) {
    const DeeperRecord full = MakeDeeperRecord(1, -1, 100, 0.7);
    // The first level is the answer's own error: never reduced, nor asked
    // (with no deeper records made, as here, not raised either:
    // FirstLevelFraction).
    const DeeperRecord first = MakeDeeperRecord(0, 1e6, 100, 0.7);
    EXPECT_FALSE(first.otherAsked);
    EXPECT_EQ(first.rays, 9 * 28);  // rows = round(sqrt(256/π)) = 9
    // Until the thread has made enough records of the level, no guess.
    const DeeperRecord early =
        MakeDeeperRecord(1, 1e6, IrradianceCache::kShareGuessRecords - 1, 0.7);
    EXPECT_FALSE(early.otherAsked);
    EXPECT_EQ(early.rays, full.rays);
    const DeeperRecord enough = MakeDeeperRecord(1, 1e6, IrradianceCache::kShareGuessRecords, 0.7);
    EXPECT_LT(enough.rays, full.rays);
}

TEST(IrradianceCache, FirstLevelFractionGrowsWithTheDeeperRecordsPerFirstLevelRecord) {
    using C = IrradianceCache;
    // One bounce, or nothing made yet: Radiance's count.
    EXPECT_EQ(C::FirstLevelFraction(1, 1, 1000), 1.0);
    EXPECT_EQ(C::FirstLevelFraction(2, 0, 1000), 1.0);
    EXPECT_EQ(C::FirstLevelFraction(2, 10, 0), 1.0);
    // sqrt(ratio / 32) · 1.5 between 1 and 1.5: a picture's 2.5 deeper
    // records per first-level record get no boost, a sparse sensor grid's
    // 120 the whole of it.
    EXPECT_EQ(C::FirstLevelFraction(2, 100, 250), 1.0);
    EXPECT_DOUBLE_EQ(C::FirstLevelFraction(2, 100, 2000), 1.5 * std::sqrt(20.0 / 32));
    EXPECT_EQ(C::FirstLevelFraction(3, 100, 3200), C::kFirstLevelBoost);
    EXPECT_EQ(C::FirstLevelFraction(2, 84, 10000), C::kFirstLevelBoost);
}

/// Rays of a first-level record in a furnace, at -ab `bounces`, after the
/// thread made `first` first-level and `deeper` second-level records.
int FirstLevelRays(int bounces, int first, int deeper) {
    IrradianceSettings settings = Settings();
    settings.bounces = bounces;
    const IrradianceCache cache(settings, Store());
    IrradianceThread thread;
    thread.madeBright = {{0.7 * first, first}, {0.7 * deeper, deeper}};
    IrradianceCounters counters;
    Rng rng(3);
    Furnace env;
    const auto r = cache.Evaluate(At({0, 0, 0}), 0.5, thread, counters, rng, env, NeverOccluded);
    EXPECT_TRUE(r.value);
    EXPECT_NEAR(r.value ? r.value->g : 0, 0.7, 1e-12);  // still exact
    // The record itself counts toward the next one's fraction.
    EXPECT_EQ(thread.madeBright[0].second, first + 1);
    return env.rays;
}

TEST(IrradianceCache, FirstLevelRecordsTakeMoreSamplesWhereEachLeadsToManyDeeperOnes) {
    // Radiance's count: rows = round(sqrt(256/π)) = 9, 28 columns.
    EXPECT_EQ(FirstLevelRays(1, 1, 1000), 9 * 28);
    EXPECT_EQ(FirstLevelRays(2, 0, 0), 9 * 28);
    EXPECT_EQ(FirstLevelRays(2, 100, 250), 9 * 28);
    // The whole boost: 384 divisions, rows = round(sqrt(384/π)) = 11, 35 columns.
    EXPECT_EQ(FirstLevelRays(2, 1, 1000), 11 * 35);
}

}  // namespace
}  // namespace rt
