// SPDX-License-Identifier: MIT
#include "raycore/shapes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/conventions.h"
#include "tests/raycore/test_scenes.h"

namespace rt {
namespace {

using testing::MakePolygon;

constexpr double kTol = 1e-12;

void ExpectVecNear(const Vec3& a, const Vec3& b, double tol) {
    EXPECT_NEAR(a.x, b.x, tol) << a << " vs " << b;
    EXPECT_NEAR(a.y, b.y, tol) << a << " vs " << b;
    EXPECT_NEAR(a.z, b.z, tol) << a << " vs " << b;
}

// --- sphere ---------------------------------------------------------------

TEST(Sphere, HitFromOutside) {
    const Sphere s{{1, 2, 3}, 2, false};
    auto h = IntersectSphere(s, {1, 2, -2}, {0, 0, 1});
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 3, kTol);
    ExpectVecNear(h->normal, {0, 0, -1}, kTol);
}

TEST(Sphere, OffCentreHitNormal) {
    // Hit at (1, 0, -sqrt(3)) on the sphere of radius 2 around the origin.
    const Sphere s{{0, 0, 0}, 2, false};
    auto h = IntersectSphere(s, {1, 0, -10}, {0, 0, 1});
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 10 - std::sqrt(3.0), kTol);
    ExpectVecNear(h->normal, {0.5, 0, -std::sqrt(3.0) / 2}, kTol);
}

TEST(Sphere, Misses) {
    const Sphere s{{0, 0, 0}, 1, false};
    EXPECT_FALSE(IntersectSphere(s, {0, 1.001, -5}, {0, 0, 1}));
    EXPECT_FALSE(IntersectSphere(s, {0, 0, 5}, {0, 0, 1}));  // sphere behind the ray
}

TEST(Sphere, FromInsideFindsFarSide) {
    const Sphere s{{0, 0, 0}, 2, false};
    auto h = IntersectSphere(s, {0, 0, 0}, {0, 1, 0});
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 2, kTol);
    ExpectVecNear(h->normal, {0, 1, 0}, kTol);
}

TEST(Sphere, BubbleNormalPointsInward) {
    const Sphere s{{0, 0, 0}, 2, true};
    auto h = IntersectSphere(s, {0, 0, 0}, {0, 1, 0});
    ASSERT_TRUE(h);
    ExpectVecNear(h->normal, {0, -1, 0}, kTol);
}

TEST(Sphere, StartOnSurfaceDiscardsZeroDistance) {
    const Sphere s{{0, 0, 0}, 1, false};
    EXPECT_FALSE(IntersectSphere(s, {0, 0, 1}, {0, 0, 1}));  // leaving
    auto h = IntersectSphere(s, {0, 0, 1}, {0, 0, -1});      // entering: far side
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 2, kTol);
}

TEST(Sphere, SmallSphereFarFromOrigin) {
    // 1 mm sphere 1e6 away from the origin, ray from 10 units away.
    const Vec3 c{1e6, -2e6, 5e5};
    const Sphere s{c, 1e-3, false};
    auto h = IntersectSphere(s, c + Vec3{0, 0, -10}, {0, 0, 1});
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 10 - 1e-3, 1e-9);
    ExpectVecNear(h->normal, {0, 0, -1}, 1e-6);
}

// --- cone family -----------------------------------------------------------

TEST(Cylinder, HitFromOutside) {
    const Cone c{{0, 0, 0}, {0, 0, 2}, 1, 1, false};
    auto h = IntersectCone(c, {-5, 0, 1}, {1, 0, 0});
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 4, kTol);
    ExpectVecNear(h->normal, {-1, 0, 0}, kTol);
}

TEST(Cylinder, ObliqueAxis) {
    // Axis along (1,1,0)/√2 through the origin, radius 1; ray along z through
    // the axis point (2,2,0) hits at distance 1 below/above it.
    const Cone c{{0, 0, 0}, {4, 4, 0}, 1, 1, false};
    auto h = IntersectCone(c, {2, 2, -5}, {0, 0, 1});
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 4, kTol);
    ExpectVecNear(h->normal, {0, 0, -1}, kTol);
}

TEST(Cylinder, FromInsideAndTube) {
    const Cone cyl{{0, 0, 0}, {0, 0, 2}, 1, 1, false};
    auto h = IntersectCone(cyl, {0, 0, 1}, {1, 0, 0});
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 1, kTol);
    ExpectVecNear(h->normal, {1, 0, 0}, kTol);
    const Cone tube{{0, 0, 0}, {0, 0, 2}, 1, 1, true};
    h = IntersectCone(tube, {0, 0, 1}, {1, 0, 0});
    ASSERT_TRUE(h);
    ExpectVecNear(h->normal, {-1, 0, 0}, kTol);
}

TEST(Cylinder, EndPlanesBoundTheSurface) {
    const Cone c{{0, 0, 0}, {0, 0, 2}, 1, 1, false};
    EXPECT_FALSE(IntersectCone(c, {-5, 0, 2.001}, {1, 0, 0}));
    EXPECT_FALSE(IntersectCone(c, {-5, 0, -0.001}, {1, 0, 0}));
    EXPECT_TRUE(IntersectCone(c, {-5, 0, 2}, {1, 0, 0}));  // end plane inclusive
    // From inside, leaving through the open top end.
    EXPECT_FALSE(IntersectCone(c, {0, 0, 1}, Normalize({0.3, 0, 1})));
    // Parallel to the axis, inside: never reaches the wall.
    EXPECT_FALSE(IntersectCone(c, {0.5, 0, -1}, {0, 0, 1}));
    // Entering through the open bottom end, hitting the wall from inside.
    const Vec3 d = Normalize({1, 0, 1});
    auto h = IntersectCone(c, {0, 0, -0.5}, d);
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, std::sqrt(2.0), kTol);  // at (1, 0, 0.5)
    ExpectVecNear(h->normal, {1, 0, 0}, kTol);
}

TEST(Cone, HitAndSlantedNormal) {
    // Base radius 1 at z=0, apex at z=1: radius 0.5 at z=0.5; the outward
    // normal is tilted 45° towards the apex.
    const Cone c{{0, 0, 0}, {0, 0, 1}, 1, 0, false};
    auto h = IntersectCone(c, {-5, 0, 0.5}, {1, 0, 0});
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 4.5, kTol);
    ExpectVecNear(h->normal, Normalize({-1, 0, 1}), kTol);
    // Same cone with the ends given the other way round.
    const Cone swapped{{0, 0, 1}, {0, 0, 0}, 0, 1, false};
    h = IntersectCone(swapped, {-5, 0, 0.5}, {1, 0, 0});
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 4.5, kTol);
    ExpectVecNear(h->normal, Normalize({-1, 0, 1}), kTol);
}

TEST(Cone, EndPlanesAndOtherNappe) {
    const Cone c{{0, 0, 0}, {0, 0, 1}, 1, 0, false};
    EXPECT_FALSE(IntersectCone(c, {-5, 0, 1.2}, {1, 0, 0}));   // past the apex plane
    EXPECT_FALSE(IntersectCone(c, {-5, 0, -0.2}, {1, 0, 0}));  // below the base plane
    // Truncated cone r 2 -> 1 between z 0 and 2; ray straight down the inside
    // at x = 1.25 hits the wall where the radius is 1.25 (z = 1.5), from inside.
    const Cone frustum{{0, 0, 0}, {0, 0, 2}, 2, 1, false};
    auto h = IntersectCone(frustum, {1.25, 0, 5}, {0, 0, -1});
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 3.5, kTol);
    ExpectVecNear(h->normal, Normalize({2, 0, 1}), kTol);
}

TEST(Cone, CupNormalPointsInward) {
    const Cone c{{0, 0, 0}, {0, 0, 1}, 1, 0, true};
    auto h = IntersectCone(c, {-5, 0, 0.5}, {1, 0, 0});
    ASSERT_TRUE(h);
    ExpectVecNear(h->normal, Normalize({1, 0, -1}), kTol);
}

// --- ring ------------------------------------------------------------------

TEST(Ring, AnnulusHitsAndInnerRadius) {
    const Ring r{{0, 0, 1}, {0, 0, 1}, 1, 2};
    auto h = IntersectRing(r, {1.5, 0, 5}, {0, 0, -1});
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 4, kTol);
    ExpectVecNear(h->normal, {0, 0, 1}, 0);
    EXPECT_FALSE(IntersectRing(r, {0.5, 0, 5}, {0, 0, -1}));  // through the hole
    EXPECT_FALSE(IntersectRing(r, {0.999, 0, 5}, {0, 0, -1}));
    EXPECT_TRUE(IntersectRing(r, {1, 0, 5}, {0, 0, -1}));  // radii inclusive
    EXPECT_TRUE(IntersectRing(r, {0, 2, 5}, {0, 0, -1}));
    EXPECT_FALSE(IntersectRing(r, {2.001, 0, 5}, {0, 0, -1}));
    // From below: same normal (not flipped).
    h = IntersectRing(r, {1.5, 0, -1}, {0, 0, 1});
    ASSERT_TRUE(h);
    ExpectVecNear(h->normal, {0, 0, 1}, 0);
}

TEST(Ring, ParallelRayMisses) {
    const Ring r{{0, 0, 0}, {0, 0, 1}, 0, 2};
    EXPECT_FALSE(IntersectRing(r, {-5, 0, 0}, {1, 0, 0}));
    EXPECT_FALSE(IntersectRing(r, {-5, 0, 0}, Normalize({1, 0, 1e-7})));
}

// --- polygon ---------------------------------------------------------------

Polygon LShape() {
    // Counter-clockwise seen from +z; the notch is the square [1,2]x[1,2].
    return MakePolygon({{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}});
}

TEST(Polygon, SquareHit) {
    const Polygon p = MakePolygon({{0, 0, 3}, {1, 0, 3}, {1, 1, 3}, {0, 1, 3}});
    auto h = IntersectPolygon(p, {0.25, 0.75, 5}, {0, 0, -1});
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 2, kTol);
    ExpectVecNear(h->normal, {0, 0, 1}, 0);
    EXPECT_FALSE(IntersectPolygon(p, {1.25, 0.75, 5}, {0, 0, -1}));
    EXPECT_FALSE(IntersectPolygon(p, {0.5, 0.5, 5}, {1, 0, 0}));  // parallel
}

TEST(Polygon, ConcaveNotchMisses) {
    const Polygon p = LShape();
    EXPECT_FALSE(IntersectPolygon(p, {1.5, 1.5, 1}, {0, 0, -1}));
    EXPECT_TRUE(IntersectPolygon(p, {0.5, 1.5, 1}, {0, 0, -1}));
    EXPECT_TRUE(IntersectPolygon(p, {1.5, 0.5, 1}, {0, 0, -1}));
    EXPECT_TRUE(IntersectPolygon(p, {0.5, 0.5, 1}, {0, 0, -1}));
}

TEST(Polygon, EdgesAndVerticesAreInside) {
    const Polygon p = LShape();
    EXPECT_TRUE(PointInPolygon(p, {1, 0, 0}));    // on the bottom edge
    EXPECT_TRUE(PointInPolygon(p, {2, 0.5, 0}));  // on the right edge
    EXPECT_TRUE(PointInPolygon(p, {1.5, 1, 0}));  // on the notch edge
    EXPECT_TRUE(PointInPolygon(p, {1, 1, 0}));    // reflex vertex
    EXPECT_TRUE(PointInPolygon(p, {0, 2, 0}));    // convex vertex
    EXPECT_FALSE(PointInPolygon(p, {1.5, 1.001, 0}));
    EXPECT_FALSE(PointInPolygon(p, {2.001, 0.5, 0}));
}

double TriangleArea(const Polygon& p, const std::array<int, 3>& t) {
    const Vec3& a = p.vertices[static_cast<size_t>(t[0])];
    const Vec3& b = p.vertices[static_cast<size_t>(t[1])];
    const Vec3& c = p.vertices[static_cast<size_t>(t[2])];
    // Signed along the polygon normal: positive keeps Radiance's winding.
    return Dot(Cross(b - a, c - a), p.normal) / 2;
}

void ExpectExactCover(const Polygon& p) {
    const auto tris = TriangulatePolygon(p);
    EXPECT_EQ(tris.size(), p.vertices.size() - 2);
    double sum = 0;
    for (const auto& t : tris) {
        const double a = TriangleArea(p, t);
        EXPECT_GT(a, 0) << "triangle winding flipped or degenerate";
        sum += a;
        // Each triangle's centroid lies inside the polygon (no ear outside).
        const Vec3 c =
            (p.vertices[static_cast<size_t>(t[0])] + p.vertices[static_cast<size_t>(t[1])] +
             p.vertices[static_cast<size_t>(t[2])]) /
            3;
        EXPECT_TRUE(PointInPolygon(p, c));
    }
    EXPECT_NEAR(sum, p.area, 1e-9 * p.area);
}

TEST(Triangulate, ConvexAndConcave) {
    ExpectExactCover(MakePolygon({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}));
    ExpectExactCover(MakePolygon({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}));
    ExpectExactCover(LShape());
    // Same L standing in the xz plane and facing -y, far from the origin.
    const Vec3 o{1e6, -2e6, 5e5};
    ExpectExactCover(MakePolygon({o + Vec3{0, 0, 0}, o + Vec3{0, 0, 2}, o + Vec3{1, 0, 2},
                                  o + Vec3{1, 0, 1}, o + Vec3{2, 0, 1}, o + Vec3{2, 0, 0}}));
    // Comb: many reflex vertices.
    std::vector<Vec3> comb{{0, 0, 0}, {10, 0, 0}};
    for (int i = 10; i > 0; --i) {
        comb.push_back({static_cast<double>(i), 3, 0});
        comb.push_back({i - 0.5, 1, 0});
    }
    comb.push_back({0, 3, 0});
    ExpectExactCover(MakePolygon(comb));
}

TEST(Triangulate, RandomStarPolygons) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.2, 1.0);
    for (int trial = 0; trial < 50; ++trial) {
        const int n = 3 + trial % 17;
        std::vector<Vec3> v;
        for (int i = 0; i < n; ++i) {
            const double a = 2 * kPi * i / n;
            const double r = u(rng);
            v.push_back({r * std::cos(a), 0.3 * r * std::cos(a), r * std::sin(a)});
        }
        ExpectExactCover(MakePolygon(v));
    }
}

TEST(Triangulate, CollinearVerticesMakeNoSlivers) {
    const Polygon p = MakePolygon({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}});
    const auto tris = TriangulatePolygon(p);
    double sum = 0;
    for (const auto& t : tris) {
        EXPECT_GT(TriangleArea(p, t), 1e-9);
        sum += TriangleArea(p, t);
    }
    EXPECT_NEAR(sum, 2, 1e-12);
}

TEST(Shape, BoundsContainGeometry) {
    testing::SceneBuilder b;
    b.AddCone({0, 0, 0}, {0, 0, 2}, 1, 0.5);
    b.AddRing({1, 1, 1}, {0, 0, 1}, 0, 2);
    b.AddSource({0, 0, 1}, 0.5);
    const Bounds3 cone = ShapeBounds(b.scene().surfaces[0]);
    ExpectVecNear(cone.lo, {-1, -1, 0}, kTol);
    ExpectVecNear(cone.hi, {1, 1, 2}, kTol);
    const Bounds3 ring = ShapeBounds(b.scene().surfaces[1]);
    ExpectVecNear(ring.lo, {-1, -1, 1}, kTol);
    ExpectVecNear(ring.hi, {3, 3, 1}, kTol);
    EXPECT_TRUE(ShapeBounds(b.scene().surfaces[2]).Empty());
    EXPECT_FALSE(IntersectShape(b.scene().surfaces[2], {0, 0, 0}, {0, 0, 1}));
}

// --- side without the normal ----------------------------------------------

/// IntersectShapeSide must give IntersectShape's distance and, for its
/// normal, -Dot(dir, normal) < 0, bit for bit: on random rays, from inside and
/// outside, and on rays that graze the surface so closely (1e-16 to 1e-7 of
/// a radian off the tangent plane) that the cheap side test must hand over to
/// the normal.
TEST(ShapeSide, EqualsTheFullHitBitForBit) {
    testing::SceneBuilder b;
    b.AddSphere({0.3, -0.2, 0.1}, 0.7);
    b.AddSphere({1, 1, 1}, 0.05, true);                      // bubble
    b.AddCone({0, 0, 0}, {0.2, 0.1, 2}, 0.03, 0.03);        // cylinder
    b.AddCone({1, 0, 0}, {1, 2, 0.5}, 0.4, 0.4, true);      // tube
    b.AddCone({0, 1, 0}, {0.5, 1, 1.5}, 0.6, 0.1);          // cone
    b.AddCone({-1, 0, 0}, {-1, 0.3, 1}, 0.1, 0.5, true);    // cup
    b.AddCone({2, 2, 0}, {2, 2, 1}, 0.5, 0);                // cone to an apex
    b.AddRing({0, 0, 1}, {0.3, 0.2, 1}, 0.1, 0.6);
    b.AddPolygon({{0, 0, 0}, {1, 0, 0.2}, {0.8, 1, 0.3}, {0.1, 0.7, 0.1}});
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1, 1);
    int hits = 0, grazing = 0, backs = 0;
    const auto check = [&](const Surface& surface, const Vec3& org, const Vec3& dir) {
        const auto full = IntersectShape(surface, org, dir);
        const auto side = IntersectShapeSide(surface, org, dir);
        ASSERT_EQ(full.has_value(), side.has_value()) << org << " " << dir;
        if (!full) return;
        ++hits;
        EXPECT_EQ(side->t, full->t) << org << " " << dir;
        const bool back = -Dot(dir, full->normal) < 0.0;
        EXPECT_EQ(side->back, back) << SurfaceTypeName(surface.type) << " " << org << " " << dir;
        backs += back;
    };
    for (const Surface& surface : b.scene().surfaces) {
        const Bounds3 box = ShapeBounds(surface);
        const Vec3 mid = (box.lo + box.hi) * 0.5;
        for (int i = 0; i < 20000; ++i) {
            // Random rays through the shape's box, from near and far.
            const Vec3 target = mid + (box.hi - box.lo) * (0.6 * u(rng));
            const Vec3 org = target + testing::RandomDirection(rng) * (i % 2 ? 3.0 : 0.2);
            const Vec3 dir = Normalize(target - org);
            check(surface, org, dir);
            // A ray through a hit point, tilted out of the tangent plane by
            // 1e-16 to 1e-7.
            const auto hit = IntersectShape(surface, org, dir);
            if (!hit) continue;
            const Vec3 p = org + dir * hit->t;
            const Frame frame = Frame::Around(hit->normal);
            const double a = 2 * kPi * (0.5 + 0.5 * u(rng));
            const double tilt =
                std::copysign(std::pow(10.0, -7 - 9 * (0.5 + 0.5 * u(rng))), u(rng));
            const Vec3 graze = Normalize(frame.u * std::cos(a) + frame.v * std::sin(a) +
                                         hit->normal * tilt);
            check(surface, p - graze * (0.05 + 0.5 * (1 + u(rng))), graze);
            ++grazing;
        }
    }
    EXPECT_GT(hits, 150000);
    EXPECT_GT(grazing, 80000);
    EXPECT_GT(backs, 20000);
}

}  // namespace
}  // namespace rt
