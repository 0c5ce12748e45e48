// SPDX-License-Identifier: MIT
//
// The lazy irradiance cache's lookup-or-compute loop (Radiance's
// multambient() and makeambient(), radiance-notes.md §4.1, §4.4): at a
// shading point, interpolate the records good enough there (with the leak
// test), otherwise sample a new hemisphere, weigh it as a record of the
// current ambient level, give it its corral bits and keep it. Without a
// record store (-aa 0) every point samples its own hemisphere.
//
// ambient/ knows nothing of rays or scenes: the caller passes how to trace
// one hemisphere ray and how to test one leak ray. An IrradianceCache is
// read-only and may serve any number of threads (its AmbientCache
// synchronises itself); each thread passes its own IrradianceThread,
// counters and random numbers.
//
//   IrradianceCache cache(settings, store);
//   auto r = cache.Evaluate(query, thread, counters, rng, trace, occluded);
//   if (r.value) colour = coefficient * *r.value;   // Ē times the material's
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "ambient/ambient_options.h"
#include "ambient/cache.h"
#include "ambient/hemisphere.h"
#include "ambient/hessian.h"
#include "ambient/record.h"
#include "core/function_ref.h"
#include "core/random.h"
#include "core/rgb.h"
#include "core/vecmath.h"

namespace rt {

/// What the ambient calculation did, for rtrace's -t report.
struct IrradianceCounters {
    std::uint64_t leakRays = 0;        // leak-test rays of cache lookups (ambient/leak.h)
    std::uint64_t ambientLookups = 0;  // cache queries
    std::uint64_t ambientHits = 0;     // queries answered by interpolation
    std::uint64_t hemispheres = 0;     // hemispheres sampled (records made or not)
    std::vector<std::uint64_t> recordsPerLevel;  // records created, by ambient level

    // Only measured with IrradianceThread::timing on, because reading the
    // clock costs time of its own.
    double secondsSampling = 0;  // outermost hemispheres, less the lookups their samples
                                 // made (the caller takes off its own work, e.g. direct light)
    double secondsLookup = 0;    // cache lookups (interpolation)
};

/// One thread's part of the loop; passed to every Evaluate.
struct IrradianceThread {
    /// Nesting of hemisphere computations (Radiance's ambient depth): a
    /// query at depth d uses and makes records of level d.
    int depth = 0;
    /// Records made by this thread and not yet handed out (for ambient files).
    std::vector<AmbientRecord> newRecords;
    /// Whether new records are queued in `newRecords` at all. Without an
    /// ambient file nobody takes them, and a queue that only grows costs a
    /// fresh page (a page fault) for every 24 records as it doubles.
    bool queueNewRecords = true;
    bool timing = false;
    /// Per ambient level: Σ bright(Ē) over the records this thread made, and
    /// their number; the typical Ē of a level for DeeperSampleFraction.
    std::vector<std::pair<double, int>> madeBright;
};

/// The radiance (brightness, W·sr⁻¹·m⁻²) a shaded point sends its viewer
/// besides the ambient term being asked for: its direct light and what it
/// has already (specular reflections). Called only when a deeper record is
/// about to be made.
using OtherRadianceRef = FunctionRef<double()>;

/// How a new hemisphere is sampled and turned into a record.
enum class RecordMethod {
    /// Ward's stratified hemisphere and split-sphere records with Ward &
    /// Heckbert's gradients (Radiance ≤ 4.2; hemisphere.h).
    Classic,
    /// Radiance 5's square grid and elliptical records from the hemisphere's
    /// Hessian, with occlusion-aware gradients (hessian.h).
    Hessian,
};

/// The methods an -ah choice (ambient_options.h) makes records by: the first
/// level's and the deeper levels'.
struct LevelMethods {
    RecordMethod firstLevel;
    RecordMethod deeper;
};
inline LevelMethods MethodsFor(RecordMethods choice) {
    switch (choice) {
        case RecordMethods::Hessian: return {RecordMethod::Hessian, RecordMethod::Hessian};
        case RecordMethods::Mixed: return {RecordMethod::Classic, RecordMethod::Hessian};
        case RecordMethods::Classic: break;
    }
    return {RecordMethod::Classic, RecordMethod::Classic};
}
/// Each method's records are interpolated with their own weights: Radiance
/// 5's hat goes with its Hessian records.
inline RecordWeighting WeightingFor(RecordMethod method) {
    return method == RecordMethod::Hessian ? RecordWeighting::Hat : RecordWeighting::SplitSphere;
}

struct IrradianceSettings {
    /// The first level's method, and the deeper levels' (nullopt: the same).
    RecordMethod method = RecordMethod::Classic;
    std::optional<RecordMethod> deeperMethod;
    RecordMethod MethodAt(int level) const {
        return level > 0 ? deeperMethod.value_or(method) : method;
    }
    double accuracy = 0.1;    // -aa (> 0 with a store)
    int divisions = 1024;     // -ad
    int superSamples = 512;   // -as
    double minimumWeight = 2e-3;  // -lw: without the cache, hemisphere sizes keep
                                  // sample rays near it
    /// Records nearer than this to a query need no leak ray
    /// (Scene::distanceTolerance).
    double distanceTolerance = 1e-6;
    /// Hessian records: hit points farther than this (scene units) are stored
    /// this far (HessianFarDistance of the scene cube).
    double farDistance = HessianFarDistance(1.0);
    /// -ab: with two or more bounces, first-level records may take more
    /// samples than -ad and deeper ones fewer (FirstLevelFraction).
    int bounces = 1;
};

/// What one hemisphere ray needs besides its direction: how its value will
/// be weighed, so that the caller can give the ray its importance.
struct AmbientSampleShare {
    /// With the cache, every sample ray weighs Radiance's average
    /// reflectance, 0.5, of its parent; without it, its true share of the
    /// coefficient, 1/divisions.
    bool caching = true;
    int divisions = 1;  // samples of the first pass
};

/// Traces one hemisphere ray from the query point (see AmbientTraceRef).
using IrradianceTraceRef =
    FunctionRef<std::optional<AmbientSample>(const Vec3& dir, const AmbientSampleShare& share)>;
/// True when something blocks the segment from `from` along unit `dir` before
/// `length` (the leak test's ray).
using OccludedRef = FunctionRef<bool(const Vec3& from, const Vec3& dir, double length)>;

struct IrradianceResult {
    enum class Source : std::uint8_t {
        Interpolated,  // from two or more records
        Extrapolated,  // from a single record and its gradients
        Computed,      // a fresh hemisphere (a record made, or not)
        Failed,        // no hemisphere sample succeeded: use the fallback value
    };
    /// Ē = irradiance/π (W·sr⁻¹·m⁻²) at the query; nullopt when Failed.
    std::optional<Rgb> value;
    Source source = Source::Failed;
};

class IrradianceCache {
public:
    /// `store` may be null: no cache (-aa 0), every query samples.
    IrradianceCache(const IrradianceSettings& settings, std::shared_ptr<AmbientCache> store);

    /// Ē at `query` (whose level is taken from `thread.depth`). `coefficientIntensity`
    /// is intens() of the material's diffuse coefficient, which sizes
    /// cache-less hemispheres. Raises `thread.depth` while sampling, so that
    /// the trace function's own queries are of the next level.
    ///
    /// `otherRadiance` (may be null) sizes records below the first level by
    /// the ambient term's share of what the point sends its viewer
    /// (DeeperSampleFraction); without it they are sampled in full.
    IrradianceResult Evaluate(const AmbientQuery& query, double coefficientIntensity,
                              IrradianceThread& thread, IrradianceCounters& counters, Rng& rng,
                              IrradianceTraceRef trace, OccludedRef occluded,
                              const OtherRadianceRef* otherRadiance = nullptr) const;

    /// The fraction of Radiance's sample count (-ad and -as times the record
    /// weight) that a record below the first level takes, when the ambient
    /// term carries `share` (in [0, 1]) of the radiance its point sends the
    /// surfaces that look at it: share², at least kMinDeeperFraction.
    ///
    /// Why: the record's Monte Carlo error reaches its viewers scaled by that
    /// share, so with share² of the samples every record adds the same
    /// relative noise to what looks at it as a record whose point has no
    /// other light does with all of them. Where lamps light the surfaces
    /// directly most deeper records need far fewer rays; where all light is
    /// indirect (a sky seen through a window) nothing changes. The first
    /// level is never reduced: its error is the answer's own.
    static double DeeperSampleFraction(double share);
    static constexpr double kMinDeeperFraction = 0.25;

    /// Samples moved from the deeper records to the first level's (README,
    /// Differences, "Samples moved to the first level"). A sensor's or
    /// pixel's value is its first-level record's hemisphere, so that
    /// record's noise is the answer's own; a deeper record's noise reaches
    /// the answer averaged with that of the many other records its viewer's
    /// hemisphere meets. So a first-level record takes FirstLevelFraction of
    /// Radiance's count; a deeper record whose point has other light takes
    /// kDeeperScale of what DeeperSampleFraction gives it; and one without
    /// (or whose share is not guessed yet) takes UnlitDeeperScale.
    static constexpr double kDeeperScale = 0.5;
    static constexpr double kFirstLevelBoost = 1.5;
    /// Deeper records made per first-level record at which the first level
    /// takes the whole boost.
    static constexpr double kFullBoostRatio = 32;
    /// The first level's fraction of Radiance's count, from the records the
    /// thread made before (never from the record's own samples): the extra
    /// first-level samples pay only where each first-level record leads to
    /// many deeper ones (sparse sensor grids, where every sensor makes its own
    /// first-level record and each of those a hundred or more deeper ones),
    /// not where first-level records are many and share their deeper ones
    /// (pictures, a few each). With optimal allocation between two levels the first
    /// level's count grows as the square root of that ratio, so the boost is
    /// sqrt(ratio / kFullBoostRatio) · kFirstLevelBoost, between 1 and
    /// kFirstLevelBoost; 1 with fewer than two bounces or no records yet.
    static double FirstLevelFraction(int bounces, int firstLevelRecords, int deeperRecords);
    /// The fraction of Radiance's count a deeper record takes when its point
    /// has no light besides the ambient term, for a first level boosted by
    /// `boost`: from 1 without boost to kDeeperScale with the whole of it.
    /// Such records carry all of their surface's light (a room lit through
    /// a window), so their noise is cut only as far as the first level is
    /// sampled more to pay for it; where it is not (a dense daylit grid),
    /// halving them raised the error by 15 % (README).
    static double UnlitDeeperScale(double boost);
    /// Records a thread makes at a level before their mean Ē is trusted as
    /// the level's typical value.
    static constexpr int kShareGuessRecords = 32;

    /// Radiance's weight of a new record at ambient level `level` for a ray
    /// of weight `rayWeight` (§4.4): 0.5^level, or about the ray's own weight
    /// when the ray matters much less than that; never below the ray weight.
    static double RecordWeight(int level, double rayWeight);

    const std::shared_ptr<AmbientCache>& store() const { return store_; }

private:
    std::optional<Rgb> Lookup(const AmbientQuery& query, IrradianceCounters& counters,
                              OccludedRef occluded, int* used) const;
    /// A fresh hemisphere at the query by the settings' method: its value Ē
    /// (nullopt when no sample succeeded) and, when `level` >= 0 and it is
    /// good enough, the record made from it (of that level and `weight`).
    struct Sampled {
        std::optional<Rgb> value;
        std::optional<AmbientRecord> record;
        /// -aa 0 only: the relative rotational gradient (1/radian, tangent
        /// to the normal sampled about) when the query's shading normal
        /// turns away from it, else zero.
        Vec3 dirGradient;
    };
    /// `fraction` scales the hemisphere's sample counts (not the record's weight).
    Sampled Sample(const AmbientQuery& query, double weight, double fraction, int level,
                   IrradianceThread& thread, IrradianceCounters& counters, Rng& rng,
                   IrradianceTraceRef trace) const;
    /// The ambient term's share of what a new record's point sends its
    /// viewers (DeeperSampleFraction), or nullopt when the point has no other
    /// light, there is no `otherRadiance`, or the thread has made fewer than
    /// kShareGuessRecords records of the level to guess the ambient term from.
    std::optional<double> AmbientShare(int level, double coefficientIntensity,
                                       const IrradianceThread& thread,
                                       const OtherRadianceRef* otherRadiance) const;
    /// The fraction of Radiance's sample count a new record of level `level`
    /// takes: FirstLevelFraction at the first level; below it kDeeperScale ·
    /// DeeperSampleFraction(share) where AmbientShare knows the share, else
    /// UnlitDeeperScale.
    double SampleFraction(int level, double coefficientIntensity, const IrradianceThread& thread,
                          const OtherRadianceRef* otherRadiance) const;

    IrradianceSettings settings_;
    std::shared_ptr<AmbientCache> store_;
};

}  // namespace rt
