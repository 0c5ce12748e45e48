// SPDX-License-Identifier: MIT
//
// Internal to shading/: function modifiers at a hit (radiance-functions.md
// §10.3, §11.1-11.9; Radiance's p_func.c, p_data.c, t_func.c, mx_func.c and
// raymixture()).
#pragma once

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

}  // namespace rt
