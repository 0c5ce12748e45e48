// SPDX-License-Identifier: MIT
//
// shading/'s public face: one Renderer per thread evaluates input rays the
// way Radiance's rtrace does. Inside, it binds three parts (shading_state.h,
// ray_tree.h): the read-only ShadingSetup (light sources, options, the
// possibly shared cache), the RayTree that walks rays through surfaces,
// modifiers and materials (materials.h) with DirectLight and IndirectLight,
// and this thread's ThreadState (random numbers, source statistics, counters,
// scratch space), which the tree is handed explicitly at every call.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>

#include "ambient/cache.h"
#include "ambient/ambient_options.h"
#include "core/diagnostics.h"
#include "raycore/raycore.h"
#include "scene/scene.h"
#include "shading/shading_options.h"
#include "shading/ray_result.h"
#include "shading/render_stats.h"

namespace rt {

class Renderer {
public:
    /// The irradiance cache the options call for, or null when they need none
    /// (-ab 0, -aa 0, -ad 0): leave out what is not used. One cache may serve
    /// several Renderers (threads).
    static std::shared_ptr<AmbientCache> MakeCache(const Scene& scene,
                                                   const AmbientOptions& ambient);

    /// What the Renderers of one scene and one set of options share, and only
    /// read while they trace: the options, the light sources, the ray tree,
    /// the cache. Opaque outside shading/.
    struct Shared;
    /// `scene` and `core` must outlive every Renderer made from the result.
    /// Finds the light sources (warning "no light sources found" through
    /// `warn` when there are none). `cache` is from MakeCache, or null.
    static std::shared_ptr<const Shared> Share(const Scene& scene, const RayCore& core,
                                               const ShadingOptions& shading,
                                               const AmbientOptions& ambient,
                                               const WarningSink& warn,
                                               std::shared_ptr<AmbientCache> cache);

    /// One thread's renderer over `shared`: its own random numbers, source
    /// statistics, counters and new records; warnings while tracing go to `warn`.
    Renderer(std::shared_ptr<const Shared> shared, WarningSink warn);
    /// A Renderer with a set-up of its own (Share, then the above); by
    /// default with a private cache.
    Renderer(const Scene& scene, const RayCore& core, const ShadingOptions& shading,
             const AmbientOptions& ambient, WarningSink warn);
    Renderer(const Scene& scene, const RayCore& core, const ShadingOptions& shading,
             const AmbientOptions& ambient, WarningSink warn,
             std::shared_ptr<AmbientCache> cache);
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    /// Evaluates one rtrace input ray. `dir` must be unit. `rmax` > 0 limits the
    /// ray length (-ld); 0 means unlimited. `rayIndex` (position in the input)
    /// seeds the random numbers so results do not depend on scheduling.
    /// With IrradianceMode::Immediate the origin and direction are taken as a
    /// measurement point and surface normal (-I, radiance-notes.md §1.9).
    RayResult TraceInput(const Vec3& org, const Vec3& dir, double rmax,
                         std::uint64_t rayIndex);

    /// Called for every ray when its evaluation finishes (post-order: children
    /// before parents), for rtrace's -ot/-oT output. `shadowRays` also reports
    /// shadow rays (-oT). Pass an empty function to turn tracing off.
    void SetTraceCallback(std::function<void(const RayResult&)> callback, bool shadowRays);

    /// Counters for the end-of-run report.
    const RenderStats& Stats() const;
    /// Measure where time goes (RenderStats::seconds*); the clock reads cost
    /// time of their own.
    void EnableTiming(bool on);

    /// Records this Renderer created since the last call, for the ambient file.
    std::vector<AmbientRecord> TakeNewRecords();
    /// Whether new records are kept for TakeNewRecords() (default true); off
    /// when no ambient file will take them.
    void QueueNewRecords(bool on);

    /// A copy of every record in the (possibly shared) cache, e.g. to draw
    /// where the cache put them; empty without a cache.
    std::vector<AmbientRecord> CacheRecords() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace rt
