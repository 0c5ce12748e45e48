// SPDX-License-Identifier: MIT
//
// Internal to shading/: Radiance's ray tree (raytrace.c) with its materials and
// direct calculation. The Renderer in renderer.h is the public face; this
// class holds the per-process state (source statistics, random numbers).
//
// Method bodies are split by topic: integrator.cpp (ray tree, rayorigin
// limits, -I/-i), direct.cpp (direct(), source rays), materials.cpp
// (normal.c, m_mirror.c, glass.c, dielectric.c, m_light, raynormal()),
// patterns.cpp (p_func.c, t_func.c, mx_func.c, raymixture()).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <unordered_set>
#include <utility>
#include <vector>

#include "ambient/cache.h"
#include "ambient/hemisphere.h"
#include "ambient/ambient_options.h"
#include "core/conventions.h"
#include "core/diagnostics.h"
#include "core/function_ref.h"
#include "core/random.h"
#include "core/rgb.h"
#include "core/vecmath.h"
#include "raycore/raycore.h"
#include "scene/scene.h"
#include "shading/light_sources.h"
#include "shading/shading_options.h"
#include "shading/ray_result.h"
#include "shading/render_stats.h"

namespace rt {

/// Radiance's ray type bits (ray.h); a ray's `crtype` ORs them along its path.
enum RayTypeBits : unsigned {
    kPrimaryRay = 1,
    kShadowRay = 2,
    kReflectedRay = 4,
    kRefractedRay = 8,
    kTransRay = 16,
    kAmbientRay = 32,
    kSpecularRay = 64,
};

/// One ray of the ray tree (Radiance's RAY, the fields lazyrad uses).
struct TracedRay {
    // Set before tracing.
    Vec3 org;
    Vec3 dir;                  // unit
    double rmax = 0;           // > 0 limits the distance
    unsigned rtype = kPrimaryRay;
    unsigned crtype = kPrimaryRay;
    int rlvl = 0;              // reflection level
    double rweight = 1;        // importance: Russian roulette, -lw, -dt
    /// Importance for light-source subdivision (-ds): like rweight, except
    /// that ambient sample rays carry their path's real coefficient instead
    /// of the cache's nominal 0.5 (see SampleAmbient).
    double sourceWeight = 1;
    Rgb rcoef{1, 1, 1};        // coefficient this ray's value will be multiplied by
    const TracedRay* parent = nullptr;
    int rsrc = -1;             // light source this shadow ray aims at, -1 for none
    int depth = 0;             // ray-tree depth for trace output

    // Filled by tracing.
    int surface = -1;          // hit surface (Scene::HitSurface(instance, surface)) or -1
    int instance = -1;         // instance the hit surface is in, -1 for none
    /// World to the space patterns start from (Scene::PatternSpace): an
    /// instance's object space; null for world space.
    const Transform* objectFromRender = nullptr;
    bool hitDistant = false;   // hit a distant source (surface is then that source)
    double rot = kFhuge;       // first intersection distance
    Vec3 rop;                  // intersection point
    Vec3 ron;                  // normal at rop, flipped by materials toward the ray
    Vec3 geometricNormal;      // unflipped normal as the surface defines it
    Vec3 pert;                 // normal perturbation (textures; mesh vertex normals), world space; negated with the surface
    double lu = 0, lv = 0;     // mesh (u,v) at the hit (Lu, Lv), 0 when none
    double rod = 0;            // -Dot(dir, ron): > 0 on the front
    Rgb pcol{1, 1, 1};         // pattern colour: the product of the patterns met
    bool irradianceHit = false;  // -I pretend hit (no object)
    bool lambertian = false;   // -i/-I: shade with Radiance's hidden Lamb material

    // Results.
    Rgb rcol;                  // radiance
    Rgb mcol;                  // mirrored part
    double rmt = kFhuge;       // mirror distance
    double rxt = kFhuge;       // unmirrored distance

    double EffectiveDistance() const {
        return Bright(mcol) > 0.5 * Bright(rcol) ? rmt : rxt;
    }

    /// Records that the ray reached distant source `sourceSurface` (Radiance's
    /// sourcehit(): no hit point, the normal faces the ray).
    void SetDistantHit(int sourceSurface) {
        surface = sourceSurface;
        instance = -1;
        objectFromRender = nullptr;
        hitDistant = true;
        rot = kFhuge;
        rop = org;
        ron = geometricNormal = -dir;
        rod = 1.0;
    }

    /// Records where the ray hit a surface (before any shading flips).
    /// `patternSpace` is Scene::PatternSpace(hit.instance).
    void SetHit(const Hit& hit, const Transform* patternSpace) {
        surface = hit.surface;
        instance = hit.instance;
        objectFromRender = patternSpace;
        rot = rmt = rxt = hit.t;
        rop = hit.point;
        ron = geometricNormal = hit.normal;
        rod = -Dot(dir, hit.normal);
        // Mesh vertex normals shade as a perturbation (o_mesh.c), so that
        // patterns still see the geometric normal.
        pert = hit.shadingNormal - hit.normal;
        lu = hit.u;
        lv = hit.v;
    }
};

class Integrator {
public:
    /// `cache` may be shared with other Integrators (threads); null when the
    /// options need none.
    Integrator(const Scene& scene, const RayCore& core, const ShadingOptions& shading,
               const AmbientOptions& ambient, WarningSink warn,
               std::shared_ptr<AmbientCache> cache);

    RayResult TraceInput(const Vec3& org, const Vec3& dir, double rmax, std::uint64_t rayIndex);

    void SetTraceCallback(std::function<void(const RayResult&)> callback, bool shadowRays) {
        trace_ = std::move(callback);
        traceShadows_ = shadowRays;
    }

    const std::vector<LightSource>& sources() const { return sources_; }
    const RenderStats& stats() const { return stats_; }
    void EnableTiming(bool on);
    /// Records this Integrator created since the last call (for ambient files).
    std::vector<AmbientRecord> TakeNewRecords() { return std::exchange(newRecords_, {}); }
    /// A copy of the cache's records (empty without a cache).
    std::vector<AmbientRecord> CacheRecords() const {
        return cache_ ? cache_->Records() : std::vector<AmbientRecord>{};
    }

private:
    // integrator.cpp
    /// Radiance's rayorigin(): sets up `child` from `parent`; false if the ray
    /// must not be traced (weight limits, Russian roulette). `coef` may be null.
    bool StartChild(TracedRay& child, const TracedRay& parent, unsigned type, const Rgb* coef);
    /// Traces and shades `ray` (raytrace()): closest hit, distant sources, trace callback.
    void Trace(TracedRay& ray);
    /// Shades a ray that hit `ray.surface` (rayshade()); with -i, Lamb replaces materials.
    void Shade(TracedRay& ray);
    /// Pass-through (raytrans()): continues the ray unchanged past the surface.
    void PassThrough(TracedRay& ray);
    /// Looks for a distant source in the ray's direction (sourcehit()).
    bool HitDistantSource(TracedRay& ray) const;
    /// The indirect term A ⊗ E/π at a shaded point (multambient()); with no ambient
    /// bounces this is the -av value.
    Rgb Ambient(const Rgb& coefficient, const TracedRay& ray, const Vec3& normal);
    /// The fallback where no bounce is computed: -av, or its -aw average.
    Rgb AmbientFallback(const Rgb& coefficient) const;
    /// Samples a fresh hemisphere at the ray's hit point (ambient depth
    /// raised for the duration). `coefficient` is the material's diffuse
    /// coefficient; `weight` the record weight. Sample rays get the weights
    /// Radiance gives them (§4.5): 0.5 of the parent's with the cache, their
    /// share of the coefficient without.
    Hemisphere SampleAmbient(const TracedRay& ray, const Rgb& coefficient, double weight);
    bool AmbientExcluded(const TracedRay& ray) const;
    void Report(const TracedRay& ray);
    /// Not const: the shading normal it prints may warn (PerturbedNormal).
    RayResult MakeResult(const TracedRay& ray);
    RayResult WithAmbientOutcome(RayResult result) const;

    // direct.cpp
    /// Radiance's direct(): adds to ray.rcol the contribution of every light
    /// source sample, `coef(ldir, omega)` giving the material's coefficient.
    void Direct(TracedRay& ray, FunctionRef<Rgb(const Vec3&, double)> coef);
    void DirectUntimed(TracedRay& ray, FunctionRef<Rgb(const Vec3&, double)> coef);
    /// Radiance's srcvalue(): radiance arriving along a source ray aimed at
    /// `source`, whose sample point lies `distance` away.
    Rgb SourceValue(TracedRay& sray, int source, double distance);
    /// Shades a shadow ray past an intervening surface (raycont()).
    void ContinueShadowRay(TracedRay& sray);

    // materials.cpp
    void ShadeNormal(TracedRay& ray, const Material& m);     // plastic, metal, trans
    void ShadeLight(TracedRay& ray, const Material& m);      // light, illum, glow, spotlight
    void ShadeMirror(TracedRay& ray, const Material& m);
    void ShadeGlass(TracedRay& ray, const Material& m);
    void ShadeDielectric(TracedRay& ray, const Material& m); // dielectric, interface
    /// Applies the material's own chain, then shades with it (by type, through a table).
    void ShadeMaterial(TracedRay& ray, const Material& m);
    /// ShadeMaterial, except that with -i the first opaque surface reached by a
    /// primary or transmitted ray is measured instead (rayshade()'s Lamb hack).
    void ShadeSurfaceMaterial(TracedRay& ray, const Material& m);
    /// Radiance's raynormal(): sets `normal` to the shading normal N' =
    /// normalize(ron + pert), reflected in the plane normal to the ray if the
    /// perturbation tipped it to the ray's other side, and returns -dir·N'
    /// (unclamped, same sign as rod). A sum of zero length warns once per
    /// surface and gives ron and rod.
    double PerturbedNormal(const TracedRay& ray, Vec3& normal);
    /// Radiance's hastexture: |pert|² > FTINY².
    static bool Textured(const TracedRay& ray);

    // patterns.cpp
    /// Evaluates `modifiers` (indices into Scene::patterns) for this ray in
    /// chain order: patterns multiply ray.pcol, textures add to ray.pert,
    /// mixtures shade both sides. True when a mixture reached a material and
    /// so shaded the ray: the chain ends there.
    /// Inline for the common case of an empty chain: it runs at every hit.
    bool ApplyModifiers(TracedRay& ray, const std::vector<int>& modifiers) {
        return !modifiers.empty() && ApplyModifierChain(ray, modifiers);
    }
    bool ApplyModifierChain(TracedRay& ray, const std::vector<int>& modifiers);
    /// Radiance's rayshade() from some modifier on: true if a material shaded the ray.
    bool ShadeChain(TracedRay& ray, const ModifierChain& chain);
    /// Radiance's raymixture(): shades copies of `ray` with `mixture`'s fore
    /// and back chains, weighted c and 1-c (c = `coefficient` clamped to
    /// [0, 1]), and blends their pcol and pert into `ray`, and their values
    /// when either reached a material (then returns true).
    bool Mix(TracedRay& ray, const Pattern& mixture, double coefficient);
    /// -I: a measuring point lying in the plane of a wall (a sensor on an
    /// edge or in a corner) would send half its sample rays through that
    /// wall, whose hit at t = 0 the self-hit rule discards. Moves the point
    /// `offset` off each such wall, to the side where the surface under the
    /// sensor continues; elsewhere returns it unchanged.
    Vec3 OffWallsThroughSensor(Vec3 point, const Vec3& normal, double offset) const;
    void FlipSurface(TracedRay& ray) const;

    const Scene& scene_;
    const RayCore& core_;
    ShadingOptions shading_;
    AmbientOptions ambient_;
    WarningSink warn_;
    /// This thread's evaluation state of the scene's function language (null
    /// without patterns), and the patterns whose compute errors were reported.
    std::unique_ptr<cal::Context> functionContext_;
    std::unordered_set<int> patternWarned_;
    std::unordered_set<const Surface*> perturbationWarned_;  // surfaces with an illegal perturbation
    std::vector<LightSource> sources_;
    Material lambertian_;   // -i/-I: plastic with reflectance pi
    Rng rng_;
    std::shared_ptr<AmbientCache> cache_;       // only with -ab > 0 and -aa > 0
    // The indirect outcome at the first surface the current input ray
    // shaded (reset per input ray), for RayResult.
    RayResult::AmbientOutcome firstOutcome_ = RayResult::AmbientOutcome::None;
    Rgb firstIndirectIrradiance_;
    bool firstAmbientSeen_ = false;
    void NoteAmbient(RayResult::AmbientOutcome outcome, const Rgb& meanRadiance);
    std::vector<AmbientRecord> newRecords_;     // created here, not yet handed out
    std::unordered_set<std::string> ambientList_;  // -ae/-ai modifier names
    int ambientDepth_ = 0;  // nesting of hemisphere computations (Radiance's ambient depth)
    RenderStats stats_;
    bool timing_ = false;
    // Scratch space for Direct(), one set per nesting depth, so that shading
    // allocates nothing per point.
    struct DirectContribution {
        int source = -1;
        Vec3 dir;
        double distance = 0;  // to the sample point on the source
        Rgb coef;      // material coefficient for this sample
        Rgb value;     // unshadowed radiance ⊗ coef
        double bright = 0;
    };
    struct DirectScratch {
        std::vector<SourceSample> samples;
        std::vector<SourcePartition> partitions;
        std::vector<DirectContribution> contributions;
        std::vector<DirectContribution> sortBuffer;
        std::vector<double> tail;
    };
    std::vector<DirectScratch> directScratch_;
    /// (int)(n^dc + 0.5) for small n: how many contributions -dc says to
    /// test beyond the current one, tabled so that no shading point calls
    /// std::pow (docs/measured-choices.md).
    std::vector<int> shadowCheckCounts_;
    /// No surface can pass light (no trans, glass, dielectric, interface or
    /// illum, and back faces are visible): shadow rays need only any-hit tests.
    bool opaqueShadows_ = true;
    int directDepth_ = 0;
    /// With timing on: Direct() calls so far, of which every
    /// kDirectTimingStride-th is timed.
    std::uint64_t directCalls_ = 0;
    static constexpr int kDirectTimingStride = 16;
    /// Seconds between two back-to-back clock reads, which every timed
    /// interval also holds and which is taken off it.
    double clockReadSeconds_ = 0;
    std::function<void(const RayResult&)> trace_;
    bool traceShadows_ = false;
};

}  // namespace rt
