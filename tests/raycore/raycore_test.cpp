// SPDX-License-Identifier: MIT
#include "raycore/raycore.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <thread>
#include <vector>

#include "core/conventions.h"
#include "raycore/shapes.h"
#include "tests/raycore/test_scenes.h"

namespace rt {
namespace {

using testing::SceneBuilder;

void ExpectVecNear(const Vec3& a, const Vec3& b, double tol) {
    EXPECT_NEAR(a.x, b.x, tol) << a << " vs " << b;
    EXPECT_NEAR(a.y, b.y, tol) << a << " vs " << b;
    EXPECT_NEAR(a.z, b.z, tol) << a << " vs " << b;
}

constexpr double kInf = std::numeric_limits<double>::infinity();

double MaxAbsForTest(const Vec3& v) {
    return std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
}

int MaterialTypeNameForTest(MaterialType type) { return static_cast<int>(type); }

using testing::RandomDirection;

TEST(RayCore, EmptySceneAndSourcesOnly) {
    SceneBuilder b;
    b.AddSource({0, 0, 1}, 0.5);
    RayCore core(b.scene());
    EXPECT_FALSE(core.Intersect({0, 0, 0}, {0, 0, 1}, 0));
    EXPECT_FALSE(core.Occluded({0, 0, 0}, {0, 0, 1}, 0));
    EXPECT_FALSE(core.IntersectSurface(0, {0, 0, 0}, {0, 0, 1}));
}

TEST(RayCore, EachShapeKind) {
    SceneBuilder b;
    const int plastic = b.AddMaterial(MaterialType::Plastic);
    const int square = b.AddPolygon({{-1, -1, 10}, {1, -1, 10}, {1, 1, 10}, {-1, 1, 10}}, plastic);
    const int sphere = b.AddSphere({5, 0, 0}, 1, false, plastic);
    const int bubble = b.AddSphere({-5, 0, 0}, 1, true);  // void: still geometry
    const int cyl = b.AddCone({0, 5, -1}, {0, 5, 1}, 1, 1, false, plastic);
    const int cone = b.AddCone({0, -5, 0}, {0, -5, 1}, 1, 0, false, plastic);
    const int ring = b.AddRing({0, 0, -10}, {0, 0, 1}, 1, 2, plastic);
    b.AddSource({0, 0, 1}, 0.5, plastic);
    RayCore core(b.scene());
    const Vec3 o{0, 0, 0};

    auto h = core.Intersect(o, {0, 0, 1}, 0);
    ASSERT_TRUE(h);
    EXPECT_EQ(h->surface, square);
    EXPECT_NEAR(h->t, 10, 1e-12);
    ExpectVecNear(h->point, {0, 0, 10}, 1e-12);
    ExpectVecNear(h->normal, {0, 0, 1}, 0);

    h = core.Intersect(o, {1, 0, 0}, 0);
    ASSERT_TRUE(h);
    EXPECT_EQ(h->surface, sphere);
    EXPECT_NEAR(h->t, 4, 1e-12);
    ExpectVecNear(h->normal, {-1, 0, 0}, 1e-12);

    h = core.Intersect(o, {-1, 0, 0}, 0);
    ASSERT_TRUE(h);
    EXPECT_EQ(h->surface, bubble);
    ExpectVecNear(h->point, {-4, 0, 0}, 1e-12);
    ExpectVecNear(h->normal, {-1, 0, 0}, 1e-12);  // inward: towards the bubble's centre

    h = core.Intersect(o, {0, 1, 0}, 0);
    ASSERT_TRUE(h);
    EXPECT_EQ(h->surface, cyl);
    EXPECT_NEAR(h->t, 4, 1e-12);
    ExpectVecNear(h->normal, {0, -1, 0}, 1e-12);

    h = core.Intersect({0, 0, 0.5}, {0, -1, 0}, 0);
    ASSERT_TRUE(h);
    EXPECT_EQ(h->surface, cone);
    EXPECT_NEAR(h->t, 4.5, 1e-12);
    ExpectVecNear(h->normal, Normalize({0, 1, 1}), 1e-12);

    EXPECT_FALSE(core.Intersect(o, {0, 0, -1}, 0));  // through the ring's hole
    h = core.Intersect({1.5, 0, 0}, {0, 0, -1}, 0);
    ASSERT_TRUE(h);
    EXPECT_EQ(h->surface, ring);
    EXPECT_NEAR(h->t, 10, 1e-12);
    ExpectVecNear(h->normal, {0, 0, 1}, 0);

    // tmax excludes farther hits; tmax <= 0 means unlimited.
    EXPECT_FALSE(core.Intersect(o, {1, 0, 0}, 3.9));
    EXPECT_TRUE(core.Intersect(o, {1, 0, 0}, 4.1));
    EXPECT_FALSE(core.Occluded(o, {1, 0, 0}, 3.9));
    EXPECT_TRUE(core.Occluded(o, {1, 0, 0}, 4.1));
    EXPECT_TRUE(core.Occluded(o, {1, 0, 0}, -1));

    // IntersectSurface sees only the one surface.
    h = core.IntersectSurface(sphere, {10, 0, 0}, {-1, 0, 0});
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 4, 1e-12);
    EXPECT_FALSE(core.IntersectSurface(sphere, o, {0, 0, 1}));
    h = core.IntersectSurface(square, {0.5, 0.5, 20}, {0, 0, -1});
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 10, 1e-12);
}

TEST(RayCore, ConcavePolygonNotch) {
    SceneBuilder b;
    b.AddPolygon({{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}});
    RayCore core(b.scene());
    EXPECT_FALSE(core.Intersect({1.5, 1.5, 1}, {0, 0, -1}, 0));
    EXPECT_FALSE(core.Occluded({1.5, 1.5, 1}, {0, 0, -1}, 0));
    for (const Vec3 p : {Vec3{0.5, 1.5, 1}, Vec3{1.5, 0.5, 1}, Vec3{0.5, 0.5, 1}}) {
        auto h = core.Intersect(p, {0, 0, -1}, 0);
        ASSERT_TRUE(h) << p;
        EXPECT_NEAR(h->t, 1, 1e-12);
    }
}

// Polygons reach Embree as quads made of triangle pairs, plus a lone triangle
// for an odd count: every part of a regular n-gon must be hit, nothing outside.
TEST(RayCore, PolygonsOfEveryVertexCountAreCovered) {
    for (int n = 3; n <= 9; ++n) {
        SceneBuilder b;
        std::vector<Vec3> vertices;
        for (int k = 0; k < n; ++k) {
            const double phi = 2 * kPi * k / n;
            vertices.push_back({std::cos(phi), std::sin(phi), 0});
        }
        b.AddPolygon(vertices);
        RayCore core(b.scene());
        const double inner = std::cos(kPi / n);  // inscribed circle radius
        for (int k = 0; k < 360; ++k) {
            const double phi = 2 * kPi * (k + 0.5) / 360;
            const Vec3 dir{std::cos(phi), std::sin(phi), 0};
            for (double r : {0.1, 0.5, 0.99 * inner}) {
                EXPECT_TRUE(core.Intersect(dir * r + Vec3{0, 0, 1}, {0, 0, -1}, 0))
                    << n << "-gon, inside at " << dir * r;
            }
            EXPECT_FALSE(core.Intersect(dir * 1.01 + Vec3{0, 0, 1}, {0, 0, -1}, 0))
                << n << "-gon, outside at " << dir * 1.01;
        }
    }
}

TEST(RayCore, RaysFromFarAwayAreAdvancedNotRejected) {
    // Embree's float rays must stay within ~1.8e19 of the origin; a ray from
    // much farther must still find the scene, with the exact distance.
    SceneBuilder b;
    b.AddPolygon({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
    RayCore core(b.scene());
    for (double far : {1e3, 1e10, 1e14, 1e25}) {
        auto h = core.Intersect({0.5, 0.5, far}, {0, 0, -1}, 0);
        ASSERT_TRUE(h) << far;
        EXPECT_NEAR(h->t, far, 1e-15 * far);
        EXPECT_NEAR(h->point.z, 0, 1e-9 * far);
        EXPECT_TRUE(core.Occluded({0.5, 0.5, far}, {0, 0, -1}, 0));
        EXPECT_FALSE(core.Intersect({0.5, 0.5, far}, {0, 0, -1}, far / 2));  // -ld stops short
        EXPECT_FALSE(core.Intersect({0.5, 0.5, far}, {0, 0, 1}, 0));        // looking away
    }
    // Origins too far to place near the scene in double miss, without crashing.
    for (double far : {1e200}) {
        EXPECT_FALSE(core.Intersect({0.5, 0.5, far}, {0, 0, -1}, 0));
        EXPECT_FALSE(core.Occluded({0.5, 0.5, far}, {0, 0, -1}, 0));
    }
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_FALSE(core.Intersect({inf, 0, 0}, {-1, 0, 0}, 0));
    EXPECT_FALSE(core.Occluded({0, std::nan(""), 0}, {0, 0, -1}, 0));
}

TEST(RayCore, RayStartingOnSurfaceFindsTheNextOne) {
    SceneBuilder b;
    const int lower = b.AddPolygon({{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}});
    const int upper = b.AddPolygon({{-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}});
    const int ball = b.AddSphere({0, 0, 3}, 0.5);
    RayCore core(b.scene());
    // Exactly on the lower plane.
    auto h = core.Intersect({0.3, 0.2, 0}, {0, 0, 1}, 0);
    ASSERT_TRUE(h);
    EXPECT_EQ(h->surface, upper);
    EXPECT_NEAR(h->t, 1, 1e-12);
    EXPECT_FALSE(core.Occluded({0.3, 0.2, 0}, {0, 0, -1}, 0));
    // Bounce chains: start where the previous hit was, oblique directions.
    std::mt19937 rng(3);
    for (int i = 0; i < 1000; ++i) {
        Vec3 d = RandomDirection(rng);
        d.z = std::fabs(d.z) + 0.05;
        d = Normalize(d);
        auto first = core.Intersect({0.1, -0.2, 0.5}, {0, 0, -1}, 0);
        ASSERT_TRUE(first);
        ASSERT_EQ(first->surface, lower);
        auto next = core.Intersect(first->point, d, 0);
        if (next) {
            EXPECT_NE(next->surface, lower);
            EXPECT_GT(next->t, 0.5);
        }
    }
    // Sphere: leaving from its surface sees nothing of it; entering sees the far side.
    h = core.Intersect({0, 0, 3.5}, {0, 0, 1}, 0);
    EXPECT_FALSE(h);
    h = core.Intersect({0, 0, 2.5}, {0, 0, 1}, 0);
    ASSERT_TRUE(h);
    EXPECT_EQ(h->surface, ball);
    EXPECT_NEAR(h->t, 1, 1e-12);
    // Bounce off the sphere's own hit points (computed, so slightly off the surface).
    for (int i = 0; i < 1000; ++i) {
        const Vec3 d = RandomDirection(rng);
        auto in = core.Intersect({0, 0, 3}, d, 0);
        ASSERT_TRUE(in);
        ASSERT_EQ(in->surface, ball);
        auto out = core.Intersect(in->point, d, 0);  // continue outwards
        if (out) {
            EXPECT_NE(out->surface, ball);
        }
        auto back = core.Intersect(in->point, -d, 0);  // back in: far side, 1 away
        ASSERT_TRUE(back);
        EXPECT_EQ(back->surface, ball);
        EXPECT_NEAR(back->t, 1, 1e-9);
    }
}

/// A ray leaving a floor point 3e-7 from a wall that stands on the floor,
/// towards the wall, meets it 4.2e-7 away: nearer than the distance tolerance
/// (1e-6), which Radiance's rule discards, so the ray used to pass through
/// the wall and out of the room. Given the floor's normal (`leaving`), the
/// wall is hit; a surface coincident with the floor (a decal 2e-7 above it)
/// is still discarded, as is the floor itself.
TEST(RayCore, RayLeavingASurfaceHitsAWallMeetingIt) {
    SceneBuilder b;
    const int m = b.AddMaterial(MaterialType::Plastic);
    const int floor = b.AddPolygon({{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}, m);
    b.AddPolygon({{0, -1, 2e-7}, {1, -1, 2e-7}, {1, 1, 2e-7}, {0, 1, 2e-7}}, m);
    const int wall = b.AddPolygon({{1, -1, 0}, {1, 1, 0}, {1, 1, 1}, {1, -1, 1}}, m);
    // A ball standing in the floor (centre on it): the floor meets it at right angles.
    const int ball = b.AddSphere({-0.5, 0, 0}, 0.25, false, m);
    RayCore core(b.scene());
    const Vec3 up{0, 0, 1}, down{0, 0, -1};
    const double gap = 3e-7;

    const Vec3 nearWall{1 - gap, 0.2, 0};
    const Vec3 towardsWall = Normalize({1, 0, 1});
    EXPECT_FALSE(core.Intersect(nearWall, towardsWall, 0));  // Radiance's rule alone
    EXPECT_FALSE(core.Occluded(nearWall, towardsWall, 0));
    for (const Vec3* leaving : {&up, &down}) {
        const auto h = core.Intersect(nearWall, towardsWall, 0, leaving);
        ASSERT_TRUE(h);
        EXPECT_EQ(h->surface, wall);
        EXPECT_NEAR(h->t, gap * std::sqrt(2.0), 1e-15);
        EXPECT_TRUE(core.Occluded(nearWall, towardsWall, 0, Occluders::All, -1, leaving));
        EXPECT_TRUE(core.Occluded(nearWall, towardsWall, 1, Occluders::All, -1, leaving));
        EXPECT_FALSE(core.Occluded(nearWall, towardsWall, 4e-7, Occluders::All, -1, leaving));
        // Away from the wall: nothing, neither the floor nor the decal.
        EXPECT_FALSE(core.Intersect(nearWall, Normalize({-1, 0, 1}), 0, leaving));
        EXPECT_FALSE(core.Intersect(nearWall, up, 0, leaving));
    }

    const Vec3 nearBall{-0.25 + gap, 0, 0};
    const Vec3 towardsBall = Normalize({-1, 0, 1});
    const auto farSide = core.Intersect(nearBall, towardsBall, 0);  // through the near side
    ASSERT_TRUE(farSide);
    EXPECT_GT(farSide->t, 0.1);
    const auto h = core.Intersect(nearBall, towardsBall, 0, &up);
    ASSERT_TRUE(h);
    EXPECT_EQ(h->surface, ball);
    EXPECT_NEAR(h->t, gap * std::sqrt(2.0), 1e-12);
    EXPECT_TRUE(core.Occluded(nearBall, towardsBall, 0, Occluders::All, -1, &up));

    // Leaving the ball or the wall near the floor, the floor is hit; leaving
    // the floor itself from a computed hit point, it is not found again.
    const Vec3 onBall{-0.25, 0, gap}, ballNormal{1, 0, 0};
    const auto fromBall = core.Intersect(onBall, Normalize({1, 0, -1}), 0, &ballNormal);
    ASSERT_TRUE(fromBall);
    EXPECT_EQ(fromBall->surface, floor);
    EXPECT_FALSE(core.Intersect(onBall, Normalize({1, 0, -1}), 0));
    std::mt19937 rng(5);
    for (int i = 0; i < 1000; ++i) {
        Vec3 d = RandomDirection(rng);
        d.z = -std::fabs(d.z) - 0.05;
        d = Normalize(d);
        const auto first = core.Intersect({-0.9, 0.3, 0.5}, d, 0);
        if (!first || first->surface != floor) continue;
        const Vec3 out = d - first->normal * (2 * Dot(d, first->normal));
        const auto next = core.Intersect(first->point, out, 0, &first->normal);
        if (next) {
            EXPECT_NE(next->surface, floor);
        }
    }
}

// Unit-scale box [-1,1]³ placed at `centre` and scaled by `scale`; rays from its
// centre towards every vertex, every edge midpoint, many points exactly on
// edges, and random directions, must all hit a wall at the analytic distance.
void CheckClosedBox(const Vec3& centre, double scale) {
    SceneBuilder b;
    const Vec3 h{scale, scale, scale};
    b.AddBox(centre - h, centre + h);
    Scene& scene = b.scene();
    RayCore core(scene);

    std::vector<Vec3> targets;
    for (int x = -1; x <= 1; ++x) {
        for (int y = -1; y <= 1; ++y) {
            for (int z = -1; z <= 1; ++z) {
                const int onSurface = (x != 0) + (y != 0) + (z != 0);
                if (onSurface >= 2) targets.push_back({double(x), double(y), double(z)});
            }
        }
    }
    // Points along each of the 12 edges (exactly on the shared edge in
    // double; the float ray may fall either side, never between).
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int axis = 0; axis < 3; ++axis) {
        for (int s1 : {-1, 1}) {
            for (int s2 : {-1, 1}) {
                for (int k = 0; k < 100; ++k) {
                    Vec3 p;
                    p[axis] = u(rng);
                    p[(axis + 1) % 3] = s1;
                    p[(axis + 2) % 3] = s2;
                    targets.push_back(p);
                }
            }
        }
    }
    std::vector<Vec3> dirs;
    for (const Vec3& t : targets) dirs.push_back(Normalize(t));
    for (int k = 0; k < 3000; ++k) dirs.push_back(RandomDirection(rng));

    int escaped = 0;
    for (const Vec3& d : dirs) {
        const double expected = scale / std::max({std::fabs(d.x), std::fabs(d.y), std::fabs(d.z)});
        auto hit = core.Intersect(centre, d, 0);
        if (!hit) {
            ++escaped;
            ADD_FAILURE() << "escaped along " << d;
            continue;
        }
        EXPECT_NEAR(hit->t / scale, expected / scale, 1e-9 + 1e-15 * MaxAbsForTest(centre) / scale)
            << d;
        EXPECT_TRUE(core.Occluded(centre, d, 0)) << d;
        EXPECT_FALSE(core.Occluded(centre, d, expected * 0.999)) << d;
        // The reported wall is the one the point lies on, facing outwards.
        const Vec3 local = (hit->point - centre) / scale;
        const Vec3& n = hit->normal;
        EXPECT_NEAR(Dot(local, n), 1, 1e-6) << d;
    }
    EXPECT_EQ(escaped, 0);

    // Random walks: each bounce starts exactly where the last hit was (on a
    // face, sometimes on an edge or corner) and goes back into the box.
    // Every ray must find another face, never the one it starts on.
    const Vec3 corner = centre + Vec3{scale, scale, scale};
    std::vector<Vec3> starts{corner, centre + Vec3{scale, scale, 0},
                             centre + Vec3{0, -scale, scale}};
    for (int walk = 0; walk < 200; ++walk) {
        Vec3 p = walk < 3 ? starts[static_cast<size_t>(walk)] : centre;
        for (int bounce = 0; bounce < 10; ++bounce) {
            Vec3 d = RandomDirection(rng);
            // Into the box: every axis on which p lies on a face turns inwards.
            const Vec3 local = (p - centre) / scale;
            for (int a = 0; a < 3; ++a) {
                if (std::fabs(std::fabs(local[a]) - 1) < 1e-6 && d[a] * local[a] > 0) d[a] = -d[a];
            }
            // Analytic distance to the wall ahead. Walls closer than kFtiny
            // are discarded by Radiance's rule (at scale 1e-4 that is 1% of
            // the box), so such rays legitimately leave: draw another one.
            double exit = kInf;
            for (int a = 0; a < 3; ++a) {
                if (d[a] != 0) {
                    const double face = centre[a] + (d[a] > 0 ? scale : -scale);
                    exit = std::min(exit, (face - p[a]) / d[a]);
                }
            }
            if (exit <= 2 * kFtiny) {
                --bounce;
                continue;
            }
            auto hit = core.Intersect(p, d, 0);
            if (!hit) {
                ++escaped;
                ADD_FAILURE() << "escaped from " << local << " along " << d;
                break;
            }
            EXPECT_NEAR(hit->t / scale, exit / scale, 1e-9 + 1e-15 * MaxAbsForTest(centre) / scale);
            EXPECT_GT(Dot(d, hit->normal), 0) << "hit a wall from outside";
            p = hit->point;
        }
    }
    EXPECT_EQ(escaped, 0);
}

TEST(RayCore, ClosedBoxNeverLeaks) { CheckClosedBox({0, 0, 0}, 1); }

TEST(RayCore, ClosedBoxFarAndSmall) { CheckClosedBox({1e6, -2e6, 5e5}, 1e-4); }

TEST(RayCore, ClosedBoxFarAndLarge) { CheckClosedBox({1e6, -2e6, 5e5}, 1e4); }

TEST(RayCore, CoincidentPolygonsFollowRadianceRule) {
    auto square = [](double z) {
        return std::vector<Vec3>{{-1, -1, z}, {1, -1, z}, {1, 1, z}, {-1, 1, z}};
    };
    struct Case {
        MaterialType first, second;  // material types; materials 0 and 1 in that order
        bool firstVoid, secondVoid;
        bool swapSurfaces;  // add the second material's surface first
        int winner;         // 0: surface with `first`, 1: with `second`
    };
    const Case cases[] = {
        {MaterialType::Plastic, MaterialType::Plastic, true, false, false, 1},  // void loses
        {MaterialType::Plastic, MaterialType::Plastic, false, true, false, 0},
        {MaterialType::Plastic, MaterialType::Plastic, true, false, true, 1},
        {MaterialType::Plastic, MaterialType::Glass, false, false, false, 0},  // opaque wins
        {MaterialType::Plastic, MaterialType::Trans, false, false, true, 0},
        {MaterialType::Dielectric, MaterialType::Metal, false, false, false, 1},
        {MaterialType::Plastic, MaterialType::Metal, false, false, false, 1},  // later modifier
        {MaterialType::Plastic, MaterialType::Metal, false, false, true, 1},
        {MaterialType::Glass, MaterialType::Interface, false, false, true, 1},
    };
    for (const Case& c : cases) {
        for (double gap : {0.0, 0.5e-6}) {
            SceneBuilder b;
            const int m0 = b.AddMaterial(c.first);
            const int m1 = b.AddMaterial(c.second);
            const int mat0 = c.firstVoid ? -1 : m0;
            const int mat1 = c.secondVoid ? -1 : m1;
            int s0, s1;
            if (c.swapSurfaces) {
                s1 = b.AddPolygon(square(2 + gap), mat1);
                s0 = b.AddPolygon(square(2), mat0);
            } else {
                s0 = b.AddPolygon(square(2), mat0);
                s1 = b.AddPolygon(square(2 + gap), mat1);
            }
            RayCore core(b.scene());
            for (const Vec3 d : {Vec3{0, 0, 1}, Normalize({0.2, -0.1, 1})}) {
                auto h = core.Intersect({0, 0, 0}, d, 0);
                ASSERT_TRUE(h);
                EXPECT_EQ(h->surface, c.winner == 0 ? s0 : s1)
                    << MaterialTypeNameForTest(c.first) << " vs "
                    << MaterialTypeNameForTest(c.second) << " gap " << gap;
            }
        }
    }
    // Same material: the first surface (lower index) is kept.
    SceneBuilder b;
    const int m = b.AddMaterial(MaterialType::Plastic);
    const int a = b.AddPolygon(square(2), m);
    b.AddPolygon(square(2), m);
    RayCore core(b.scene());
    EXPECT_EQ(core.Intersect({0.1, 0.1, 0}, {0, 0, 1}, 0)->surface, a);
    // Same material, within kFtiny but not at the same distance: the nearer
    // one, from either side and in either order (a ray stopping on the
    // farther one would start its reflections behind the nearer one).
    for (const bool nearFirst : {true, false}) {
        SceneBuilder bn;
        const int mn = bn.AddMaterial(MaterialType::Plastic);
        const int lower = nearFirst ? bn.AddPolygon(square(2 - 5e-7), mn) : -1;
        const int upper = bn.AddPolygon(square(2), mn);
        const int lower2 = nearFirst ? lower : bn.AddPolygon(square(2 - 5e-7), mn);
        RayCore coreN(bn.scene());
        EXPECT_EQ(coreN.Intersect({0.1, 0.1, 0}, {0, 0, 1}, 0)->surface, lower2) << nearFirst;
        EXPECT_EQ(coreN.Intersect({0.1, 0.1, 4}, {0, 0, -1}, 0)->surface, upper) << nearFirst;
    }
    // More than kFtiny apart: the nearer one, whatever its material.
    SceneBuilder b2;
    const int glass = b2.AddMaterial(MaterialType::Glass);
    const int near = b2.AddPolygon(square(2), -1);
    b2.AddPolygon(square(2 + 3e-6), glass);
    RayCore core2(b2.scene());
    EXPECT_EQ(core2.Intersect({0, 0, 0}, {0, 0, 1}, 0)->surface, near);
}

TEST(RayCore, CoincidentRingAndPolygon) {
    // The rule holds across geometry kinds (user geometry vs triangles).
    for (bool ringHasMaterial : {false, true}) {
        SceneBuilder b;
        const int m = b.AddMaterial(MaterialType::Plastic);
        const int poly = b.AddPolygon({{-3, -3, 2}, {3, -3, 2}, {3, 3, 2}, {-3, 3, 2}},
                                      ringHasMaterial ? -1 : m);
        const int ring = b.AddRing({0, 0, 2}, {0, 0, 1}, 0, 2, ringHasMaterial ? m : -1);
        RayCore core(b.scene());
        auto h = core.Intersect({0.5, 0.5, 0}, {0, 0, 1}, 0);
        ASSERT_TRUE(h);
        EXPECT_EQ(h->surface, ringHasMaterial ? ring : poly);
        h = core.Intersect({0.5, 0.5, 4}, {0, 0, -1}, 0);
        ASSERT_TRUE(h);
        EXPECT_EQ(h->surface, ringHasMaterial ? ring : poly);
    }
}

// Spheres, cylinders, cones, rings and polygons scattered in a box: Embree's
// answer must equal the brute-force minimum over exact IntersectSurface, and
// Occluded must agree with Intersect.
Scene MixedScene() {
    SceneBuilder b;
    const int m = b.AddMaterial(MaterialType::Plastic);
    b.AddBox({-10, -10, -10}, {10, 10, 10}, m);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> pos(-8, 8), size(0.3, 2);
    for (int i = 0; i < 20; ++i) {
        const Vec3 c{pos(rng), pos(rng), pos(rng)};
        switch (i % 5) {
            case 0:
                b.AddSphere(c, size(rng), i % 2 == 1, m);
                break;
            case 1:
                b.AddCone(c, c + RandomDirection(rng) * size(rng) * 2, size(rng), size(rng), false,
                          m);
                break;
            case 2: {
                const double r = size(rng);
                b.AddCone(c, c + RandomDirection(rng) * 2, r, r, true, m);
                break;
            }
            case 3: {
                const double r = size(rng);
                b.AddRing(c, RandomDirection(rng), r * 0.3, r, m);
                break;
            }
            case 4: {
                const Vec3 n = RandomDirection(rng);
                const Frame f = Frame::Around(n);
                const double s = size(rng);
                b.AddPolygon({c + f.ToWorld({0, 0, 0}), c + f.ToWorld({2 * s, 0, 0}),
                              c + f.ToWorld({2 * s, s, 0}), c + f.ToWorld({s, s, 0}),
                              c + f.ToWorld({s, 2 * s, 0}), c + f.ToWorld({0, 2 * s, 0})},
                             m);
                break;
            }
        }
    }
    return b.scene();
}

TEST(RayCore, MatchesBruteForceAndOccluded) {
    const Scene scene = MixedScene();
    RayCore core(scene);
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> pos(-9, 9), len(0, 30);
    int hits = 0, mismatches = 0;
    for (int i = 0; i < 20000; ++i) {
        const Vec3 org{pos(rng), pos(rng), pos(rng)};
        const Vec3 dir = RandomDirection(rng);
        const double tmax = i % 3 == 0 ? 0.0 : len(rng);
        std::optional<Hit> best;
        for (int s = 0; s < static_cast<int>(scene.surfaces.size()); ++s) {
            auto h = core.IntersectSurface(s, org, dir);
            if (h && (tmax <= 0 || h->t < tmax) && (!best || h->t < best->t)) best = h;
        }
        const auto hit = core.Intersect(org, dir, tmax);
        EXPECT_EQ(core.Occluded(org, dir, tmax), hit.has_value()) << org << dir << tmax;
        if (hit.has_value() != best.has_value() ||
            (hit && (hit->surface != best->surface || std::fabs(hit->t - best->t) > 1e-9))) {
            ++mismatches;
            ADD_FAILURE() << org << " " << dir << " tmax " << tmax << ": embree "
                          << (hit ? hit->surface : -1) << " brute " << (best ? best->surface : -1);
            continue;
        }
        if (hit) {
            ++hits;
            ExpectVecNear(hit->normal, best->normal, 1e-12);
            ExpectVecNear(hit->point, org + dir * hit->t, 1e-12);
        }
    }
    EXPECT_EQ(mismatches, 0);
    EXPECT_GT(hits, 10000);
}

TEST(RayCore, ConcurrentQueriesAgree) {
    const Scene scene = MixedScene();
    RayCore core(scene);
    std::mt19937 rng(13);
    std::uniform_real_distribution<double> pos(-9, 9);
    std::vector<std::pair<Vec3, Vec3>> rays;
    for (int i = 0; i < 4000; ++i)
        rays.push_back({{pos(rng), pos(rng), pos(rng)}, RandomDirection(rng)});
    std::vector<int> expected;
    for (const auto& [o, d] : rays) {
        auto h = core.Intersect(o, d, 0);
        expected.push_back(h ? h->surface : -1);
    }
    std::vector<int> errors(4, 0);
    std::vector<std::thread> threads;
    for (int t = 0; t < 4; ++t) {
        threads.emplace_back([&, t] {
            for (int rep = 0; rep < 3; ++rep) {
                for (size_t i = 0; i < rays.size(); ++i) {
                    auto h = core.Intersect(rays[i].first, rays[i].second, 0);
                    if ((h ? h->surface : -1) != expected[i]) ++errors[static_cast<size_t>(t)];
                }
            }
        });
    }
    for (auto& th : threads) th.join();
    for (int e : errors) EXPECT_EQ(e, 0);
}

TEST(RayCore, FarFromSceneOrigin) {
    // A small scene far from the coordinate origin, rays from outside it.
    SceneBuilder b;
    const Vec3 c{1e6, -2e6, 5e5};
    const int s = b.AddSphere(c, 0.01);
    b.AddBox(c + Vec3{-1, -1, -1}, c + Vec3{1, 1, 1});
    RayCore core(b.scene());
    auto h = core.Intersect(c + Vec3{0, 0, 0.5}, {0, 0, -1}, 0);
    ASSERT_TRUE(h);
    EXPECT_EQ(h->surface, s);
    EXPECT_NEAR(h->t, 0.49, 1e-9);
    ExpectVecNear(h->point, c + Vec3{0, 0, 0.01}, 1e-9);
    // From outside the box, 100 units away.
    h = core.Intersect(c + Vec3{100, 0.5, 0.5}, {-1, 0, 0}, 0);
    ASSERT_TRUE(h);
    EXPECT_NEAR(h->t, 99, 1e-9);
    ExpectVecNear(h->normal, {1, 0, 0}, 0);
}

}  // namespace
}  // namespace rt
