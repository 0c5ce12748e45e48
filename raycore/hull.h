// SPDX-License-Identifier: MIT
//
// The scene's bounding polygons: polygons whose plane has the whole scene on
// one side, such as the walls, floor and ceiling of a room. A straight segment
// between two points on the inner side of such a plane never crosses it (a
// half-space is convex), so occlusion tests between points of the scene need
// not look at these polygons at all. In a room they are the biggest surfaces,
// and their boxes, as large as the room, make every traversal of a bounding
// volume hierarchy that holds them test them; leaving them out made shadow
// rays in the Cornell box about 2.5 times cheaper in Embree.
#pragma once

#include <limits>
#include <vector>

#include "core/vecmath.h"
#include "scene/scene.h"

namespace rt {

/// A plane with its inner side: Dot(normal, x) >= offset.
struct InnerHalfSpace {
    Vec3 normal;  // unit, pointing into the scene
    double offset = 0;

    /// Signed distance of `x` from the plane, positive on the inner side.
    double Distance(const Vec3& x) const { return Dot(normal, x) - offset; }
};

struct BoundingPolygons {
    std::vector<int> surfaces;            // polygon surfaces lying in one of the planes
    std::vector<InnerHalfSpace> planes;   // distinct planes, largest polygons first
    double margin = 0;                    // points this far outside still count as inside
    /// The axis-aligned planes as a box (infinite where there is none), widened
    /// by the margin: rooms are mostly boxes, and Inside() runs twice per
    /// shadow ray.
    Vec3 boxLo{-kInfinity, -kInfinity, -kInfinity}, boxHi{kInfinity, kInfinity, kInfinity};
    std::vector<InnerHalfSpace> oblique;  // the other planes

    /// True if `x` is on the inner side of every plane (within the margin).
    bool Inside(const Vec3& x) const {
        // Written as one expression so that it compiles to branch-free compares.
        const bool inBox = (x.x >= boxLo.x) & (x.y >= boxLo.y) & (x.z >= boxLo.z) &
                           (x.x <= boxHi.x) & (x.y <= boxHi.y) & (x.z <= boxHi.z);
        if (!inBox) return false;
        for (const InnerHalfSpace& p : oblique) {
            if (p.Distance(x) < -margin) return false;
        }
        return true;
    }

  private:
    static constexpr double kInfinity = std::numeric_limits<double>::infinity();
};

/// Finds bounding polygons among the scene's polygons, largest first. Every
/// surface's extent (polygon vertices, the corners of other shapes' boxes)
/// must lie on the inner side of the polygon's plane within `margin`, which
/// should be far below the scene's distance tolerance. The search is bounded:
/// at most `maxPlanes` distinct planes, and at most 4·maxPlanes candidate
/// polygons are checked (each check stops at the first point on the wrong
/// side), so it stays linear in the scene's size.
BoundingPolygons FindBoundingPolygons(const Scene& scene, double margin, int maxPlanes = 8);

}  // namespace rt
