// SPDX-License-Identifier: MIT
//
// The surface sets of the occlusion query (RayCore::Occluders): which
// surfaces transmit shadow rays, and that the opaque-only and
// transmitting-only queries, with every shortcut (bounding polygons, the
// light sources' plane, the furniture box, the transmitting boxes, the
// ignored source), give the answer of a closest-hit query on a scene that
// holds only those surfaces.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "raycore/raycore.h"
#include "scene/loader.h"
#include "scene/transform.h"
#include "tests/raycore/brute_occlusion.h"
#include "tests/raycore/test_scenes.h"

namespace rt {
namespace {

using testing::RandomDirection;
using testing::RandomSurfacePoint;

Scene Build(const std::string& text) {
    std::istringstream in(text);
    return BuildScene(ReadSceneObjects(in, "t.rad", {}, {}), {});
}

const char* const kMaterials = R"(
void plastic white 0 0 5 .5 .5 .5 0 0
void metal steel 0 0 5 .5 .5 .5 .9 0
void light lamp 0 0 3 10 10 10
void glow dimglow 0 0 4 1 1 1 0
void spotlight spot 0 0 7 10 10 10 60 0 0 -1
void glass pane 0 0 3 .9 .9 .9
void trans film 0 0 7 .5 .5 .5 0 0 .5 .5
void trans frosted 0 0 7 .5 .5 .5 0 .05 .5 .5
void trans diffuser 0 0 7 .5 .5 .5 0 0 .5 0
void dielectric water 0 0 5 .9 .9 .9 1.33 0
void interface iface 0 0 8 .9 .9 .9 1.33 1 1 1 1
void illum portal 0 0 3 1 1 1
void illum walled 1 white 0 3 1 1 1
void mirror mirror 0 0 3 .9 .9 .9
void mirror mirrorpane 1 pane 0 3 .9 .9 .9
void mirror mirrorwhite 1 white 0 3 .9 .9 .9
void mixfunc mx 4 pane white if(Px-3,1,0) . 0 0
void brightfunc dim 2 .5 . 0 0
)";

/// Surfaces named after whether they must transmit: t_* do, o_* do not.
TEST(TransmitsShadowRays, MaterialsAlternatesModifiersAndHoles) {
    const Scene scene = Build(std::string(kMaterials) + R"(
white polygon o_plastic 0 0 12 0 0 0 1 0 0 1 1 0 0 1 0
steel sphere o_metal 0 0 4 0 0 0 1
lamp ring o_light 0 0 8 0 0 0 0 0 1 0 1
dimglow ring o_glow 0 0 8 0 0 0 0 0 1 0 1
spot ring o_spotlight 0 0 8 0 0 0 0 0 1 0 1
mirror polygon o_mirror 0 0 12 0 0 0 1 0 0 1 1 0 0 1 0
mirrorwhite polygon o_mirror_opaque_alternate 0 0 12 0 0 0 1 0 0 1 1 0 0 1 0
pane polygon t_glass 0 0 12 0 0 0 1 0 0 1 1 0 0 1 0
film cylinder t_trans 0 0 7 0 0 0 0 0 1 1
frosted polygon o_rough_trans 0 0 12 0 0 0 1 0 0 1 1 0 0 1 0
diffuser polygon o_diffuse_trans 0 0 12 0 0 0 1 0 0 1 1 0 0 1 0
water sphere t_dielectric 0 0 4 0 0 0 1
iface bubble t_interface 0 0 4 0 0 0 1
portal polygon t_illum 0 0 12 0 0 0 1 0 0 1 1 0 0 1 0
walled polygon t_illum_alternate 0 0 12 0 0 0 1 0 0 1 1 0 0 1 0
mirrorpane polygon t_mirror_glass_alternate 0 0 12 0 0 0 1 0 0 1 1 0 0 1 0
mx polygon t_mixture 0 0 12 0 0 0 1 0 0 1 1 0 0 1 0
dim polygon t_hole 0 0 12 0 0 0 1 0 0 1 1 0 0 1 0
void polygon o_void 0 0 12 0 0 0 1 0 0 1 1 0 0 1 0
)");
    ASSERT_EQ(scene.surfaces.size(), 19u);
    for (const Surface& s : scene.surfaces) {
        EXPECT_EQ(TransmitsShadowRays(scene, s), s.name[0] == 't') << s.name;
    }
}

/// A 6 x 5 x 3 room with a lamp below the ceiling and, inside, surfaces of
/// every shape that stop shadow rays and that transmit them; a glass
/// louvre in the lamp's plane (left out with it between points below that
/// plane), glass in a wall's plane (left out with the walls between points
/// inside), and three instances of two prototypes: one opaque, one with a
/// glass pane, and the opaque one again under an overriding glass material.
Scene MixedRoom() {
    Scene scene = Build(std::string(kMaterials) + R"(
white polygon floor 0 0 12 0 0 0  0 5 0  6 5 0  6 0 0
white polygon ceiling 0 0 12 0 0 3  6 0 3  6 5 3  0 5 3
white polygon south 0 0 12 0 0 0  6 0 0  6 0 3  0 0 3
white polygon north 0 0 12 0 5 0  0 5 3  6 5 3  6 5 0
white polygon west 0 0 12 0 0 0  0 0 3  0 5 3  0 5 0
white polygon east 0 0 12 6 0 0  6 5 0  6 5 3  6 0 3
lamp polygon panel 0 0 12 2.5 2 2.9  2.5 3 2.9  3.5 3 2.9  3.5 2 2.9
pane polygon louvre 0 0 12 3.5 2 2.9  4.5 2 2.9  4.5 3 2.9  3.5 3 2.9
pane polygon wallpane 0 0 12 6 1 1  6 1 2  6 2 2  6 2 1
lamp sphere globe 0 0 4 1 4 2.2 .12
lamp cylinder tube 0 0 7 .3 .8 2.7 .3 3.8 2.7 .03
white polygon block 0 0 12 1 1 .8  2 1 .8  2 2 .8  1 2 .8
steel sphere ball 0 0 4 2.8 2.4 .95 .2
white cone leg 0 0 8 3 2.5 0 3 2.5 .72 .25 .05
white cup cup 0 0 8 4 4 0 4 4 .5 .1 .3
steel ring disc 0 0 8 1.5 3.5 1 0 0 1 .1 .4
film polygon screen 0 0 12 4.8 .8 0  4.8 3.6 0  4.8 3.6 2  4.8 .8 2
pane sphere glassball 0 0 4 4.2 1.5 .4 .35
film cylinder shade 0 0 7 1 4 1.9 1 4 2.5 .3
water ring pond 0 0 8 2 .7 .01 0 0 1 0 .5
portal polygon opening 0 0 12 .01 2 1  .01 3 1  .01 3 2  .01 2 2
mirrorpane polygon mirror 0 0 12 5.99 3 .5  5.99 4 .5  5.99 4 1.5  5.99 3 1.5
mx polygon mixed 0 0 12 2 4.5 .3  4 4.5 .3  4 4.5 1.3  2 4.5 1.3
)");
    const auto makePrototype = [](const std::string& text) {
        const Scene object = Build(std::string(kMaterials) + text);
        Prototype p;
        p.file = "object";
        p.surfaces = object.surfaces;
        p.cubeOrigin = object.cubeOrigin;
        p.cubeSize = object.cubeSize;
        return p;
    };
    scene.prototypes.push_back(makePrototype(R"(
white polygon top 0 0 12 0 0 .5  1 0 .5  1 1 .5  0 1 .5
steel cylinder post 0 0 7 .5 .5 0 .5 .5 .5 .05
)"));
    scene.prototypes.push_back(makePrototype(R"(
white polygon frame 0 0 12 0 0 0  1 0 0  1 0 .2  0 0 .2
pane polygon glazing 0 0 12 0 0 .2  1 0 .2  1 0 1  0 0 1
)"));
    const auto place = [&](int prototype, std::vector<std::string> words,
                           std::optional<int> overrideMaterial) {
        Instance in;
        in.name = "i" + std::to_string(scene.instances.size());
        in.prototype = prototype;
        in.renderFromObject = ParseTransformArgs(words).transform;
        in.renderFromObject.scale = std::fabs(in.renderFromObject.scale);
        in.objectFromRender = Inverse(in.renderFromObject);
        if (overrideMaterial) {
            Surface s;
            s.name = in.name;
            s.type = SurfaceType::Instance;
            s.material = *overrideMaterial;
            in.override = s;
        }
        scene.instances.push_back(in);
    };
    int pane = -1;
    for (size_t m = 0; m < scene.materials.size(); ++m) {
        if (scene.materials[m].name == "pane") pane = static_cast<int>(m);
    }
    place(0, {"-rz", "20", "-t", "4.5", "3.2", "0"}, std::nullopt);
    place(1, {"-s", "1.2", "-t", "1.5", "2.6", ".2"}, std::nullopt);
    place(0, {"-rz", "-35", "-t", "2", ".5", "1.4"}, pane);
    // oconv's cube, kept by the filtered scenes so that every RayCore puts
    // the same float coordinates before Embree.
    scene.cubeOrigin = {-1, -1, -1};
    scene.cubeSize = 8;
    return scene;
}

bool InstanceTransmits(const Scene& scene, const Instance& in) {
    if (in.override) return TransmitsShadowRays(scene, *in.override);
    for (const Surface& s : scene.prototypes[static_cast<size_t>(in.prototype)].surfaces) {
        if (TransmitsShadowRays(scene, s)) return true;
    }
    return false;
}

/// `scene` with only the surfaces and instances that transmit shadow rays
/// (or only those that do not).
Scene Only(const Scene& scene, bool transmitting) {
    Scene only = scene;
    std::erase_if(only.surfaces, [&](const Surface& s) {
        return s.type != SurfaceType::Source && TransmitsShadowRays(scene, s) != transmitting;
    });
    std::erase_if(only.instances,
                  [&](const Instance& in) { return InstanceTransmits(scene, in) != transmitting; });
    return only;
}

TEST(Occluders, EachSetAgreesWithAClosestHitOnThatSetAlone) {
    const Scene scene = MixedRoom();
    const RayCore core(scene);
    const Scene opaqueScene = Only(scene, false), transmittingScene = Only(scene, true);
    ASSERT_LT(opaqueScene.surfaces.size(), scene.surfaces.size());
    ASSERT_LT(transmittingScene.surfaces.size(), scene.surfaces.size());
    ASSERT_EQ(opaqueScene.instances.size(), 1u);
    ASSERT_EQ(transmittingScene.instances.size(), 2u);
    const RayCore opaque(opaqueScene), transmitting(transmittingScene);
    EXPECT_TRUE(core.HasTransmitting());
    EXPECT_FALSE(opaque.HasTransmitting());

    int panel = -1, tube = -1, globe = -1;
    for (size_t i = 0; i < scene.surfaces.size(); ++i) {
        if (scene.surfaces[i].name == "panel") panel = static_cast<int>(i);
        if (scene.surfaces[i].name == "tube") tube = static_cast<int>(i);
        if (scene.surfaces[i].name == "globe") globe = static_cast<int>(i);
    }
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(0, 1);
    const auto onSurface = [&]() {
        return RandomSurfacePoint(core, {0.05, 0.05, 0.05}, {5.95, 4.95, 2.95}, rng);
    };
    // Where shadow rays end: on the lamp (in its plane), on the tube and the
    // globe (their first hit from the start), and anywhere.
    struct Target {
        Vec3 end;
        int source = -1;  // the surface the segment stops short of, if a source
    };
    const auto target = [&](const Vec3& a) -> Target {
        switch (rng() % 4) {
            case 0: return {{2.5 + u(rng), 2 + u(rng), 2.9}, panel};
            case 1: {
                const Vec3 p{0.3 + 0.02 * (u(rng) - 0.5), 0.8 + 3 * u(rng),
                             2.7 + 0.02 * (u(rng) - 0.5)};
                const auto h = core.IntersectSurface(tube, a, Normalize(p - a));
                return h ? Target{h->point, tube} : Target{p, -1};
            }
            case 2: {
                const Vec3 p = Vec3{1, 4, 2.2} + RandomDirection(rng) * (0.1 * u(rng));
                const auto h = core.IntersectSurface(globe, a, Normalize(p - a));
                return h ? Target{h->point, globe} : Target{p, -1};
            }
            default: return {onSurface(), -1};
        }
    };
    int checked = 0, rays = 0, opaqueBlocks = 0, transmittingBlocks = 0, both = 0;
    for (int i = 0; i < 30000; ++i) {
        const Vec3 a = onSurface();
        if (i % 10 == 9) {
            // A ray without an end, as toward a distant source.
            const Vec3 dir = RandomDirection(rng);
            EXPECT_EQ(core.Occluded(a, dir, 0, Occluders::Opaque),
                      opaque.Intersect(a, dir, 0).has_value()) << a << " along " << dir;
            EXPECT_EQ(core.Occluded(a, dir, 0, Occluders::Transmitting),
                      transmitting.Intersect(a, dir, 0).has_value()) << a << " along " << dir;
            ++rays;
            continue;
        }
        const Target t = target(a);
        const double length = Length(t.end - a);
        if (length < 1e-3) continue;
        const Vec3 dir = (t.end - a) / length;
        const double reach = length * (1 - 1e-7);
        const bool o = opaque.Intersect(a, dir, reach).has_value();
        const bool tr = transmitting.Intersect(a, dir, reach).has_value();
        EXPECT_EQ(core.Occluded(a, dir, reach, Occluders::Opaque), o) << a << " -> " << t.end;
        EXPECT_EQ(core.Occluded(a, dir, reach, Occluders::Transmitting), tr)
            << a << " -> " << t.end;
        EXPECT_EQ(core.Occluded(a, dir, reach), o || tr) << a << " -> " << t.end;
        if (t.source >= 0) {
            // The source a segment stops short of is never in its way.
            EXPECT_EQ(core.Occluded(a, dir, reach, Occluders::Opaque, t.source), o);
            EXPECT_EQ(core.Occluded(a, dir, reach, Occluders::Transmitting, t.source), tr);
        }
        ++checked;
        opaqueBlocks += o;
        transmittingBlocks += tr;
        both += o && tr;
    }
    EXPECT_GT(checked, 25000);
    EXPECT_GT(rays, 2500);
    EXPECT_GT(opaqueBlocks, 1000);
    EXPECT_GT(transmittingBlocks, 5000);
    EXPECT_GT(both, 300);
}

/// Without anything that transmits, the opaque set is every surface and the
/// transmitting set is empty.
TEST(Occluders, OpaqueSceneHasNoTransmittingSet) {
    const Scene scene = Build(std::string(kMaterials) + R"(
white polygon floor 0 0 12 0 0 0  1 0 0  1 1 0  0 1 0
lamp sphere bulb 0 0 4 .5 .5 1 .1
)");
    const RayCore core(scene);
    EXPECT_FALSE(core.HasTransmitting());
    std::mt19937 rng(3);
    for (int i = 0; i < 2000; ++i) {
        const Vec3 a = Vec3{0.5, 0.5, 0.5} + RandomDirection(rng) * 0.4;
        const Vec3 dir = RandomDirection(rng);
        const bool all = core.Occluded(a, dir, 2);
        EXPECT_EQ(core.Occluded(a, dir, 2, Occluders::Opaque), all);
        EXPECT_FALSE(core.Occluded(a, dir, 2, Occluders::Transmitting));
    }
}

}  // namespace
}  // namespace rt
