// SPDX-License-Identifier: MIT
//
// The light sources' plane (raycore/source_plane.h), and the occlusion tests
// that leave its polygons and the furniture's surroundings out, against
// brute force.
#include "raycore/source_plane.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
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

/// A 4 x 5 x 3 room (walls 0-5) with a block on the floor (6-11); just below
/// the ceiling, at z = 2.9, a lamp facing down (12), a white louvre beside it
/// in the same plane facing up (13), a smaller lamp elsewhere in the plane
/// (14), and a lamp on a wall (15), which is smaller and not in the plane.
Scene LitRoom() {
    SceneBuilder b;
    const int white = b.AddMaterial(MaterialType::Plastic, "white");
    const int lamp = b.AddMaterial(MaterialType::Light, "lamp");
    b.AddBox({0, 0, 0}, {4, 5, 3}, white);
    b.AddBox({1, 1, 0}, {2, 2.5, 1.2}, white);
    b.AddPolygon({{1.5, 2, 2.9}, {1.5, 3, 2.9}, {2.5, 3, 2.9}, {2.5, 2, 2.9}}, lamp);
    b.AddPolygon({{2.5, 2, 2.9}, {3.5, 2, 2.9}, {3.5, 3, 2.9}, {2.5, 3, 2.9}}, white);
    b.AddPolygon({{0.5, 4, 2.9}, {0.5, 4.5, 2.9}, {1, 4.5, 2.9}, {1, 4, 2.9}}, lamp);
    b.AddPolygon({{3.99, 1, 1}, {3.99, 1.3, 1}, {3.99, 1.3, 1.3}, {3.99, 1, 1.3}}, lamp);
    return b.scene();
}

TEST(SourcePlane, HoldsTheLargestLampAndEverythingCoplanar) {
    const Scene scene = LitRoom();
    const auto plane = FindSourcePlane(scene, std::vector<bool>(scene.surfaces.size(), false), 5);
    ASSERT_TRUE(plane);
    EXPECT_NEAR(plane->normal.z, -1, 1e-15);  // the big lamp's own normal
    EXPECT_NEAR(plane->offset, -2.9, 1e-15);
    EXPECT_EQ(plane->surfaces, (std::vector<int>{12, 13, 14}));
}

TEST(SourcePlane, OnlyAmongTheSurfacesLeftIn) {
    const Scene scene = LitRoom();
    std::vector<bool> leftOut(scene.surfaces.size(), false);
    leftOut[12] = leftOut[14] = true;  // the lamps in the plane
    const auto plane = FindSourcePlane(scene, leftOut, 5);
    ASSERT_TRUE(plane);
    EXPECT_NEAR(std::fabs(plane->normal.x), 1, 1e-15);  // the wall lamp's
    EXPECT_EQ(plane->surfaces, (std::vector<int>{15}));
    leftOut[15] = true;
    EXPECT_FALSE(FindSourcePlane(scene, leftOut, 5));
}

TEST(SourcePlane, NoneWithoutLightPolygons) {
    SceneBuilder b;
    const int white = b.AddMaterial(MaterialType::Plastic, "white");
    const int lamp = b.AddMaterial(MaterialType::Light, "lamp");
    b.AddBox({0, 0, 0}, {1, 1, 1}, white);
    b.AddSphere({0.5, 0.5, 0.5}, 0.1, false, lamp);
    const Scene scene = b.scene();
    EXPECT_FALSE(FindSourcePlane(scene, std::vector<bool>(scene.surfaces.size(), false), 1));
}

TEST(SourcePlane, ClearsOnlySegmentsWhollyOnOneSide) {
    SourcePlane plane;
    plane.normal = {0, 0, -1};
    plane.offset = -2.9;
    plane.scale = 5;
    EXPECT_TRUE(plane.Clears({1, 1, 0}, {2, 2, 2.9 - 1e-7}));  // a shadow ray's end
    EXPECT_TRUE(plane.Clears({1, 1, 2.95}, {2, 2, 3}));        // above it
    EXPECT_FALSE(plane.Clears({1, 1, 0}, {2, 2, 2.95}));       // across it
    EXPECT_FALSE(plane.Clears({1, 1, 0}, {2, 2, 2.9}));        // ends in it
    EXPECT_FALSE(plane.Clears({1, 1, 0}, {2, 2, 2.9 - 1e-9}));  // within the clearance
}

/// Segments like shadow rays toward points of the lamp plane's polygons (which
/// the layer without them must answer), and segments that cross or touch the
/// plane or run above it, where those polygons must block. Each end is a
/// point on a surface (the closest hit of a random ray), on one of the plane's
/// polygons, or in the gap between the plane and the ceiling. Segments that
/// graze an edge are skipped (RobustBruteOccluded).
TEST(SourcePlane, OcclusionAgreesWithBruteForce) {
    const Scene scene = LitRoom();
    const RayCore core(scene);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0, 1);
    const auto onSurface = [&]() {
        return RandomSurfacePoint(core, {0.1, 0.1, 0.1}, {3.9, 4.9, 2.8}, rng);
    };
    const auto inPlane = [&]() -> Vec3 {
        switch (rng() % 3) {
            case 0: return {1.5 + u(rng), 2 + u(rng), 2.9};
            case 1: return {2.5 + u(rng), 2 + u(rng), 2.9};
            default: return {0.5 + 0.5 * u(rng), 4 + 0.5 * u(rng), 2.9};
        }
    };
    const auto aboveIt = [&]() -> Vec3 { return {1.4 + 2.2 * u(rng), 1.9 + 1.2 * u(rng), 2.95}; };
    int checked = 0, blocked = 0, blockedAcross = 0;
    for (int i = 0; i < 20000; ++i) {
        const Vec3 a = i % 5 == 4 ? aboveIt() : onSurface();
        const Vec3 b = i % 2 == 0 ? inPlane() : (i % 4 == 1 ? aboveIt() : onSurface());
        const auto segment = CheckShadowSegment(core, scene, a, b);
        if (!segment) continue;
        EXPECT_EQ(segment->occluded, segment->expected) << a << " -> " << b;
        ++checked;
        blocked += segment->expected;
        if (segment->expected && (a.z > 2.9) != (b.z > 2.9) && std::min(a.z, b.z) < 2.9) {
            ++blockedAcross;
        }
    }
    EXPECT_GT(checked, 15000);
    EXPECT_GT(blocked, 2000);
    EXPECT_GT(blockedAcross, 300);  // segments through the plane's polygons
}

}  // namespace
}  // namespace rt
