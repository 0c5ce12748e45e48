// SPDX-License-Identifier: MIT
//
// Internal to shading/: function modifiers at a hit (radiance-functions.md
// §10.3, §11.1-11.9; Radiance's p_func.c, p_data.c, t_func.c, mx_func.c and
// raymixture()).
#pragma once

#include <optional>
#include <vector>

#include "shading/shading_state.h"
#include "shading/traced_ray.h"

namespace rt {

class RayTree;

/// Evaluates `modifiers` (indices into Scene::patterns) for this ray in chain
/// order: patterns multiply ray.pcol, textures add to ray.pert, mixtures
/// shade both sides through `tree`. True when a mixture reached a material
/// and so shaded the ray: the chain ends there.
bool ApplyModifierChain(const RayTree& tree, ThreadState& ts, TracedRay& ray,
                        const std::vector<int>& modifiers);

/// An anisotropic material's u direction at this hit (Radiance's
/// getacoords() before the projection into the surface): orientation
/// function `index` (Scene::patterns) evaluated in its space and turned into
/// render space, not normalised; zero after a math error.
Vec3 EvaluateOrientation(const Scene& scene, ThreadState& ts, const TracedRay& ray, int index);

/// A BSDF material's frame at this hit (m_bsdf.c): the thickness (0 for
/// aBSDF and below FTINY) and the up vector, from frame function `index`
/// (four values: thickness first; three: aBSDF), both turned and scaled
/// into render space by the function's transform and the instance's.
/// Values as computed after a math error, as Radiance uses them.
struct BsdfFrame {
    double thickness = 0;
    Vec3 up;
};
BsdfFrame EvaluateBsdfFrame(const Scene& scene, ThreadState& ts, const TracedRay& ray, int index);

/// What a BRDF material's function sees of the point besides the ray
/// (radiance-functions.md §10.4): NxP…, RdotP, CrP….
struct BrdfInputs {
    Vec3 normal;     // perturbed unit normal, render space
    double cosine;   // -D·N' (clamped to [-1, 1] for RdotP)
    Rgb color;       // material colour times pattern colour
};

/// BRDF function `index` (Scene::patterns, PatternType::Brdf or Brtd) for light
/// arriving from unit `ldir` (render space) with solid angle `omega`:
/// func(lx, ly, lz, omega) with the direction in the function's space (grey),
/// for the *data types func(value at the coordinates, lx, ly, lz, omega),
/// for BRTDfunc one function per channel. Nothing after a math error.
std::optional<Rgb> EvaluateBrdf(const Scene& scene, ThreadState& ts, const TracedRay& ray,
                                int index, const BrdfInputs& in, const Vec3& ldir,
                                double omega);

/// BRTDfunc's expressions `first` … `first + 2` (0: reflection, 3:
/// transmission) at this ray, with the BRDF variables set. Nothing after a
/// math error.
std::optional<Rgb> EvaluateBrdfColour(const Scene& scene, ThreadState& ts, const TracedRay& ray,
                                      int index, const BrdfInputs& in, int first);

/// One of a prism's redirections (m_direct.c's redirect() and dir_proj()).
struct Redirection {
    enum class Outcome { Redirected, Insignificant, MathError };
    Outcome outcome = Outcome::Insignificant;
    double coefficient = 0;  // the coefficient expression's value
    Vec3 dir;                // new direction, render space, not normalised
};

/// prism1/prism2 function `index` (Scene::patterns, PatternType::Redirect),
/// redirection `n` (0 or 1), for this ray, with DxA… the unit render-space
/// `sourceDir` in the function's space (zero: the ray aims at no source).
/// As Radiance: the coefficient first, Insignificant at or below FTINY
/// (the direction then not evaluated), MathError after one in either.
/// `context` is the caller's (a thread's, or the source set-up's own).
Redirection EvaluateRedirection(const Scene& scene, cal::Context& context, const TracedRay& ray,
                                int index, int n, const Vec3& sourceDir);

}  // namespace rt
