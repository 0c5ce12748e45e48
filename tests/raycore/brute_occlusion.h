// SPDX-License-Identifier: MIT
//
// Brute-force occlusion for the tests of RayCore's shortcuts (bounding
// polygons, the light sources' plane, the furniture box): every surface's
// exact test, one by one.
#pragma once

#include <optional>
#include <random>

#include "core/vecmath.h"
#include "raycore/raycore.h"
#include "scene/scene.h"

namespace rt::testing {

/// Any surface hit in (tol, tmax).
inline bool BruteOccluded(const RayCore& core, const Scene& scene, const Vec3& org,
                          const Vec3& dir, double tmax) {
    for (int s = 0; s < static_cast<int>(scene.surfaces.size()); ++s) {
        const auto h = core.IntersectSurface(s, org, dir);
        if (h && h->t < tmax) return true;
    }
    return false;
}

/// Brute force, unless moving the segment sideways by 1e-5 changes the
/// answer: a segment that grazes an edge (the double test counts points within
/// 1e-6 of an edge as inside) or runs along a face has no robust answer, and
/// Embree's float test, whose outcome there also depends on the hierarchy's
/// boxes, may then differ either way. The moved segments are 1e-4 shorter at
/// each end, so that moving does not push their ends into the surfaces they
/// start and end on.
inline std::optional<bool> RobustBruteOccluded(const RayCore& core, const Scene& scene,
                                               const Vec3& org, const Vec3& dir, double tmax) {
    const bool answer = BruteOccluded(core, scene, org, dir, tmax);
    const Frame frame = Frame::Around(dir);
    for (const Vec3& side : {frame.u, -frame.u, frame.v, -frame.v}) {
        if (BruteOccluded(core, scene, org + side * 1e-5 + dir * 1e-4, dir, tmax - 2e-4) !=
            answer) {
            return std::nullopt;
        }
    }
    return answer;
}

/// Occlusion of the segment from `a` to `b` as a shadow ray tests it (stopping
/// 1e-7 of its length short of `b`), by RayCore and by brute force.
struct ShadowSegment {
    bool occluded;  // RayCore::Occluded
    bool expected;  // brute force
};
/// Nothing if the segment is shorter than 1e-3 or has no robust answer.
inline std::optional<ShadowSegment> CheckShadowSegment(const RayCore& core, const Scene& scene,
                                                       const Vec3& a, const Vec3& b) {
    const Vec3 d = b - a;
    const double length = Length(d);
    if (length < 1e-3) return std::nullopt;
    const Vec3 dir = d / length;
    const double tmax = length * (1 - 1e-7);
    const auto expected = RobustBruteOccluded(core, scene, a, dir, tmax);
    if (!expected) return std::nullopt;
    return ShadowSegment{core.Occluded(a, dir, tmax), *expected};
}

/// A point on some surface: the closest hit of a random ray from a random
/// point of the box [lo, hi], which must lie inside a closed scene.
template <typename Engine>
Vec3 RandomSurfacePoint(const RayCore& core, const Vec3& lo, const Vec3& hi, Engine& rng) {
    std::uniform_real_distribution<double> u(0, 1);
    for (;;) {
        const Vec3 org{lo.x + (hi.x - lo.x) * u(rng), lo.y + (hi.y - lo.y) * u(rng),
                       lo.z + (hi.z - lo.z) * u(rng)};
        std::normal_distribution<double> g;
        const Vec3 dir = Normalize(Vec3{g(rng), g(rng), g(rng)});
        if (auto h = core.Intersect(org, dir, 0)) return h->point;
    }
}

}  // namespace rt::testing
