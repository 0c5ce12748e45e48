// SPDX-License-Identifier: MIT
//
// Exact double-precision ray/surface intersection for Radiance's primitives
// (o_face.c + face.c, o_cone.c + cone.c, sphere.c), and the polygon
// triangulation the Embree mesh is built from. Pure functions, no Embree: the
// ray core uses them to recompute every candidate Embree finds, and
// RayCore::IntersectSurface uses them directly.
//
// All intersectors follow Radiance's rule that distances t <= tmin are not
// hits (tmin = kFtiny in Radiance; the ray core passes the scene's
// Scene::distanceTolerance), and return the nearest remaining hit of that one surface (no tmax: the
// caller compares). `dir` must be unit so that t is a distance.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "core/vecmath.h"
#include "scene/scene.h"

namespace rt {

struct ShapeHit {
    double t = 0;  // distance along the unit direction, > tmin
    Vec3 normal;   // unit, as the surface defines it (inward for bubble/cup/tube), not flipped
};

/// A hit without its normal: the distance, and whether the ray meets the
/// surface's back, i.e. -Dot(dir, normal) < 0 for the ShapeHit normal, bit for
/// bit. The *Side intersectors skip the normal's square roots and divisions
/// when cheaper arithmetic settles the side for certain, and compute it
/// otherwise.
struct ShapeSide {
    double t = 0;
    bool back = false;
};

/// Sphere or bubble. Rays starting inside find the far side.
std::optional<ShapeHit> IntersectSphere(const Sphere& sphere, const Vec3& org, const Vec3& dir,
                                        double tmin = kFtiny);

std::optional<ShapeSide> IntersectSphereSide(const Sphere& sphere, const Vec3& org,
                                             const Vec3& dir, double tmin = kFtiny);

/// Cone, cup, cylinder or tube: the lateral surface between the end planes
/// through p0 and p1 (open ends, as Radiance). `inward` comes from the shape.
std::optional<ShapeHit> IntersectCone(const Cone& cone, const Vec3& org, const Vec3& dir,
                                      double tmin = kFtiny);

/// What IntersectCone derives from the cone before it looks at the ray (a
/// square root and four divisions), for cones tested many times.
struct ConeFrame {
    Vec3 p0;
    Vec3 axis;          // unit, from p0 toward p1
    double length = 0;  // |p1 - p0|
    double slope = 0;   // (r1 - r0) / length: the radius grows this much per unit of height
    double r0 = 0;
    bool inward = false;
};
ConeFrame MakeConeFrame(const Cone& cone);

/// IntersectCone(cone, ...) for frame = MakeConeFrame(cone), bit for bit.
std::optional<ShapeHit> IntersectCone(const ConeFrame& frame, const Vec3& org, const Vec3& dir,
                                      double tmin = kFtiny);
std::optional<ShapeSide> IntersectConeSide(const ConeFrame& frame, const Vec3& org,
                                           const Vec3& dir, double tmin = kFtiny);

/// Disc/annulus r0 <= |p - center| <= r1 (both radii inclusive). Rays with
/// |dir·normal| <= kFtiny are parallel and miss, as in Radiance.
std::optional<ShapeHit> IntersectRing(const Ring& ring, const Vec3& org, const Vec3& dir,
                                      double tmin = kFtiny);

/// Distance to the polygon's plane (Dot(normal, p) == offset) without the
/// inside test; nullopt when parallel (|dir·normal| <= kFtiny) or t <= tmin.
/// The ray core uses this for hits Embree already placed inside a triangle.
std::optional<double> IntersectPolygonPlane(const Polygon& polygon, const Vec3& org,
                                            const Vec3& dir, double tmin = kFtiny);

/// Radiance's inface(): crossing-number test in the plane that drops the
/// normal's largest component, for a point on (or near) the polygon's plane.
/// Points on an edge or vertex (within kFtiny relative to the edge length)
/// count as inside. Works for concave polygons.
bool PointInPolygon(const Polygon& polygon, const Vec3& point);

/// Plane distance plus PointInPolygon.
std::optional<ShapeHit> IntersectPolygon(const Polygon& polygon, const Vec3& org, const Vec3& dir,
                                         double tmin = kFtiny);

/// Ear-clipping triangulation in the polygon's plane (double precision), for
/// convex and concave simple polygons with any vertex count >= 3. Indices refer
/// to polygon.vertices; triangles keep Radiance's winding (counter-clockwise
/// seen from the front). Collinear vertices produce no sliver triangles. A
/// self-intersecting outline that has no ear left is finished as a fan, so the
/// result always covers the outline (never throws).
std::vector<std::array<int, 3>> TriangulatePolygon(const Polygon& polygon);

/// Exact (double) bounds of the shape's geometry; empty for a distant source.
Bounds3 ShapeBounds(const Surface& surface);

/// Dispatches on the surface type (sphere/bubble, cone family, ring, polygon);
/// nullopt for a distant source.
std::optional<ShapeHit> IntersectShape(const Surface& surface, const Vec3& org, const Vec3& dir,
                                       double tmin = kFtiny);
std::optional<ShapeSide> IntersectShapeSide(const Surface& surface, const Vec3& org,
                                            const Vec3& dir, double tmin = kFtiny);

}  // namespace rt
