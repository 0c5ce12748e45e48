// SPDX-License-Identifier: MIT
//
// The plane of a scene's light-source polygons (ceiling luminaires, a
// window's glow). A shadow ray toward such a source stops just short of the
// source, so it lies wholly on one side of the source's plane, and a segment
// with both ends strictly on one side of a plane cannot meet anything lying
// in that plane. Its occlusion test may therefore skip every polygon in the
// plane: above all the source itself, which otherwise sits at the far end of
// every one of those rays and costs each an exact test that always rejects.
#pragma once

#include <algorithm>
#include <optional>
#include <vector>

#include "core/vecmath.h"
#include "scene/scene.h"

namespace rt {

struct SourcePlane {
    Vec3 normal;  // unit: one light-source polygon's own normal
    double offset = 0;
    /// Polygon surfaces whose plane equals this one (within the scene's
    /// rounding), light sources or not.
    std::vector<int> surfaces;
    /// Size of the scene's coordinates (see FindSourcePlane).
    double scale = 1;

    /// True if the segment from `a` to `b` cannot meet a polygon in the plane:
    /// both ends lie on one side of it by a clearance that exceeds, a
    /// hundredfold, both the rounding of the exact polygon test and the
    /// differences between the planes of the polygons taken as lying in it.
    bool Clears(const Vec3& a, const Vec3& b) const {
        const double clearance =
            kClearance * std::max(scale, std::max(MaxAbs(a), MaxAbs(b)));
        const double da = Dot(normal, a) - offset, db = Dot(normal, b) - offset;
        return (da > clearance && db > clearance) || (da < -clearance && db < -clearance);
    }

    /// Relative clearance: far above the plane differences allowed (1e-12)
    /// and a dot product's rounding, far below the distance by which shadow
    /// rays stop short of their source (1e-7 of their length).
    static constexpr double kClearance = 1e-9;
};

/// The plane of the largest light-source polygon among the surfaces not
/// marked in `leftOut` (a light material on a polygon: light, illum, glow,
/// spotlight), with every such polygon lying in the same plane; nothing if
/// there is no such polygon. `scale` is the size of the scene's coordinates
/// (the largest absolute coordinate or the scene's extent, whichever is
/// larger) and sets the rounding allowances.
std::optional<SourcePlane> FindSourcePlane(const Scene& scene, const std::vector<bool>& leftOut,
                                           double scale);

}  // namespace rt
