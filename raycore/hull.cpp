// SPDX-License-Identifier: MIT
#include "raycore/hull.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "raycore/shapes.h"

namespace rt {
namespace {

/// Points whose inner side decides for every surface: polygon vertices, and
/// the eight corners of the bounding box of any other shape (the box holds
/// the shape, so if its corners are inside, so is the shape). Distant sources
/// are not geometry; instances count by their placed cubes.
void AddCorners(std::vector<Vec3>& points, const Bounds3& b) {
    if (b.Empty()) return;
    for (int corner = 0; corner < 8; ++corner) {
        points.push_back({corner & 1 ? b.hi.x : b.lo.x, corner & 2 ? b.hi.y : b.lo.y,
                          corner & 4 ? b.hi.z : b.lo.z});
    }
}

std::vector<Vec3> ExtremePoints(const Scene& scene) {
    std::vector<Vec3> points;
    for (const Surface& surface : scene.surfaces) {
        if (surface.type == SurfaceType::Source) continue;
        if (const auto* polygon = std::get_if<Polygon>(&surface.shape)) {
            points.insert(points.end(), polygon->vertices.begin(), polygon->vertices.end());
            continue;
        }
        AddCorners(points, ShapeBounds(surface));
    }
    // An instance lies within its placed cube.
    for (const Instance& instance : scene.instances) AddCorners(points, InstanceBounds(scene, instance));
    return points;
}

/// The inner half-space of `polygon`'s plane if every point lies on one side
/// of it (within `margin`), else nothing.
std::optional<InnerHalfSpace> BoundingSide(const Polygon& polygon,
                                           const std::vector<Vec3>& points, double margin) {
    bool front = true, back = true;  // every point so far on that side
    for (const Vec3& x : points) {
        const double s = Dot(polygon.normal, x) - polygon.offset;
        if (s < -margin) front = false;
        if (s > margin) back = false;
        if (!front && !back) return std::nullopt;
    }
    if (front) return InnerHalfSpace{polygon.normal, polygon.offset};
    return InnerHalfSpace{-polygon.normal, -polygon.offset};
}

}  // namespace

BoundingPolygons FindBoundingPolygons(const Scene& scene, double margin, int maxPlanes) {
    BoundingPolygons result;
    result.margin = margin;
    std::vector<int> candidates;
    for (int i = 0; i < static_cast<int>(scene.surfaces.size()); ++i) {
        const auto* polygon = std::get_if<Polygon>(&scene.surfaces[static_cast<size_t>(i)].shape);
        // A plane that is not finite bounds nothing (and can never be hit).
        if (polygon && IsFinite(polygon->normal) && std::isfinite(polygon->offset)) {
            candidates.push_back(i);
        }
    }
    if (candidates.empty() || maxPlanes <= 0) return result;
    const auto area = [&](int i) {
        return std::get<Polygon>(scene.surfaces[static_cast<size_t>(i)].shape).area;
    };
    const size_t checks = std::min(candidates.size(), 4 * static_cast<size_t>(maxPlanes));
    std::partial_sort(candidates.begin(), candidates.begin() + static_cast<long>(checks),
                      candidates.end(), [&](int a, int b) {
                          return area(a) != area(b) ? area(a) > area(b) : a < b;
                      });
    candidates.resize(checks);

    const std::vector<Vec3> points = ExtremePoints(scene);
    for (int i : candidates) {
        const auto& polygon = std::get<Polygon>(scene.surfaces[static_cast<size_t>(i)].shape);
        const auto side = BoundingSide(polygon, points, margin);
        if (!side) continue;
        // Coplanar bounding polygons share one plane.
        const auto same = std::find_if(result.planes.begin(), result.planes.end(),
                                       [&](const InnerHalfSpace& p) {
                                           return Dot(p.normal, side->normal) > 1 - 1e-12 &&
                                                  std::fabs(p.offset - side->offset) <= margin;
                                       });
        if (same == result.planes.end()) {
            if (static_cast<int>(result.planes.size()) >= maxPlanes) continue;
            result.planes.push_back(*side);
        }
        result.surfaces.push_back(i);
    }
    std::sort(result.surfaces.begin(), result.surfaces.end());
    for (const InnerHalfSpace& p : result.planes) {
        // An axis-aligned plane, inner side +axis (x[axis] >= offset) or
        // -axis (x[axis] <= -offset), goes into the box.
        int axis = -1;
        for (int k = 0; k < 3; ++k) {
            if (std::fabs(p.normal[k]) == 1.0 && p.normal[(k + 1) % 3] == 0.0 &&
                p.normal[(k + 2) % 3] == 0.0) {
                axis = k;
            }
        }
        if (axis < 0) {
            result.oblique.push_back(p);
        } else if (p.normal[axis] > 0) {
            result.boxLo[axis] = std::max(result.boxLo[axis], p.offset - margin);
        } else {
            result.boxHi[axis] = std::min(result.boxHi[axis], -p.offset + margin);
        }
    }
    return result;
}

}  // namespace rt
