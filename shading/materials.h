// SPDX-License-Identifier: MIT
//
// Internal to shading/: Radiance's materials (radiance-notes.md §2.7–2.8),
// one shader per type, dispatched through a table. A shader reads its
// material's typed parameters (scene.h), the ray's pattern colour and
// perturbation, traces its child rays through `tree`, and asks the tree's
// DirectLight and IndirectLight for the light at its point.
#pragma once

#include "core/function_ref.h"
#include "core/vecmath.h"
#include "scene/scene.h"
#include "shading/shading_state.h"
#include "shading/traced_ray.h"

namespace rt {

class RayTree;

/// Shades `ray` with material `m` by its type (not its modifier chain:
/// RayTree::ShadeMaterial applies that first).
void ShadeByType(const RayTree& tree, ThreadState& ts, TracedRay& ray, const Material& m);

/// plastic, metal and trans (normal.c); also the -i/-I Lambertian meter.
void ShadeNormal(const RayTree& tree, ThreadState& ts, TracedRay& ray, const Material& m);

/// What every diffusely reflecting material ends with, in Radiance's order:
/// the ambient term on the ray's side with coefficient `*front` about
/// `normal`, on the other side with `*back` (the surface turned around for
/// it), then, if `addDirect`, the direct light through `coefficient`. A null
/// coefficient skips its term.
void AddIndirectAndDirect(const RayTree& tree, ThreadState& ts, TracedRay& ray, const Vec3& normal,
                          const Rgb* front, const Rgb* back,
                          FunctionRef<Rgb(const Vec3&, double)> coefficient,
                          bool addDirect = true);

/// plastic2, metal2 and trans2 (m_aniso.c), in aniso.cpp.
void ShadeAniso(const RayTree& tree, ThreadState& ts, TracedRay& ray, const Material& m);

/// plasfunc, metfunc, transfunc, plasdata, metdata, transdata (m_brdf.c's
/// m_brdf2()), in brdf.cpp.
void ShadeBrdf(const RayTree& tree, ThreadState& ts, TracedRay& ray, const Material& m);
/// BRTDfunc (m_brdf.c's m_brdf()), in brdf.cpp.
void ShadeBrtd(const RayTree& tree, ThreadState& ts, TracedRay& ray, const Material& m);

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
