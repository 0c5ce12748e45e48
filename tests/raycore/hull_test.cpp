// SPDX-License-Identifier: MIT
//
// The bounding polygons (raycore/hull.h), and the occlusion tests that leave
// them out, against brute force.
#include "raycore/hull.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>
#include <vector>

#include "raycore/raycore.h"
#include "tests/raycore/brute_occlusion.h"
#include "tests/raycore/test_scenes.h"

namespace rt {
namespace {

using testing::RandomSurfacePoint;
using testing::CheckShadowSegment;
using testing::SceneBuilder;

constexpr double kMargin = 1e-8;

/// A 4 x 5 x 3 room (six walls, ids 0-5), a block standing on the floor
/// (6-11, its bottom face 6 in the floor's plane), a lamp just below the
/// ceiling (12) and a sphere (13).
Scene Room(bool withLamp = true) {
    SceneBuilder b;
    const int white = b.AddMaterial(MaterialType::Plastic, "white");
    const int lamp = b.AddMaterial(MaterialType::Light, "lamp");
    b.AddBox({0, 0, 0}, {4, 5, 3}, white);
    b.AddBox({1, 1, 0}, {2, 2.5, 1.2}, white);
    b.AddPolygon({{1.5, 2, 2.99}, {2.5, 2, 2.99}, {2.5, 3, 2.99}, {1.5, 3, 2.99}},
                 withLamp ? lamp : white);
    b.AddSphere({3, 3.5, 1}, 0.5, false, white);
    return b.scene();
}

TEST(BoundingPolygons, RoomWallsAndCoplanarFacesOnly) {
    const BoundingPolygons bounds = FindBoundingPolygons(Room(), kMargin);
    // The six walls and the block's bottom, which lies in the floor's plane;
    // not the block's other faces, the lamp or anything else.
    EXPECT_EQ(bounds.surfaces, (std::vector<int>{0, 1, 2, 3, 4, 5, 6}));
    EXPECT_EQ(bounds.planes.size(), 6u);
    EXPECT_TRUE(bounds.Inside({2, 2.5, 1.5}));
    EXPECT_TRUE(bounds.Inside({0, 0, 0}));             // a corner is on every plane
    EXPECT_TRUE(bounds.Inside({2, 2.5, -0.5 * kMargin}));
    EXPECT_FALSE(bounds.Inside({2, 2.5, -2 * kMargin}));  // below the floor
    EXPECT_FALSE(bounds.Inside({4.5, 2.5, 1.5}));
    // Every inner side points into the room.
    for (const InnerHalfSpace& p : bounds.planes) EXPECT_GT(p.Distance({2, 2.5, 1.5}), 0.9);
    // All six are axis-aligned: Inside() tests them as a box.
    EXPECT_TRUE(bounds.oblique.empty());
}

TEST(BoundingPolygons, ObliquePlanesAreTestedOneByOne) {
    // A wedge: floor, two vertical walls and a sloping roof x + z <= 2.
    SceneBuilder b;
    b.AddPolygon({{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}});
    b.AddPolygon({{0, 0, 0}, {0, 0, 2}, {0, 1, 2}, {0, 1, 0}});
    b.AddPolygon({{0, 0, 2}, {2, 0, 0}, {2, 1, 0}, {0, 1, 2}});
    b.AddPolygon({{0, 0, 0}, {2, 0, 0}, {0, 0, 2}});
    b.AddPolygon({{0, 1, 0}, {0, 1, 2}, {2, 1, 0}});
    const BoundingPolygons bounds = FindBoundingPolygons(b.scene(), kMargin);
    EXPECT_EQ(bounds.surfaces.size(), 5u);
    ASSERT_EQ(bounds.oblique.size(), 1u);
    EXPECT_TRUE(bounds.Inside({0.5, 0.5, 0.5}));
    EXPECT_TRUE(bounds.Inside({1, 0.5, 1}));    // on the roof
    EXPECT_FALSE(bounds.Inside({1, 0.5, 1.01}));  // just above it
    EXPECT_FALSE(bounds.Inside({-0.01, 0.5, 0.5}));
    EXPECT_FALSE(bounds.Inside({0.5, 1.01, 0.5}));
}

TEST(BoundingPolygons, OnlyPolygonsWithEverythingOnOneSide) {
    SceneBuilder b;
    b.AddPolygon({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
    // Vertical, through the middle of the square: each has points on both
    // sides of the other's plane.
    b.AddPolygon({{0.5, -1, -0.5}, {0.5, 2, -0.5}, {0.5, 2, 2}, {0.5, -1, 2}});
    EXPECT_TRUE(FindBoundingPolygons(b.scene(), kMargin).surfaces.empty());
    // A triangle below everything bounds the scene from below.
    b.AddPolygon({{0, 0, -1}, {1, 0, -1}, {1, 1, -1}});
    const BoundingPolygons bounds = FindBoundingPolygons(b.scene(), kMargin);
    EXPECT_EQ(bounds.surfaces, (std::vector<int>{2}));
    ASSERT_EQ(bounds.planes.size(), 1u);
    EXPECT_GT(bounds.planes[0].normal.z, 0.999);
}

TEST(BoundingPolygons, PlanesAreCapped) {
    SceneBuilder b;
    // A convex prism with 20 sides: every face bounds it.
    for (int k = 0; k < 20; ++k) {
        const double a0 = 2 * kPi * k / 20, a1 = 2 * kPi * (k + 1) / 20;
        const Vec3 p0{std::cos(a0), std::sin(a0), 0}, p1{std::cos(a1), std::sin(a1), 0};
        b.AddPolygon({p0, p1, p1 + Vec3{0, 0, 1}, p0 + Vec3{0, 0, 1}});
    }
    const BoundingPolygons bounds = FindBoundingPolygons(b.scene(), kMargin, 8);
    EXPECT_EQ(bounds.planes.size(), 8u);
    EXPECT_EQ(bounds.surfaces.size(), 8u);
}

/// Shadow-ray-like segments between points on the room's surfaces, including
/// the walls the interior layer leaves out, points on edges and in corners,
/// and from points outside the room (which must still see the walls).
TEST(BoundingPolygons, OcclusionAgreesWithBruteForce) {
    const Scene scene = Room();
    const RayCore core(scene);
    std::mt19937 rng(31);
    std::uniform_real_distribution<double> u(0, 1);
    const auto onSurface = [&]() {
        return RandomSurfacePoint(core, {0.1, 0.1, 0.1}, {3.9, 4.9, 2.9}, rng);
    };
    const std::vector<Vec3> special = {{0, 0, 0},   {4, 5, 3},   {2, 0, 1.5}, {0, 2.5, 0},
                                       {1, 1, 0},   {2, 2.5, 0}, {2, 2.5, -1}, {5, 2, 1},
                                       {2, -1, 2},  {2, 2, 3.5}};
    int checked = 0, blocked = 0;
    for (int i = 0; i < 20000; ++i) {
        const Vec3 a = i < 2000 ? special[static_cast<size_t>(i) % special.size()] : onSurface();
        const Vec3 b = i % 3 == 0 ? Vec3{1.5 + u(rng), 2 + u(rng), 2.99} : onSurface();
        const auto segment = CheckShadowSegment(core, scene, a, b);
        if (!segment) continue;
        EXPECT_EQ(segment->occluded, segment->expected) << a << " -> " << b;
        ++checked;
        blocked += segment->expected;
    }
    EXPECT_GT(checked, 15000);
    EXPECT_GT(blocked, 1000);  // the block, the sphere and the walls from outside do block
}

}  // namespace
}  // namespace rt
