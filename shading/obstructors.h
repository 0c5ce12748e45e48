// SPDX-License-Identifier: MIT
//
// Internal to shading/: the layout of Radiance's obstructor ("shadow") cache
// (srcobstr.c, radiance-notes.md §3.6). For each light source a table of
// cells, each holding the last reliable opaque surface found blocking rays
// toward the source through that cell. Before a sample of a whole
// (unpartitioned) source is shadow-tested, the cell's surface is intersected
// with the sample ray; if it lies in front of the source the sample is
// dropped, without a shadow ray and without entering the source's hit
// statistics. Dropping changes which samples the -dt test counts, so the
// cache changes answers at -dt > 0 the way it does in Radiance; at -dt 0 it
// only saves shadow rays.
//
// This header holds the geometry only (cells, and the ray that fills a cell
// when it is first looked up); DirectLight keeps the tables, one set per
// thread.
#pragma once

#include "core/vecmath.h"
#include "scene/scene.h"
#include "shading/light_sources.h"

namespace rt {

/// Cells along one side of a table (Radiance's SHADCACHE).
inline constexpr int kObstructorResolution = 20;

/// How one source's table divides the rays that reach it.
struct ObstructorLayout {
    enum class Kind {
        None,     // not cached: skipped, proximity (glow), spot and virtual sources
        Distant,  // (2R)² cells over a plane perpendicular to the source's main axis
        Flat,     // 3R² cells of directions over the front half of a cube around the normal
        Radial,   // 6R² cells of directions over a whole cube (spheres, cylinders)
    };
    Kind kind = Kind::None;
    // Distant: the plane's axis and the two along it, its corner, and the
    // inverse widths (1/length) of the region the cells cover.
    int axis = 0, axis1 = 1, axis2 = 2;
    Vec3 corner;
    double inverseWidth1 = 0, inverseWidth2 = 0;
    Vec3 toSource;  // unit direction to the source
    // Flat: unit vectors across the source (u, v) and its normal.
    Vec3 u, v, normal;

    int CellCount() const;
    /// The cell of a ray from `org` toward the source along unit `dir`, or -1
    /// when it has none (a distant source's ray from outside the region, a
    /// flat source's ray from behind it).
    int Cell(const Vec3& org, const Vec3& dir) const;
};

/// Radiance's initobscache() parameters for `src`, in a scene whose octree
/// cube is `cubeOrigin`, `cubeSize`.
ObstructorLayout MakeObstructorLayout(const LightSource& src, const Vec3& cubeOrigin,
                                      double cubeSize);

/// A ray cast outward from a source to fill one cell.
struct ObstructorFillRay {
    Vec3 org;
    Vec3 dir;  // unit, away from the source
};

/// The ray initobscache() casts outward from `src` for `cell` (in
/// [0, CellCount())): the first reliable blocker along it, as if it had
/// stopped a ray aimed back at the source, is the cell's first entry. Each
/// of Radiance's fill rays writes only its own cell, so filling a cell when
/// it is first needed gives the table Radiance fills whole at the source's
/// first use, for a fraction of the rays when there are many sources.
ObstructorFillRay MakeObstructorFillRay(const ObstructorLayout& layout, const LightSource& src,
                                        int cell);

/// True if `surface` (one of the scene's own) may be recorded as a blocker:
/// its material is one Radiance marks opaque (plastic, metal, plastic2,
/// metal2, ashik2, plasfunc, metfunc, plasdata, metdata, light, spotlight)
/// with no mixture on the way to it, and no antimatter may clip it.
bool IsReliableBlocker(const Scene& scene, const Surface& surface);

}  // namespace rt
