// SPDX-License-Identifier: MIT
//
// The two kinds of state the ray tree works with, kept apart so that what is
// shared is visibly read-only and what a ray changes is passed in by hand:
//  - ShadingSetup: built once from the scene and the options, then only read
//    while rays are traced (the ambient cache it points to synchronises
//    itself and may be shared by several threads).
//  - ThreadState: one per thread (one per Renderer): random numbers, the
//    function language's evaluation context, source statistics, counters,
//    scratch space, new records and the trace callback. Every function of
//    the ray tree that changes something takes it as an argument.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "ambient/cache.h"
#include "ambient/irradiance_cache.h"
#include "ambient/ambient_options.h"
#include "cal/context.h"
#include "core/diagnostics.h"
#include "core/random.h"
#include "core/rgb.h"
#include "core/vecmath.h"
#include "raycore/raycore.h"
#include "scene/scene.h"
#include "shading/light_sources.h"
#include "shading/obstructors.h"
#include "shading/shading_options.h"
#include "shading/ray_result.h"
#include "shading/render_stats.h"

namespace rt {

/// Read-only while rays are traced.
struct ShadingSetup {
    /// `scene` and `core` must outlive the setup. Finds the light sources,
    /// warning through `warn` ("no light sources found" only when no glow
    /// sky lights the scene through indirect bounces, as Radiance). `cache`
    /// may be null (the options need none) or shared.
    ShadingSetup(const Scene& scene, const RayCore& core, const ShadingOptions& shading,
                 const AmbientOptions& ambient, const WarningSink& warn,
                 std::shared_ptr<AmbientCache> cache);

    const Scene& scene;
    const RayCore& core;
    ShadingOptions shading;
    AmbientOptions ambient;
    std::vector<LightSource> sources;
    /// Radiance's obstructor cache (shading/obstructors.h): each source's
    /// table layout (all Kind::None when the cache is off), and for each of
    /// Scene::surfaces whether it may be recorded as a blocker.
    std::vector<ObstructorLayout> obstructorLayouts;
    std::vector<std::uint8_t> reliableBlockers;
    /// Radiance's hidden "Lamb" material for -i/-I: plastic with reflectance
    /// π, which turns reflected radiance into irradiance.
    Material lambertian;
    /// Shadow rays are answered by occlusion queries (RayCore::Occluders):
    /// followed through the surfaces as before when a transmitting surface is
    /// in the way, otherwise blocked if an opaque one is and unshadowed if
    /// none is. Needs back faces visible: with -bv- any surface passes light
    /// from behind.
    bool queryShadows = true;
    bool transmitting = false;  // RayCore::HasTransmitting()
    /// (int)(n^dc + 0.5) for small n: how many contributions -dc says to test
    /// beyond the current one, without a std::pow per shading point.
    std::vector<int> shadowCheckCounts;
    std::unordered_set<std::string> ambientList;  // -ae/-ai modifier names
    /// The lookup-or-compute loop over the record store `cache` (only with
    /// -ab > 0 and -aa > 0; null otherwise, and then every point samples).
    std::shared_ptr<AmbientCache> cache;
    IrradianceCache irradiance;
    /// -me, -ma and -mg; `hasMedium` false when the extinction is zero.
    Medium medium;
    bool hasMedium = false;
    /// Each mist material's light sources (by Scene::materials index), as
    /// Radiance's m_mist.c finds them: per name the last source that
    /// matches, unknown and repeated names left out with a warning.
    std::unordered_map<int, std::vector<int>> mistSources;
};

/// Radiance's per-source shadow-test statistics and aiming count (source.c,
/// srcvalue()); they change as rays are traced, so each thread keeps its own.
struct SourceTally {
    // Shadow tests and unblocked ones: direct() estimates untested samples
    // by their ratio.
    long nhits = 1;
    long ntests = 2;
    // Radiance's aiming count (srcvalue(), srcsupp.c): a sample ray that
    // hits its source adds 1, without limit; one that misses takes
    // kAimRequired, and the miss that takes the count below zero prints
    // "aiming failure", once: a negative count never changes again. It
    // starts at FirstAimCount: Radiance's "bitch on second failure", on the
    // fourth for a cylinder.
    static constexpr long kAimRequired = 100;
    long aimSuccess = 2 * kAimRequired - 1;
    /// Radiance's starting count for `source`.
    static long FirstAimCount(const LightSource& source) {
        return (source.shape == LightSource::Shape::Cylinder ? 4 : 2) * kAimRequired - 1;
    }
};

/// One light-source sample's share of the direct term at a shading point.
struct DirectContribution {
    // A constructor, not aggregate initialisation, for emplace_back: clang
    // before 16 has no parenthesised aggregate initialisation (C++20), and
    // the fuzz build (scripts/fuzz.sh) is clang's.
    DirectContribution() = default;
    DirectContribution(int source_, const Vec3& dir_, double distance_, const Rgb& coef_,
                       const Rgb& value_, double bright_, bool alone_)
        : source(source_), dir(dir_), distance(distance_), coef(coef_), value(value_),
          bright(bright_), alone(alone_) {}

    int source = -1;
    Vec3 dir;
    double distance = 0;  // to the sample point on the source
    Rgb coef;             // material coefficient for this sample
    Rgb value;            // unshadowed radiance ⊗ coef
    double bright = 0;
    bool alone = false;   // SourceSample::alone
};

/// Scratch space of one direct-light evaluation, kept between calls so that
/// shading allocates nothing per point.
struct DirectScratch {
    std::vector<SourceSample> samples;
    std::vector<SourcePartition> partitions;
    std::vector<DirectContribution> contributions;
    std::vector<DirectContribution> sortBuffer;
    std::vector<double> tail;
};

/// Everything tracing changes: one per thread.
struct ThreadState {
    ThreadState(const ShadingSetup& setup, WarningSink warn);

    /// Measure where time goes (RenderStats::seconds*); costs a few per cent.
    void EnableTiming(bool on);
    /// Starts input ray `rayIndex`: seeds the random numbers (-u+: a stream
    /// per input position; -u-: the same for every ray) and forgets the
    /// previous ray's first ambient outcome.
    void StartInputRay(const ShadingOptions& shading, std::uint64_t rayIndex);
    void Warn(const std::string& message) const {
        if (warn) warn(message);
    }

    WarningSink warn;
    Rng rng;
    /// The function language's evaluation state (null without patterns).
    std::unique_ptr<cal::Context> functionContext;
    std::unordered_set<int> patternWarned;  // patterns whose compute errors were reported
    std::unordered_set<const Surface*> perturbationWarned;  // illegal perturbations reported
    std::unordered_set<const Material*> orientationWarned;  // illegal orientation vectors reported
    std::unordered_set<const Material*> brdfWarned;  // BRDF functions' compute errors reported
    std::vector<SourceTally> sourceTallies;  // one per ShadingSetup::sources
    /// Each source's obstructor table: per cell a Scene::surfaces index or -1.
    /// Empty until the source's first check fills it (DirectLight).
    std::vector<std::vector<int>> obstructors;
    RenderStats stats;
    /// The ambient depth, the records made here and not yet handed out, and
    /// whether the cache's work is timed.
    IrradianceThread ambient;

    std::vector<DirectScratch> directScratch;  // one set per direct-light depth
    int directDepth = 0;

    // The indirect outcome at the first surface the current input ray shaded,
    // for RayResult (reset per input ray).
    RayResult::AmbientOutcome firstOutcome = RayResult::AmbientOutcome::None;
    Rgb firstIndirectIrradiance;
    bool firstAmbientSeen = false;

    // Timing (rtrace -t).
    bool timing = false;
    /// Direct-light calls so far, of which every kDirectTimingStride-th is
    /// timed and stands for the others (reading the clock around every call
    /// would itself cost a noticeable share of the run).
    std::uint64_t directCalls = 0;
    static constexpr int kDirectTimingStride = 16;
    /// Seconds between two back-to-back clock reads, which every timed
    /// interval also holds.
    double clockReadSeconds = 0;

    // Trace output (-ot/-oT): called for every ray when it is done.
    std::function<void(const RayResult&)> trace;
    bool traceShadows = false;
};

}  // namespace rt
