// SPDX-License-Identifier: MIT
//
// Internal to shading/: Radiance's direct calculation (source.c direct(),
// srcvalue(), raycont() for shadow rays); radiance-notes.md §3.3–3.4.
#pragma once

#include "core/function_ref.h"
#include "core/rgb.h"
#include "core/vecmath.h"
#include "shading/shading_state.h"
#include "shading/traced_ray.h"

namespace rt {

class RayTree;

class DirectLight {
public:
    /// Both must outlive this object; `tree` shades what shadow rays meet.
    DirectLight(const ShadingSetup& setup, const RayTree& tree) : s_(setup), tree_(tree) {}

    /// Radiance's direct(): adds to ray.rcol the contribution of every light
    /// source sample, `coef(ldir, omega)` giving the material's coefficient
    /// for a unit direction to the source and the solid angle (sr) the sample
    /// stands for.
    void Add(ThreadState& ts, TracedRay& ray, FunctionRef<Rgb(const Vec3&, double)> coef) const;

private:
    void AddUntimed(ThreadState& ts, TracedRay& ray,
                    FunctionRef<Rgb(const Vec3&, double)> coef) const;
    /// Radiance's aiming count for `source` (SourceTally): one sample ray
    /// that did or did not `hit` it.
    void CountAim(ThreadState& ts, int source, bool hit) const;
    /// Radiance's srcvalue(): radiance arriving along a source ray aimed at
    /// `source`, whose sample point lies `distance` away.
    Rgb SourceValue(ThreadState& ts, TracedRay& sray, int source, double distance) const;
    /// srcvalue() for a virtual `source`: radiance arriving along `sray`
    /// through the mirror or prism that relays it (black if the ray misses it).
    Rgb RelayValue(ThreadState& ts, TracedRay& sray, int source) const;

    const ShadingSetup& s_;
    const RayTree& tree_;
};

}  // namespace rt
