// SPDX-License-Identifier: MIT
//
// Internal to shading/: Radiance's ray tree (raytrace.c): rayorigin()
// limits, raytrace(), rayshade(), raytrans(), sourcehit() and the -I/-i
// irradiance modes (radiance-notes.md §1.9, §2.5). The tree walks from ray
// to surface to modifiers (patterns.h) to material (materials.h), whose
// shaders trace child rays through it and ask DirectLight and IndirectLight
// for the light arriving at their point.
//
// A RayTree holds only the read-only ShadingSetup; every call that changes
// something takes the calling thread's ThreadState.
#pragma once

#include <cstdint>
#include <vector>

#include "core/rgb.h"
#include "core/vecmath.h"
#include "scene/scene.h"
#include "shading/direct.h"
#include "shading/indirect.h"
#include "shading/patterns.h"
#include "shading/ray_result.h"
#include "shading/shading_state.h"
#include "shading/traced_ray.h"

namespace rt {

/// Radiance's "zero ray weight in Russian roulette" (rayorigin()): -lr <= 0
/// with -lw <= 0 at the first ray that carries a coefficient.
[[noreturn]] void ThrowZeroWeightRoulette();

class RayTree {
public:
    /// `setup` must outlive the tree.
    explicit RayTree(const ShadingSetup& setup) : s_(setup), direct_(setup, *this),
                                                  indirect_(setup, *this) {}
    RayTree(const RayTree&) = delete;
    RayTree& operator=(const RayTree&) = delete;

    /// Evaluates one rtrace input ray (see Renderer::TraceInput).
    RayResult TraceInput(ThreadState& ts, const Vec3& org, const Vec3& dir, double rmax,
                         std::uint64_t rayIndex) const;

    /// Radiance's rayorigin(): sets up `child` from `parent`; false if the ray
    /// must not be traced (weight limits, Russian roulette). `coef` may be null.
    bool StartChild(ThreadState& ts, TracedRay& child, const TracedRay& parent, unsigned type,
                    const Rgb* coef) const;
    /// Traces and shades `ray` (raytrace()): closest hit, distant sources, trace callback.
    void Trace(ThreadState& ts, TracedRay& ray) const;
    /// What Cast() found.
    enum class Met { Surface, DistantSource, Nothing };
    /// Radiance's raycast(): the first intersection only (or the distant
    /// source the ray points at), nothing shaded; Trace() shades what it met.
    Met Cast(ThreadState& ts, TracedRay& ray) const;
    /// Shades a ray that hit `ray.surface` (rayshade()); with -i, Lamb replaces materials.
    void Shade(ThreadState& ts, TracedRay& ray) const;
    /// Pass-through (raytrans()): continues the ray unchanged past the surface.
    void PassThrough(ThreadState& ts, TracedRay& ray) const { PassThrough(ts, ray, ray.clip); }
    /// The same, the continuing ray and its children passing the surfaces
    /// `clip` names instead of the ray's own (antimatter; TracedRay::clip).
    void PassThrough(ThreadState& ts, TracedRay& ray, const std::vector<int>* clip) const;
    /// The same, the continuing ray and its children travelling through
    /// `beyond` (mist: the medium on the surface's other side).
    void PassThrough(ThreadState& ts, TracedRay& ray, const Medium& beyond) const;
    /// Applies the material's own chain, then shades with it (materials.h).
    void ShadeMaterial(ThreadState& ts, TracedRay& ray, const Material& m) const;
    /// ShadeMaterial, except that with -i the first opaque surface reached by a
    /// primary or transmitted ray is measured instead (rayshade()'s Lamb hack).
    void ShadeSurfaceMaterial(ThreadState& ts, TracedRay& ray, const Material& m) const;
    /// Evaluates a modifier chain (patterns.h); true when a mixture shaded the
    /// ray. Inline for the common case of an empty chain: it runs at every hit.
    bool ApplyModifiers(ThreadState& ts, TracedRay& ray, const std::vector<int>& modifiers) const {
        return !modifiers.empty() && ApplyModifierChain(*this, ts, ray, modifiers);
    }
    /// Radiance's rayparticipate(): the medium's extinction over the ray's
    /// length `rot`, then, for rays other than shadow rays, the light it
    /// scatters in from the -av ambient value and from the light sources
    /// it lists (mist). No medium: nothing.
    void Participate(ThreadState& ts, TracedRay& ray) const {
        if (ray.medium) ParticipateIn(ts, *ray.medium, ray);
    }
    /// Participate() through `medium` instead of the ray's own.
    void ParticipateIn(ThreadState& ts, const Medium& medium, TracedRay& ray) const;
    /// The share of a shadow ray's light that crosses `distance` of
    /// `medium` (scattering counts as no loss for shadow rays, as Radiance).
    static Rgb ShadowTransmittance(const Medium& medium, double distance);
    /// Hands a finished ray to the trace callback (-ot/-oT), if any; shadow
    /// rays only with -oT.
    void Report(ThreadState& ts, const TracedRay& ray) const;
    /// Report() for a shadow ray that met something other than its source and
    /// was followed past it (Radiance's raycont() in direct()): reported with
    /// -ot too, as Radiance's trace hook sees it.
    void ReportFollowedShadow(ThreadState& ts, const TracedRay& ray) const;
    /// The factor by which a ray's path through a medium lowers the weight of
    /// the rays it starts, shadow rays included (rayorigin()'s extinction
    /// estimate: exp(−σ·length) from the clearest channel, 1 below 0.1, 0
    /// beyond 92).
    static double MediumImportance(const TracedRay& parent);
    /// With -oT, reports a shadow ray that met nothing on its way to a
    /// distant source as the source it reaches, shaded (Radiance's direct()
    /// traces such rays when sources are followed); the answer is unchanged.
    void ReportShadowAtDistantSource(ThreadState& ts, TracedRay& ray) const;

    const ShadingSetup& setup() const { return s_; }
    const DirectLight& direct() const { return direct_; }
    const IndirectLight& indirect() const { return indirect_; }

private:
    /// The rest of PassThrough: `child`, started from `ray`, goes on in the
    /// same direction, and its results become the ray's.
    void Continue(ThreadState& ts, TracedRay& ray, TracedRay& child) const;
    /// Radiance's srcscatter(): the light of the medium's sources scattered
    /// into the ray over its length, sampled at points along it.
    void ScatterSourceLight(ThreadState& ts, const Medium& medium, TracedRay& ray) const;
    /// Looks for a distant source in the ray's direction (sourcehit()).
    bool HitDistantSource(TracedRay& ray) const;
    /// Shades a ray HitDistantSource() aimed at its source: the source's
    /// modifiers, then its material.
    void ShadeDistantSource(ThreadState& ts, TracedRay& ray) const;
    /// -I: a measuring point lying in the plane of a wall (a sensor on an
    /// edge or in a corner) would send half its sample rays through that
    /// wall, whose hit at t = 0 the self-hit rule discards. Moves the point
    /// `offset` off each such wall, to the side where the surface under the
    /// sensor continues; elsewhere returns it unchanged.
    Vec3 OffWallsThroughSensor(Vec3 point, const Vec3& normal, double offset) const;
    /// Not const in `ts`: the shading normal it prints may warn (PerturbedNormal).
    RayResult MakeResult(ThreadState& ts, const TracedRay& ray) const;

    const ShadingSetup& s_;
    DirectLight direct_;
    IndirectLight indirect_;
};

}  // namespace rt
