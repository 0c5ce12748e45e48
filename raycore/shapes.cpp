// SPDX-License-Identifier: MIT
#include "raycore/shapes.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/conventions.h"

namespace rt {
namespace {

/// Radiance's face axis: the largest normal component (ties go to the lower
/// axis, except that z must be strictly larger), as getface() chooses it.
int DominantAxis(const Vec3& n) {
    int ax = std::fabs(n.x) > std::fabs(n.y) ? 0 : 1;
    if (std::fabs(n.z) > std::fabs(n[ax])) ax = 2;
    return ax;
}

/// Roots of A t² + 2 B t + C = 0 given the reduced discriminant B² − AC >= 0,
/// in the cancellation-free form (q = −(B + sign(B)·√disc); t = q/A and C/q),
/// ascending. A == 0 degrades to the linear root. Returns the root count.
int StableRoots(double a, double b, double c, double disc, double roots[2]) {
    double q = -(b + std::copysign(std::sqrt(disc), b));
    int n = 0;
    if (q == 0) {
        // b == 0 and disc == 0: a double root at 0 when a != 0 (never a hit).
        if (a != 0) roots[n++] = 0;
        return n;
    }
    if (a != 0) roots[n++] = q / a;
    roots[n++] = c / q;
    if (n == 2 && roots[0] > roots[1]) std::swap(roots[0], roots[1]);
    return n;
}

double Cross2(double ax, double ay, double bx, double by) { return ax * by - ay * bx; }

}  // namespace

namespace {

/// The nearest root of a sphere beyond tmin, and f = org − centre.
struct SphereRoot {
    double t;
    Vec3 f;
};
[[gnu::always_inline]] inline std::optional<SphereRoot> FindSphereRoot(const Sphere& sphere,
                                                                       const Vec3& org,
                                                                       const Vec3& dir,
                                                                       double tmin) {
    // Discriminant as r² − |f⊥|² (Ray Tracing Gems ch. 7): stays accurate when
    // the origin is far from a small sphere, where b² − c cancels.
    const Vec3 f = org - sphere.center;
    const double b = Dot(f, dir);
    const Vec3 perp = f - dir * b;
    const double r2 = sphere.radius * sphere.radius;
    const double disc = r2 - LengthSquared(perp);
    if (disc < 0) return std::nullopt;
    double roots[2];
    const int n = StableRoots(1.0, b, LengthSquared(f) - r2, disc, roots);
    for (int i = 0; i < n; ++i) {
        if (roots[i] > tmin) return SphereRoot{roots[i], f};
    }
    return std::nullopt;
}

/// True if `v`, parallel to the unit normal a shape would compute but not
/// normalised (and, for a cone, without its divisions), gives the sign of
/// Dot(dir, normal) for certain: the few roundings between the two change
/// the dot product by ~1e-15 of |v|, far below this margin.
bool SideIsCertain(const Vec3& v, double dot) {
    return std::fabs(dot) > 1e-12 * (std::fabs(v.x) + std::fabs(v.y) + std::fabs(v.z));
}

}  // namespace

std::optional<ShapeHit> IntersectSphere(const Sphere& sphere, const Vec3& org, const Vec3& dir,
                                        double tmin) {
    const auto root = FindSphereRoot(sphere, org, dir, tmin);
    if (!root) return std::nullopt;
    Vec3 normal = Normalize(root->f + dir * root->t);
    if (sphere.inward) normal = -normal;
    return ShapeHit{root->t, normal};
}

std::optional<ShapeSide> IntersectSphereSide(const Sphere& sphere, const Vec3& org,
                                             const Vec3& dir, double tmin) {
    const auto root = FindSphereRoot(sphere, org, dir, tmin);
    if (!root) return std::nullopt;
    Vec3 v = root->f + dir * root->t;
    if (sphere.inward) v = -v;
    const double dot = Dot(dir, v);
    if (SideIsCertain(v, dot)) return ShapeSide{root->t, dot > 0};
    Vec3 normal = Normalize(v);
    return ShapeSide{root->t, -Dot(dir, normal) < 0.0};
}

ConeFrame MakeConeFrame(const Cone& cone) {
    ConeFrame f;
    const Vec3 axis = cone.p1 - cone.p0;
    f.p0 = cone.p0;
    f.length = Length(axis);
    f.axis = axis / f.length;
    f.slope = (cone.r1 - cone.r0) / f.length;
    f.r0 = cone.r0;
    f.inward = cone.inward;
    return f;
}

std::optional<ShapeHit> IntersectCone(const Cone& cone, const Vec3& org, const Vec3& dir,
                                      double tmin) {
    return IntersectCone(MakeConeFrame(cone), org, dir, tmin);
}

namespace {

/// The nearest root of a cone's lateral surface beyond tmin and between its
/// end planes, and the part of (hit point − p0) perpendicular to the axis.
struct ConeRoot {
    double t;
    Vec3 radial;
};
[[gnu::always_inline]] inline std::optional<ConeRoot> FindConeRoot(const ConeFrame& cone,
                                                                   const Vec3& org,
                                                                   const Vec3& dir, double tmin) {
    // Frame: a = unit axis from p0, h = height along it, radius(h) = r0 + k·h.
    // With o⊥, d⊥ the parts of (org − p0) and dir perpendicular to a, the
    // lateral surface is |o⊥ + t·d⊥|² = (r0 + k·(ho + t·hd))².
    const Vec3& a = cone.axis;
    const double length = cone.length;
    const double k = cone.slope;
    const Vec3 o = org - cone.p0;
    const double ho = Dot(o, a);
    const double hd = Dot(dir, a);
    const Vec3 op = o - a * ho;
    const Vec3 dp = dir - a * hd;
    const double rad0 = cone.r0 + k * ho;  // cone radius at the origin's height
    const double qa = LengthSquared(dp) - k * k * hd * hd;
    const double qb = Dot(op, dp) - k * hd * rad0;
    const double qc = LengthSquared(op) - rad0 * rad0;
    // qb² − qa·qc rewritten (Lagrange's identity) as a difference of two
    // squared lengths, which keeps its accuracy for distant origins.
    const double disc = LengthSquared(dp * rad0 - op * (k * hd)) - LengthSquared(Cross(op, dp));
    if (disc < 0) return std::nullopt;
    if (qa == 0 && qb == 0) return std::nullopt;  // along the axis of a cylinder
    double roots[2];
    const int n = StableRoots(qa, qb, qc, disc, roots);
    for (int i = 0; i < n; ++i) {
        const double t = roots[i];
        if (t <= tmin) continue;
        const double h = ho + t * hd;
        if (h < 0 || h > length) continue;  // outside the end planes
        return ConeRoot{t, op + dp * t};
    }
    return std::nullopt;
}

/// IntersectCone's normal at a root.
Vec3 ConeNormal(const ConeFrame& cone, const Vec3& radial) {
    const Vec3& a = cone.axis;
    const double k = cone.slope;
    const double radialLength = Length(radial);
    // Outward normal of the slanted side: radial unit tilted by −k·a
    // (Radiance o_cone.c: (al·radial − (r1−r0)·a)/slant length).
    Vec3 normal = radialLength > 0 ? Normalize(radial / radialLength - a * k)
                                   : a * (k > 0 ? -1.0 : 1.0);  // at the apex
    if (cone.inward) normal = -normal;
    return normal;
}

}  // namespace

std::optional<ShapeHit> IntersectCone(const ConeFrame& cone, const Vec3& org, const Vec3& dir,
                                      double tmin) {
    const auto root = FindConeRoot(cone, org, dir, tmin);
    if (!root) return std::nullopt;
    return ShapeHit{root->t, ConeNormal(cone, root->radial)};
}

std::optional<ShapeSide> IntersectConeSide(const ConeFrame& cone, const Vec3& org,
                                           const Vec3& dir, double tmin) {
    const auto root = FindConeRoot(cone, org, dir, tmin);
    if (!root) return std::nullopt;
    // radial − a·k·|radial| is the normal times |radial|; a cylinder's is radial.
    const Vec3& radial = root->radial;
    Vec3 v = cone.slope == 0 ? radial : radial - cone.axis * (cone.slope * Length(radial));
    if (cone.inward) v = -v;
    const double dot = Dot(dir, v);
    if (SideIsCertain(v, dot)) return ShapeSide{root->t, dot > 0};
    return ShapeSide{root->t, -Dot(dir, ConeNormal(cone, radial)) < 0.0};
}

std::optional<ShapeHit> IntersectRing(const Ring& ring, const Vec3& org, const Vec3& dir,
                                      double tmin) {
    const double denom = Dot(ring.normal, dir);
    if (std::fabs(denom) <= kFtiny) return std::nullopt;  // parallel, as o_cone.c
    const double t = Dot(ring.normal, ring.center - org) / denom;
    if (t <= tmin) return std::nullopt;
    const double rho2 = LengthSquared((org - ring.center) + dir * t);
    if (rho2 < ring.r0 * ring.r0 || rho2 > ring.r1 * ring.r1) return std::nullopt;
    return ShapeHit{t, ring.normal};
}

std::optional<double> IntersectPolygonPlane(const Polygon& polygon, const Vec3& org,
                                            const Vec3& dir, double tmin) {
    const double denom = Dot(polygon.normal, dir);
    if (std::fabs(denom) <= kFtiny) return std::nullopt;  // parallel, as o_face.c
    const double t = (polygon.offset - Dot(polygon.normal, org)) / denom;
    if (!(t > tmin)) return std::nullopt;
    return t;
}

bool PointInPolygon(const Polygon& polygon, const Vec3& point) {
    const int ax = DominantAxis(polygon.normal);
    const int xi = (ax + 1) % 3;
    const int yi = (ax + 2) % 3;
    const double x = point[xi];
    const double y = point[yi];
    const auto& v = polygon.vertices;
    const size_t n = v.size();
    // Edges and vertices are inside: a point within kFtiny·|edge| of an edge
    // segment counts, so rays through a shared edge hit both polygons.
    for (size_t i = 0, j = n - 1; i < n; j = i++) {
        const double x0 = v[j][xi], y0 = v[j][yi];
        const double ex = v[i][xi] - x0, ey = v[i][yi] - y0;
        const double len2 = ex * ex + ey * ey;
        if (len2 == 0) continue;
        const double px = x - x0, py = y - y0;
        const double along = ex * px + ey * py;
        if (std::fabs(Cross2(ex, ey, px, py)) <= kFtiny * len2 && along >= -kFtiny * len2 &&
            along <= (1 + kFtiny) * len2) {
            return true;
        }
    }
    // Crossing count along +x (face.c inface()).
    int crossings = 0;
    for (size_t i = 0, j = n - 1; i < n; j = i++) {
        const double x0 = v[j][xi], y0 = v[j][yi];
        const double x1 = v[i][xi], y1 = v[i][yi];
        if ((y0 > y) == (y1 > y)) continue;
        if (x0 > x && x1 > x) {
            ++crossings;
        } else if (x0 > x || x1 > x) {
            crossings += (y1 > y0) != ((y0 - y) * (x1 - x) > (x0 - x) * (y1 - y));
        }
    }
    return (crossings & 1) != 0;
}

std::optional<ShapeHit> IntersectPolygon(const Polygon& polygon, const Vec3& org, const Vec3& dir,
                                         double tmin) {
    const auto t = IntersectPolygonPlane(polygon, org, dir, tmin);
    if (!t || !PointInPolygon(polygon, org + dir * *t)) return std::nullopt;
    return ShapeHit{*t, polygon.normal};
}

std::vector<std::array<int, 3>> TriangulatePolygon(const Polygon& polygon) {
    std::vector<std::array<int, 3>> triangles;
    const int n = static_cast<int>(polygon.vertices.size());
    if (n < 3) return triangles;
    // 2-D coordinates in the plane that drops the dominant normal axis,
    // relative to vertex 0 so that far-from-origin scenes keep their digits.
    const int ax = DominantAxis(polygon.normal);
    const int xi = (ax + 1) % 3;
    const int yi = (ax + 2) % 3;
    std::vector<double> px(static_cast<size_t>(n)), py(static_cast<size_t>(n));
    const Vec3 v0 = polygon.vertices[0];
    double area2 = 0;
    for (int i = 0; i < n; ++i) {
        const Vec3 d = polygon.vertices[static_cast<size_t>(i)] - v0;
        px[static_cast<size_t>(i)] = d[xi];
        py[static_cast<size_t>(i)] = d[yi];
    }
    for (int i = 0, j = n - 1; i < n; j = i++) {
        area2 += Cross2(px[static_cast<size_t>(j)], py[static_cast<size_t>(j)],
                        px[static_cast<size_t>(i)], py[static_cast<size_t>(i)]);
    }
    if (area2 == 0) return triangles;  // degenerate ("zero area" in Radiance)
    const double orient = area2 > 0 ? 1.0 : -1.0;
    double extent2 = 0;
    for (int i = 0; i < n; ++i) {
        extent2 = std::max(extent2, px[static_cast<size_t>(i)] * px[static_cast<size_t>(i)] +
                                        py[static_cast<size_t>(i)] * py[static_cast<size_t>(i)]);
    }
    // Areas below this count as collinear; relative to the polygon's size.
    const double epsArea = 1e-14 * extent2;

    auto cross = [&](int a, int b, int c) {
        const size_t ua = static_cast<size_t>(a), ub = static_cast<size_t>(b),
                     uc = static_cast<size_t>(c);
        return orient * Cross2(px[ub] - px[ua], py[ub] - py[ua], px[uc] - px[ua], py[uc] - py[ua]);
    };
    auto samePoint = [&](int a, int b) {
        return px[static_cast<size_t>(a)] == px[static_cast<size_t>(b)] &&
               py[static_cast<size_t>(a)] == py[static_cast<size_t>(b)];
    };

    std::vector<int> ring(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) ring[static_cast<size_t>(i)] = i;
    triangles.reserve(static_cast<size_t>(n - 2));
    size_t cursor = 0;
    while (ring.size() > 3) {
        const size_t m = ring.size();
        bool clipped = false;
        for (size_t step = 0; step < m && !clipped; ++step) {
            const size_t i = (cursor + step) % m;
            const int a = ring[(i + m - 1) % m];
            const int b = ring[i];
            const int c = ring[(i + 1) % m];
            const double area = cross(a, b, c);
            if (std::fabs(area) <= epsArea) {
                // Collinear (or a zero-width spike): dropping b changes no area.
                ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(i));
                cursor = i == 0 ? 0 : i - 1;
                clipped = true;
                break;
            }
            if (area < 0) continue;  // reflex
            // An ear must not contain (or touch) any other remaining vertex;
            // copies of a, b, c (seams joining holes) do not block it.
            bool blocked = false;
            for (size_t j = 0; j < m && !blocked; ++j) {
                const int p = ring[j];
                if (p == a || p == b || p == c || samePoint(p, a) || samePoint(p, b) ||
                    samePoint(p, c)) {
                    continue;
                }
                blocked = cross(a, b, p) >= -epsArea && cross(b, c, p) >= -epsArea &&
                          cross(c, a, p) >= -epsArea;
            }
            if (blocked) continue;
            triangles.push_back({a, b, c});
            ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(i));
            cursor = i == 0 ? 0 : i - 1;
            clipped = true;
        }
        if (!clipped) {
            // Self-intersecting outline: no ear exists. Cover the rest as a fan
            // so nothing leaks, accepting overlap.
            for (size_t j = 1; j + 1 < ring.size(); ++j) {
                if (std::fabs(cross(ring[0], ring[j], ring[j + 1])) > epsArea) {
                    triangles.push_back({ring[0], ring[j], ring[j + 1]});
                }
            }
            return triangles;
        }
    }
    if (std::fabs(cross(ring[0], ring[1], ring[2])) > epsArea) {
        triangles.push_back({ring[0], ring[1], ring[2]});
    }
    return triangles;
}

Bounds3 ShapeBounds(const Surface& surface) {
    Bounds3 b;
    switch (surface.type) {
        case SurfaceType::Polygon:
            for (const Vec3& v : std::get<Polygon>(surface.shape).vertices) b.Extend(v);
            break;
        case SurfaceType::Sphere:
        case SurfaceType::Bubble: {
            const auto& s = std::get<Sphere>(surface.shape);
            const Vec3 r{s.radius, s.radius, s.radius};
            b.Extend(s.center - r);
            b.Extend(s.center + r);
            break;
        }
        case SurfaceType::Cone:
        case SurfaceType::Cup:
        case SurfaceType::Cylinder:
        case SurfaceType::Tube: {
            // Each end disc spans r·sqrt(1 − a_i²) along axis i.
            const auto& c = std::get<Cone>(surface.shape);
            const Vec3 a = Normalize(c.p1 - c.p0);
            const Vec3 s{std::sqrt(std::max(0.0, 1 - a.x * a.x)),
                         std::sqrt(std::max(0.0, 1 - a.y * a.y)),
                         std::sqrt(std::max(0.0, 1 - a.z * a.z))};
            b.Extend(c.p0 - s * c.r0);
            b.Extend(c.p0 + s * c.r0);
            b.Extend(c.p1 - s * c.r1);
            b.Extend(c.p1 + s * c.r1);
            break;
        }
        case SurfaceType::Ring: {
            const auto& r = std::get<Ring>(surface.shape);
            const Vec3& n = r.normal;
            const Vec3 s{std::sqrt(std::max(0.0, 1 - n.x * n.x)),
                         std::sqrt(std::max(0.0, 1 - n.y * n.y)),
                         std::sqrt(std::max(0.0, 1 - n.z * n.z))};
            b.Extend(r.center - s * r.r1);
            b.Extend(r.center + s * r.r1);
            break;
        }
        case SurfaceType::Source:
        case SurfaceType::Instance:
        case SurfaceType::Mesh:
            break;  // not geometry of their own
    }
    return b;
}

std::optional<ShapeSide> IntersectShapeSide(const Surface& surface, const Vec3& org,
                                            const Vec3& dir, double tmin) {
    switch (surface.type) {
        case SurfaceType::Sphere:
        case SurfaceType::Bubble:
            return IntersectSphereSide(std::get<Sphere>(surface.shape), org, dir, tmin);
        case SurfaceType::Cone:
        case SurfaceType::Cup:
        case SurfaceType::Cylinder:
        case SurfaceType::Tube:
            return IntersectConeSide(MakeConeFrame(std::get<Cone>(surface.shape)), org, dir, tmin);
        default: {
            const auto hit = IntersectShape(surface, org, dir, tmin);
            if (!hit) return std::nullopt;
            return ShapeSide{hit->t, -Dot(dir, hit->normal) < 0.0};
        }
    }
}

std::optional<ShapeHit> IntersectShape(const Surface& surface, const Vec3& org, const Vec3& dir,
                                       double tmin) {
    switch (surface.type) {
        case SurfaceType::Polygon:
            return IntersectPolygon(std::get<Polygon>(surface.shape), org, dir, tmin);
        case SurfaceType::Sphere:
        case SurfaceType::Bubble:
            return IntersectSphere(std::get<Sphere>(surface.shape), org, dir, tmin);
        case SurfaceType::Cone:
        case SurfaceType::Cup:
        case SurfaceType::Cylinder:
        case SurfaceType::Tube:
            return IntersectCone(std::get<Cone>(surface.shape), org, dir, tmin);
        case SurfaceType::Ring:
            return IntersectRing(std::get<Ring>(surface.shape), org, dir, tmin);
        case SurfaceType::Source:
        case SurfaceType::Instance:
        case SurfaceType::Mesh:
            return std::nullopt;
    }
    return std::nullopt;
}

}  // namespace rt
