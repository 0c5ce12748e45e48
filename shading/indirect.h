// SPDX-License-Identifier: MIT
//
// Internal to shading/: the indirect term, Radiance's multambient()
// (radiance-notes.md §4.1): the -av fallback and the -ae/-ai lists here, and
// the lazy irradiance cache's lookup-or-compute loop in ambient/
// (IrradianceCache), given how to trace a hemisphere ray and a leak ray.
#pragma once

#include "core/rgb.h"
#include "core/vecmath.h"
#include "shading/ray_result.h"
#include "shading/shading_state.h"
#include "shading/traced_ray.h"

namespace rt {

class RayTree;

class IndirectLight {
public:
    /// Both must outlive this object; `tree` traces the hemisphere rays.
    IndirectLight(const ShadingSetup& setup, const RayTree& tree) : s_(setup), tree_(tree) {}

    /// The indirect term A ⊗ E/π at a shaded point, for diffuse coefficient
    /// `coefficient` and shading normal `normal` (unit); with no ambient
    /// bounces this is the -av value. `otherRadiance` (may be null): what
    /// the point sends its viewer besides this term, for sizing deeper
    /// records (IrradianceCache::DeeperSampleFraction).
    Rgb Ambient(ThreadState& ts, const Rgb& coefficient, const TracedRay& ray, const Vec3& normal,
                const OtherRadianceRef* otherRadiance = nullptr) const;

private:
    /// The fallback where no bounce is computed: -av, or its -aw average.
    Rgb Fallback(const Rgb& coefficient) const;
    /// -ae/-ai: the hit surface's modifier keeps the -av value.
    bool Excluded(const TracedRay& ray) const;
    /// Keeps how the input ray's first shaded surface got its indirect light.
    static void Note(ThreadState& ts, RayResult::AmbientOutcome outcome, const Rgb& meanRadiance);

    const ShadingSetup& s_;
    const RayTree& tree_;
};

}  // namespace rt
