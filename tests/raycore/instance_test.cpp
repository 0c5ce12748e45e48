// SPDX-License-Identifier: MIT
//
// Instances in the ray core: a prototype placed by transforms must give the
// hits that the same surfaces give when transformed into the world (as xform
// writes them), to double precision, including Radiance's coincidence rule
// across instances; and the shortcuts for shadow rays (bounding polygons, the
// light sources' plane) must keep instances as occluders.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "raycore/raycore.h"
#include "tests/raycore/test_scenes.h"
#include "scene/loader.h"
#include "scene/transform.h"

namespace rt {
namespace {

// Every surface kind, a transparent polygon coincident with an opaque one
// (the opaque one must win from both sides), in object coordinates.
const char* const kMaterials = R"(
void plastic white 0 0 5 .5 .5 .5 0 0
void trans clear 0 0 7 .5 .5 .5 0 0 .5 .5
void light lamp 0 0 3 10 10 10
)";
const char* const kObject = R"(
white polygon floor 0 0 12 0 0 0  1 0 0  1 1 0  0 1 0
clear polygon film 0 0 12 0 0 0  1 0 0  1 1 0  0 1 0
white polygon slope 0 0 12 0 0 .2  1 0 .5  1 1 .5  0 1 .2
white sphere ball 0 0 4 .5 .5 .6 .25
white cylinder post 0 0 7 .1 .1 0 .1 .1 .9 .05
white cone spike 0 0 8 .8 .2 0 .8 .2 .7 .15 0
white ring disc 0 0 8 .3 .8 .3 0 .3 1 .05 .2
)";

std::vector<SceneObject> Parse(const std::string& text) {
    std::istringstream in(text);
    return ReadSceneObjects(in, "t.rad", {}, {});
}

struct Placement {
    std::vector<std::string> words;  // transform arguments
};

const std::vector<Placement> kPlacements = {
    {{"-rz", "30", "-s", "1.7", "-t", "3", "-2", "1"}},
    {{"-mx", "-s", "0.5", "-t", "-2", "0", "0"}},
    {{"-ry", "90", "-rx", "-20", "-t", "1", "4", "2"}},
};

/// The object placed by kPlacements, as world surfaces (xform's rewriting)
/// after `extra`.
Scene WorldScene(const std::string& extra) {
    std::vector<SceneObject> objects = Parse(std::string(kMaterials) + extra);
    for (const Placement& p : kPlacements) {
        XformSettings settings;
        settings.transform = ParseTransformArgs(p.words).transform;
        for (const SceneObject& o : Parse(kObject)) objects.push_back(TransformSceneObject(o, settings));
    }
    return BuildScene(objects, {});
}

/// `object`'s surfaces as a prototype.
Prototype PrototypeOf(const Scene& object) {
    Prototype prototype;
    prototype.file = "object";
    prototype.surfaces = object.surfaces;
    prototype.cubeOrigin = object.cubeOrigin;
    prototype.cubeSize = object.cubeSize;
    return prototype;
}

/// The same, as one prototype and three instances of it.
Scene InstancedScene(const std::string& extra) {
    Scene scene = BuildScene(Parse(std::string(kMaterials) + extra), {});
    scene.prototypes.push_back(
        PrototypeOf(BuildScene(Parse(std::string(kMaterials) + kObject), {})));
    for (const Placement& p : kPlacements) {
        Instance instance;
        instance.prototype = 0;
        instance.renderFromObject = ParseTransformArgs(p.words).transform;
        instance.renderFromObject.scale = std::fabs(instance.renderFromObject.scale);
        instance.objectFromRender = Inverse(instance.renderFromObject);
        scene.instances.push_back(instance);
    }
    scene.cubeSize = 0;  // bounds from the geometry, as for hand-built scenes
    return scene;
}

using testing::RandomDirection;

TEST(Instances, HitsEqualTheSurfacesTransformedIntoTheWorld) {
    const Scene world = WorldScene("");
    const Scene instanced = InstancedScene("");
    const RayCore worldCore(world), instancedCore(instanced);
    const std::size_t perInstance = world.surfaces.size() / kPlacements.size();
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> pos(-4, 6), unit(0, 1);
    int hits = 0, filmHits = 0;
    for (int i = 0; i < 30000; ++i) {
        // Half the rays start on a surface, as reflected and shadow rays do;
        // most aim at a point of one placement's cube.
        Vec3 org{pos(rng), pos(rng), pos(rng)};
        if (i % 2 == 1) {
            if (const auto h = worldCore.Intersect(org, RandomDirection(rng), 0)) org = h->point;
        }
        Vec3 dir = RandomDirection(rng);
        if (i % 4 != 0) {
            const Instance& in = instanced.instances[static_cast<std::size_t>(i) % kPlacements.size()];
            const Vec3 target = in.renderFromObject.Point({unit(rng), unit(rng), unit(rng)});
            if (LengthSquared(target - org) > 1e-12) dir = Normalize(target - org);
        }
        const auto w = worldCore.Intersect(org, dir, 0);
        const auto h = instancedCore.Intersect(org, dir, 0);
        ASSERT_EQ(w.has_value(), h.has_value()) << org << " " << dir;
        EXPECT_EQ(worldCore.Occluded(org, dir, 0), w.has_value());
        EXPECT_EQ(instancedCore.Occluded(org, dir, 0), h.has_value());
        if (!w) continue;
        ++hits;
        // The same surface of the same placement: world surfaces are
        // placement-major, like the instances.
        ASSERT_GE(h->instance, 0);
        EXPECT_EQ(static_cast<std::size_t>(w->surface),
                  static_cast<std::size_t>(h->instance) * perInstance + static_cast<std::size_t>(h->surface))
            << org << " " << dir;
        const Surface& ws = world.surfaces[static_cast<std::size_t>(w->surface)];
        const Surface& hs = instanced.HitSurface(h->instance, h->surface);
        EXPECT_EQ(ws.name, hs.name);
        EXPECT_EQ(ws.material, hs.material);
        filmHits += hs.name == "film";
        const double scale = std::max(1.0, std::fabs(w->t));
        EXPECT_NEAR(h->t, w->t, 1e-9 * scale);
        for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(h->point[k], w->point[k], 1e-9 * scale);
            EXPECT_NEAR(h->normal[k], w->normal[k], 1e-9);
        }
        EXPECT_EQ(h->shadingNormal, h->normal);
    }
    EXPECT_GT(hits, 10000);
    EXPECT_EQ(filmHits, 0);  // the opaque floor always wins over the coincident film
}

/// Inside a closed room with a lamp, shadow rays go to the layers without the
/// walls (and without the lamp's plane): the instances must still block them.
TEST(Instances, ShadowShortcutsKeepInstancesAsOccluders) {
    const std::string room = R"(
white polygon rfloor 0 0 12 -5 -5 -1  9 -5 -1  9 9 -1  -5 9 -1
white polygon rceil 0 0 12 -5 -5 7  -5 9 7  9 9 7  9 -5 7
white polygon rw1 0 0 12 -5 -5 -1  -5 9 -1  -5 9 7  -5 -5 7
white polygon rw2 0 0 12 9 -5 -1  9 -5 7  9 9 7  9 9 -1
white polygon rw3 0 0 12 -5 -5 -1  -5 -5 7  9 -5 7  9 -5 -1
white polygon rw4 0 0 12 -5 9 -1  9 9 -1  9 9 7  -5 9 7
lamp polygon panel 0 0 12 0 0 6.99  0 2 6.99  2 2 6.99  2 0 6.99
)";
    const Scene instanced = InstancedScene(room);
    const RayCore core(instanced);
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> x(-4.9, 8.9), z(-0.9, 6.9), u(0, 1);
    int blocked = 0, checked = 0;
    for (int i = 0; i < 30000; ++i) {
        // From points near the placements, to the lamp or to other points.
        const Instance& in = instanced.instances[static_cast<std::size_t>(i) % kPlacements.size()];
        const Vec3 near = in.renderFromObject.Point({u(rng), u(rng), u(rng)});
        const Vec3 a = i % 3 ? near + RandomDirection(rng) * (2 * u(rng)) : Vec3{x(rng), x(rng), z(rng)};
        if (std::fabs(a.x - 2) > 6.9 || std::fabs(a.y - 2) > 6.9 || std::fabs(a.z - 3) > 3.9) continue;
        const Vec3 b = i % 2 ? Vec3{2 * u(rng), 2 * u(rng), 6.98} : Vec3{x(rng), x(rng), z(rng)};
        const double length = Length(b - a);
        if (length < 1e-6) continue;
        const Vec3 dir = (b - a) / length;
        const bool expected = core.Intersect(a, dir, length).has_value();
        EXPECT_EQ(core.Occluded(a, dir, length), expected) << a << " -> " << b;
        ++checked;
        blocked += expected;
    }
    EXPECT_GT(checked, 20000);
    EXPECT_GT(blocked, 2000);
}

/// RayCore's `leaving` rule (raycore_test's RayLeavingASurfaceHitsAWallMeetingIt)
/// across instances: a world floor, and a wall and a ball in a prototype
/// placed at twice its size, with a decal coincident with the floor. A ray leaving the floor 3e-7 (world units) from
/// the instanced wall or ball, towards it, hits it; the tolerance and the
/// crossing test are applied in the instance's own units.
TEST(Instances, RayLeavingASurfaceHitsAnInstancedWallMeetingIt) {
    Scene scene = BuildScene(Parse(std::string(kMaterials) +
                                   "white polygon floor 0 0 12 -1 -1 0  4 -1 0  4 3 0  -1 3 0\n"),
                             {});
    scene.prototypes.push_back(PrototypeOf(BuildScene(
        Parse(std::string(kMaterials) +
              "white polygon wall 0 0 12 .5 0 0  .5 1 0  .5 1 1  .5 0 1\n"
              "white sphere ball 0 0 4 .25 .5 0 .125\n"
              "white polygon decal 0 0 12 0 0 .5e-7  .45 0 .5e-7  .45 .45 .5e-7  0 .45 .5e-7\n"),
        {})));
    Instance instance;
    instance.prototype = 0;
    instance.renderFromObject = ParseTransformArgs({"-s", "2", "-t", "1", "0", "0"}).transform;
    instance.objectFromRender = Inverse(instance.renderFromObject);
    scene.instances.push_back(instance);
    scene.cubeSize = 0;
    const RayCore core(scene);
    const Vec3 up{0, 0, 1};
    const double gap = 3e-7;
    // The wall stands at x = 2, the ball's centre at (1.5, 1, 0), radius 0.25.
    for (const auto& [org, dir, surface] :
         {std::tuple{Vec3{2 - gap, 1, 0}, Normalize({1, 0, 1}), 0},
          std::tuple{Vec3{1.75 + gap, 1, 0}, Normalize({-1, 0, 1}), 1}}) {
        const auto through = core.Intersect(org, dir, 0);
        EXPECT_TRUE(!through || through->t > 0.1) << surface;  // Radiance's rule alone
        const auto h = core.Intersect(org, dir, 0, &up);
        ASSERT_TRUE(h) << surface;
        EXPECT_EQ(h->instance, 0);
        EXPECT_EQ(h->surface, surface);
        EXPECT_NEAR(h->t, gap * std::sqrt(2.0), 1e-12);
        EXPECT_TRUE(core.Occluded(org, dir, 0.1, Occluders::All, -1, &up));
        EXPECT_FALSE(core.Occluded(org, dir, 0.1));
    }
    // A decal 1e-7 above the floor (in the instance) is coincident with it:
    // still discarded, as the floor's normal maps into the instance.
    EXPECT_FALSE(core.Intersect({1.2, 0.2, 0}, up, 0, &up));
    EXPECT_FALSE(core.Occluded({1.2, 0.2, 0}, up, 0, Occluders::All, -1, &up));
}

}  // namespace
}  // namespace rt
