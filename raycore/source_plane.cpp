// SPDX-License-Identifier: MIT
#include "raycore/source_plane.h"

#include <cmath>

namespace rt {
namespace {

/// Planes that differ by less than this (relative to the coordinates) are
/// one plane: polygons built from the same coordinates agree to ~1e-16.
constexpr double kSamePlane = 1e-12;

const Polygon* FinitePolygon(const Surface& surface) {
    const auto* polygon = std::get_if<Polygon>(&surface.shape);
    if (!polygon || !IsFinite(polygon->normal) || !std::isfinite(polygon->offset)) return nullptr;
    return polygon;
}

}  // namespace

std::optional<SourcePlane> FindSourcePlane(const Scene& scene, const std::vector<bool>& leftOut,
                                           double scale) {
    const Polygon* largest = nullptr;
    for (size_t i = 0; i < scene.surfaces.size(); ++i) {
        const Surface& surface = scene.surfaces[i];
        if (leftOut[i] || surface.material < 0) continue;
        if (!IsLightType(scene.materials[static_cast<size_t>(surface.material)].type)) continue;
        const Polygon* polygon = FinitePolygon(surface);
        if (polygon && (!largest || polygon->area > largest->area)) largest = polygon;
    }
    if (!largest || !(scale > 0) || !std::isfinite(scale)) return std::nullopt;

    SourcePlane plane;
    plane.normal = largest->normal;
    plane.offset = largest->offset;
    plane.scale = scale;
    for (size_t i = 0; i < scene.surfaces.size(); ++i) {
        if (leftOut[i]) continue;
        const Polygon* polygon = FinitePolygon(scene.surfaces[i]);
        if (!polygon) continue;
        // A polygon facing the other way lies in the plane too.
        const double side = Dot(polygon->normal, plane.normal) > 0 ? 1.0 : -1.0;
        if (MaxAbs(polygon->normal * side - plane.normal) <= kSamePlane &&
            std::fabs(polygon->offset * side - plane.offset) <= kSamePlane * scale) {
            plane.surfaces.push_back(static_cast<int>(i));
        }
    }
    return plane;
}

}  // namespace rt
