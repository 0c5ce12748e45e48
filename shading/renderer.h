// SPDX-License-Identifier: MIT
//
// The radiance integrator: Radiance's ray tree (raytrace.c), its materials
// (normal.c, m_mirror.c, glass.c, dielectric.c, source.c m_light) and its
// direct calculation (source.c, srcsamp.c, srcsupp.c). One Renderer per
// thread or process: it carries source hit statistics and random state.
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

    /// `scene` and `core` must outlive the Renderer. Finds the light sources
    /// (warning "no light sources found" through `warn` when there are none).
    /// `cache` is from MakeCache (possibly shared); by default a private one.
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

    /// A copy of every record in the (possibly shared) cache, e.g. to draw
    /// where the cache put them; empty without a cache.
    std::vector<AmbientRecord> CacheRecords() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace rt
