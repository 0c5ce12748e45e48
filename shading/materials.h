// SPDX-License-Identifier: MIT
//
// Internal to shading/: Radiance's materials (radiance-notes.md §2.7–2.8),
// one shader per type, dispatched through a table. A shader reads its
// material's typed parameters (scene.h), the ray's pattern colour and
// perturbation, traces its child rays through `tree`, and asks the tree's
// DirectLight and IndirectLight for the light at its point.
#pragma once

#include <optional>

#include "core/vecmath.h"
#include "scene/scene.h"
#include "shading/ray_tree.h"
#include "shading/shading_state.h"
#include "shading/traced_ray.h"

namespace rt {

/// Shades `ray` with material `m` by its type (not its modifier chain:
/// RayTree::ShadeMaterial applies that first).
void ShadeByType(const RayTree& tree, ThreadState& ts, TracedRay& ray, const Material& m);

/// plastic, metal and trans (normal.c); also the -i/-I Lambertian meter.
void ShadeNormal(const RayTree& tree, ThreadState& ts, TracedRay& ray, const Material& m);

/// What every diffusely reflecting material ends with, in Radiance's order:
/// the ambient term on the ray's side with coefficient `*front` about
/// `normal`, on the other side with `*back` (the surface turned around for
/// it), then, if `addDirect`, the direct light through `coefficient` (the
/// material's callable (const Vec3& ldir, double omega) -> Rgb). A null
/// coefficient skips its term. Inline: plastic's shading is on every path.
template <class Coefficient>
inline void AddIndirectAndDirect(const RayTree& tree, ThreadState& ts, TracedRay& ray,
                                 const Vec3& normal, const Rgb* front, const Rgb* back,
                                 Coefficient& coefficient, bool addDirect = true) {
    if (front) {
        // What the point sends its viewer besides the ambient term: what the
        // ray has so far and the direct light, computed on a copy, only when
        // a deeper record is about to be made (the direct light is added
        // after the ambient term, as Radiance does, for -dt's test).
        const auto other = [&]() {
            TracedRay copy = ray;
            tree.direct().Add(ts, copy, coefficient);
            return Bright(copy.rcol);
        };
        const OtherRadianceRef otherRef(other);
        ray.rcol += tree.indirect().Ambient(ts, *front, ray, normal, &otherRef);
    }
    if (back) {
        // The back side's deeper records are sampled in full: the direct
        // light belongs to the front side's viewer.
        ray.FlipSurface();
        ray.rcol += tree.indirect().Ambient(ts, *back, ray, -normal);
        ray.FlipSurface();
    }
    if (addDirect) tree.direct().Add(ts, ray, coefficient);
}

/// plastic2, metal2 and trans2 (m_aniso.c), in aniso.cpp.
void ShadeAniso(const RayTree& tree, ThreadState& ts, TracedRay& ray, const Material& m);

/// ashik2 (ashikhmin.c), in aniso.cpp.
void ShadeAshik(const RayTree& tree, ThreadState& ts, TracedRay& ray, const Material& m);

/// plasfunc, metfunc, transfunc, plasdata, metdata, transdata (m_brdf.c's
/// m_brdf2()), in brdf.cpp.
void ShadeBrdf(const RayTree& tree, ThreadState& ts, TracedRay& ray, const Material& m);
/// BRTDfunc (m_brdf.c's m_brdf()), in brdf.cpp.
void ShadeBrtd(const RayTree& tree, ThreadState& ts, TracedRay& ray, const Material& m);

/// BSDF and aBSDF (m_bsdf.c), in bsdf.cpp.
void ShadeBsdf(const RayTree& tree, ThreadState& ts, TracedRay& ray, const Material& m);

/// Radiance's back-face rule for materials shaded from either side: a ray
/// meeting the surface's back is passed straight through with -bv-, and
/// otherwise the surface is turned to face it. False when the ray was
/// passed: nothing is left to shade. Inline: it runs at every such hit.
inline bool FaceTheRay(const RayTree& tree, ThreadState& ts, TracedRay& ray) {
    if (ray.rod >= 0.0) return true;
    if (!tree.setup().shading.backfaceVisible) {
        tree.PassThrough(ts, ray);
        return false;
    }
    ray.FlipSurface();
    return true;
}

/// Attempts per rough specular sample before giving up (Radiance's MAXITER).
inline constexpr int kMaxSpecularTries = 10;

/// Adds the sampled rays of a rough specular lobe to the ray's value
/// (Radiance's sampling loops without a per-sample weight): `n` samples of
/// coefficient `coef` each, directions from `draw()` (none: the sample was
/// rejected and is drawn again), at most kMaxSpecularTries·n draws; stops
/// early if the ray tree refuses a ray.
/// One sampled specular ray of coefficient `coef` toward `dir` (made unit
/// here, and returned in `*unit` if given): its value times its
/// coefficient; none when the ray tree refuses it (rayorigin()'s limits).
std::optional<Rgb> TraceSpecularSample(const RayTree& tree, ThreadState& ts,
                                       const TracedRay& ray, const Rgb& coef, const Vec3& dir,
                                       Vec3* unit = nullptr);

template <class Draw>
inline void AddLobeSamples(const RayTree& tree, ThreadState& ts, TracedRay& ray, const Rgb& coef,
                           int n, Draw&& draw) {
    for (int tries = 0, done = 0; done < n && tries < kMaxSpecularTries * n; ++tries) {
        const std::optional<Vec3> dir = draw();
        if (!dir) continue;
        const auto value = TraceSpecularSample(tree, ts, ray, coef, *dir);
        if (!value) break;
        ray.rcol += *value;
        ++done;
    }
}

/// Sample rays a rough specular lobe of coefficient `coef` gets: one, or
/// with -ss above 1.5 about -ss times the ray's weight, each kept above -lw
/// (Radiance's nstarget in normal.c and m_aniso.c).
int LobeSamples(const ShadingSetup& setup, const TracedRay& ray, const Rgb& coef);

/// Radiance's isflat() for the surface a ray hit: polygons (mesh triangles
/// shading with their own material among them) and rings. Flat surfaces
/// widen highlights by the source's size.
bool IsFlatHit(const Scene& scene, const TracedRay& ray);

/// Radiance's raynormal(): sets `normal` to the shading normal N' =
/// normalize(ron + pert), reflected in the plane normal to the ray if the
/// perturbation tipped it to the ray's other side, and returns -dir·N'
/// (unclamped, same sign as rod). A sum of zero length warns once per
/// surface (through `ts`) and gives ron and rod.
double PerturbedNormal(const Scene& scene, ThreadState& ts, const TracedRay& ray, Vec3& normal);

}  // namespace rt
