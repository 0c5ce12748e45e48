// SPDX-License-Identifier: MIT
//
// Internal to shading/: Radiance's direct calculation (source.c direct(),
// srcvalue(), raycont() for shadow rays); radiance-notes.md §3.3–3.4.
#pragma once

#include <vector>

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

    /// For light a medium scatters (Radiance's srcscatter()): whether this
    /// thread's obstructor cache knows a surface blocking the ray from `org`
    /// to `sample` (of a whole source), and, after a ray toward its source
    /// `sray.rsrc` came back black, recording the surface it met first.
    bool KnownBlocked(ThreadState& ts, const SourceSample& sample, const Vec3& org) const {
        return CachedBlocked(ts, sample.source, org, sample.dir, sample.distance);
    }
    void RecordBlockerOf(ThreadState& ts, const TracedRay& sray) const;

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

    // Radiance's obstructor cache (shading/obstructors.h, srcobstr.c).
    /// A table entry not filled yet; -1 is a cell with no blocker.
    static constexpr int kUnfilled = -2;
    /// This thread's table for `source` (kUnfilled entries at first).
    std::vector<int>& Obstructors(ThreadState& ts, int source) const;
    /// The surface in `cell` of `source`'s `table` (-1: none), found by the
    /// cell's fill ray (initobscache()'s) if the cell was never filled.
    int CachedSurface(std::vector<int>& table, int source, int cell) const;
    /// srcblocked(): whether the surface cached for the ray from `org` along
    /// unit `dir` toward `source` blocks it before `distance` (the sample
    /// point; any distance for a distant source).
    bool CachedBlocked(ThreadState& ts, int source, const Vec3& org, const Vec3& dir,
                       double distance) const;
    /// Whether `source` has a table (ObstructorLayout::Kind other than None).
    bool HasObstructors(int source) const {
        return s_.obstructorLayouts[static_cast<std::size_t>(source)].kind !=
               ObstructorLayout::Kind::None;
    }
    /// Whether `surface` of `instance` (-1: the scene's own) may be recorded
    /// for `source`: not in an instance, not the source itself, and
    /// IsReliableBlocker.
    bool IsRecordable(int source, int instance, int surface) const;
    /// srcblocker(): `surface` of `instance` is the first surface on the ray
    /// from `org` along `dir` toward `source`; if it IsRecordable it goes
    /// into the ray's cell.
    void RecordBlocker(ThreadState& ts, int source, const Vec3& org, const Vec3& dir,
                       int instance, int surface) const;
    /// After a shadow ray found an opaque surface within `reach`: finds the
    /// first one (the occlusion query does not say which) and records it.
    void RecordShadowBlocker(ThreadState& ts, int source, const Vec3& org, const Vec3& dir,
                             double reach, const Vec3* leaving) const;

    const ShadingSetup& s_;
    const RayTree& tree_;
};

}  // namespace rt
