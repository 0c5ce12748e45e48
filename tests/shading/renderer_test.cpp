// Physics of the -ab 0 shading path on hand-built scenes: direct light from
// area and distant sources against closed forms, the ambient value, shadows,
// and the specular materials.
#include "shading/renderer.h"

#include <cmath>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "raycore/raycore.h"
#include "tests/testing/scene_builder.h"

namespace rt {
namespace {

using testing::SceneBuilder;

/// Lambert's formula: irradiance at `p` (normal `n`) from a uniform polygon of
/// radiance L, exact for any convex polygon wholly above the receiver plane.
double PolygonIrradiance(const std::vector<Vec3>& verts, const Vec3& p, const Vec3& n, double L) {
    double sum = 0;
    for (size_t i = 0; i < verts.size(); ++i) {
        Vec3 a = Normalize(verts[i] - p);
        Vec3 b = Normalize(verts[(i + 1) % verts.size()] - p);
        Vec3 c = Cross(a, b);
        double gamma = std::acos(std::fmax(-1.0, std::fmin(1.0, Dot(a, b))));
        sum += gamma * Dot(n, c) / Length(c);
    }
    return 0.5 * L * std::fabs(sum);
}

struct Fixture {
    Scene scene;
    std::unique_ptr<RayCore> core;
    std::unique_ptr<Renderer> renderer;
    std::vector<std::string> warnings;

    Fixture(const SceneBuilder& b, ShadingOptions shading = {}, AmbientOptions ambient = {}) {
        scene = b.Build();
        core = std::make_unique<RayCore>(scene);
        shading.uncorrelated = false;
        renderer = std::make_unique<Renderer>(
            scene, *core, shading, ambient,
            [this](const std::string& m) { warnings.push_back(m); });
    }
    RayResult Trace(Vec3 org, Vec3 dir) { return renderer->TraceInput(org, Normalize(dir), 0, 0); }
};

const std::vector<Vec3> kLampVerts = {{0, 0, 2}, {0, 1, 2}, {1, 1, 2}, {1, 0, 2}};  // faces down

SceneBuilder LampOverFloor(double lampRadiance, double floorReflectance) {
    SceneBuilder b;
    int lamp = b.AddMaterial("lamp", MaterialType::Light, {lampRadiance, lampRadiance, lampRadiance});
    int white = b.AddMaterial("white", MaterialType::Plastic,
                              {floorReflectance, floorReflectance, floorReflectance, 0, 0});
    b.AddPolygon("panel", lamp, kLampVerts);
    b.AddPolygon("floor", white, {{-5, -5, 0}, {6, -5, 0}, {6, 6, 0}, {-5, 6, 0}});
    return b;
}

TEST(Renderer, ImmediateIrradianceUnderSquareLampMatchesLambertFormula) {
    for (double dt : {0.0, 0.03}) {
        ShadingOptions opts;
        opts.irradiance = IrradianceMode::Immediate;
        opts.direct.threshold = dt;
        Fixture f(LampOverFloor(10, 0.5), opts);
        for (Vec3 p : {Vec3(0.5, 0.5, 0), Vec3(0.1, 0.8, 0.5), Vec3(-1, 2, 0), Vec3(0.5, 0.5, 1.5)}) {
            RayResult r = f.Trace(p, {0, 0, 1});
            double exact = PolygonIrradiance(kLampVerts, p + Vec3(0, 0, 1e-4), {0, 0, 1}, 10);
            EXPECT_NEAR(r.value.g, exact, 0.01 * exact) << "point " << p << " dt " << dt;
            EXPECT_EQ(r.value.r, r.value.g);
            EXPECT_EQ(r.surfaceName, "*");  // -I records no object
            EXPECT_DOUBLE_EQ(r.firstLength, 1e-5);
        }
    }
}

TEST(Renderer, DiffuseFloorRadianceIsRhoOverPiTimesIrradiance) {
    Fixture f(LampOverFloor(10, 0.5));
    Vec3 p(0.3, 0.6, 0);
    Vec3 eye(0.3, -3, 1);
    RayResult r = f.Trace(eye, p - eye);
    double exact = PolygonIrradiance(kLampVerts, p, {0, 0, 1}, 10) * 0.5 / kPi;
    EXPECT_NEAR(r.value.g, exact, 0.01 * exact);
    EXPECT_EQ(r.surfaceName, "floor");
    EXPECT_EQ(r.modifierName, "white");
    EXPECT_NEAR(r.point.z, 0, 1e-12);
    EXPECT_EQ(r.normal, Vec3(0, 0, 1));
    EXPECT_NEAR(r.firstLength, Length(p - eye), 1e-9);
}

TEST(Renderer, LampSeenFromBelowShowsItsRadianceAndIsBlackFromAbove) {
    Fixture f(LampOverFloor(10, 0.5));
    RayResult below = f.Trace({0.5, 0.5, 1}, {0, 0, 1});
    EXPECT_EQ(below.value, Rgb(10, 10, 10));
    RayResult above = f.Trace({0.5, 0.5, 3}, {0, 0, -1});
    EXPECT_EQ(above.value, Rgb(0, 0, 0));
    EXPECT_EQ(above.surfaceName, "panel");
}

TEST(Renderer, OccluderCastsShadow) {
    SceneBuilder b = LampOverFloor(10, 0.5);
    int black = b.AddMaterial("black", MaterialType::Plastic, {0, 0, 0, 0, 0});
    b.AddPolygon("blocker", black, {{-1, -1, 1}, {2, -1, 1}, {2, 2, 1}, {-1, 2, 1}});
    ShadingOptions opts;
    opts.irradiance = IrradianceMode::Immediate;
    Fixture f(b, opts);
    EXPECT_EQ(f.Trace({0.5, 0.5, 0}, {0, 0, 1}).value, Rgb(0, 0, 0));
}

TEST(Renderer, SunOnGroundMatchesDistantSourceFormula) {
    SceneBuilder b;
    const double L = 1e6, angle = 0.5;
    int sun = b.AddMaterial("sun_light", MaterialType::Light, {L, L, L});
    int ground = b.AddMaterial("ground_mat", MaterialType::Plastic, {0.2, 0.2, 0.2, 0, 0});
    Vec3 sunDir = Normalize(Vec3(0, -1, std::sqrt(3.0)));  // 60 degrees elevation
    b.AddDistant("sun", sun, sunDir, angle);
    b.AddRing("ground", ground, {0, 0, 0}, {0, 0, 1}, 0, 100);
    Fixture f(b);
    RayResult r = f.Trace({0, 0, 5}, {0.1, 0.2, -1});
    // The sun's solid angle as Radiance keeps it, in a float (light_sources.cpp).
    double omega = static_cast<float>(2 * kPi * (1 - std::cos(angle / 2 * kPi / 180)));
    double exact = 0.2 / kPi * L * omega * sunDir.z;
    EXPECT_NEAR(r.value.g, exact, 1e-9 * exact);
    // Looking straight at the sun shows its radiance; the miss reports 1e10.
    RayResult s = f.Trace({0, 0, 5}, sunDir);
    EXPECT_EQ(s.value, Rgb(L, L, L));
    EXPECT_EQ(s.firstLength, kFhuge);
    EXPECT_EQ(s.modifierName, "sun_light");
    EXPECT_EQ(s.normal, -sunDir);
}

TEST(Renderer, SkyGlowIsSeenByPrimaryRaysButLightsNothingWithoutBounces) {
    SceneBuilder b;
    int sky = b.AddMaterial("sky_glow", MaterialType::Glow, {1, 1, 1, 0});
    int ground = b.AddMaterial("ground_mat", MaterialType::Plastic, {0.2, 0.2, 0.2, 0, 0});
    b.AddDistant("sky", sky, {0, 0, 1}, 180);
    b.AddRing("ground", ground, {0, 0, 0}, {0, 0, 1}, 0, 1000);
    Fixture f(b);
    EXPECT_EQ(f.Trace({0, 0, 1}, {0.3, 0, 1}).value, Rgb(1, 1, 1));
    EXPECT_EQ(f.Trace({0, 0, 1}, {0, 0, -1}).value, Rgb(0, 0, 0));
    ASSERT_EQ(f.warnings.size(), 1u);
    EXPECT_EQ(f.warnings[0], "no light sources found");
}

TEST(Renderer, FurnaceWithoutBouncesReturnsRhoTimesAmbientValue) {
    SceneBuilder b;
    int grey = b.AddMaterial("grey50", MaterialType::Plastic, {0.5, 0.5, 0.5, 0, 0});
    b.AddSphere("shell", grey, {0, 0, 0}, 1, /*inward=*/true);
    AmbientOptions amb;
    amb.value = Rgb(1, 1, 1);
    Fixture f(b, {}, amb);
    RayResult r = f.Trace({0.1, 0.2, 0.3}, {1, -2, 0.5});
    EXPECT_NEAR(r.value.g, 0.5, 1e-12);
    ShadingOptions irr;
    irr.irradiance = IrradianceMode::Immediate;
    Fixture g(b, irr, amb);
    EXPECT_NEAR(g.Trace({0, 0, 0}, {0, 1, 0}).value.g, kPi, 1e-12);
}

TEST(Renderer, IrradianceAtHitReplacesMaterialByLambertianMeter) {
    ShadingOptions opts;
    opts.irradiance = IrradianceMode::AtHit;
    Fixture f(LampOverFloor(10, 0.5), opts);
    Vec3 p(0.3, 0.6, 0);
    Vec3 eye(0.3, -3, 1);
    double exact = PolygonIrradiance(kLampVerts, p, {0, 0, 1}, 10);
    EXPECT_NEAR(f.Trace(eye, p - eye).value.g, exact, 0.01 * exact);
    // Light sources still show their radiance.
    EXPECT_EQ(f.Trace({0.5, 0.5, 1}, {0, 0, 1}).value, Rgb(10, 10, 10));
}

TEST(Renderer, MirrorReflectsTheLamp) {
    SceneBuilder b = LampOverFloor(10, 0.5);
    int mirror = b.AddMaterial("mirror", MaterialType::Mirror, {0.8, 0.6, 0.4});
    b.AddPolygon("glass_floor", mirror, {{-1, -1, 0.5}, {2, -1, 0.5}, {2, 2, 0.5}, {-1, 2, 0.5}});
    Fixture f(b);
    // From below the lamp... the eye sits between mirror and lamp and looks down.
    RayResult r = f.Trace({0.5, 0.5, 1}, {0, 0, -1});
    EXPECT_NEAR(r.value.r, 8, 1e-9);
    EXPECT_NEAR(r.value.b, 4, 1e-9);
    EXPECT_EQ(r.mirrored, r.value);
    EXPECT_NEAR(r.EffectiveLength(), 0.5 + 1.5, 1e-9);  // unfolded mirror distance
}

TEST(Renderer, GlassTransmitsFresnelFractionAtNormalIncidence) {
    SceneBuilder b = LampOverFloor(10, 0.0);  // black floor: nothing in the reflection
    int glass = b.AddMaterial("pane", MaterialType::Glass, {1, 1, 1});
    b.AddPolygon("window", glass, {{-1, -1, 1}, {2, -1, 1}, {2, 2, 1}, {-1, 2, 1}});
    Fixture f(b);
    double n = 1.52, r = std::pow((n - 1) / (n + 1), 2);
    double t = (1 - r) / (1 + r);  // both faces, all inter-reflections
    EXPECT_NEAR(f.Trace({0.5, 0.5, 0.5}, {0, 0, 1}).value.g, 10 * t, 1e-6);
    // Shadow rays pass the pane with the same transmission.
    ShadingOptions opts;
    opts.irradiance = IrradianceMode::Immediate;
    opts.direct.threshold = 0;
    Fixture g(b, opts);
    Vec3 p(0.5, 0.5, 0);
    double exact = PolygonIrradiance(kLampVerts, p, {0, 0, 1}, 10);
    EXPECT_NEAR(g.Trace(p, {0, 0, 1}).value.g, exact * t, 0.02 * exact);
}

TEST(Renderer, BackfacesAreTransparentWithBvOff) {
    SceneBuilder b = LampOverFloor(10, 0.5);
    int white = b.AddMaterial("white2", MaterialType::Plastic, {0.5, 0.5, 0.5, 0, 0});
    // Faces up: the eye below sees its back.
    b.AddPolygon("shelf", white, {{-1, -1, 1}, {2, -1, 1}, {2, 2, 1}, {-1, 2, 1}});
    ShadingOptions opts;
    opts.backfaceVisible = false;
    Fixture f(b, opts);
    EXPECT_EQ(f.Trace({0.5, 0.5, 0.5}, {0, 0, 1}).value, Rgb(10, 10, 10));
    Fixture g(b);
    EXPECT_EQ(g.Trace({0.5, 0.5, 0.5}, {0, 0, 1}).surfaceName, "shelf");
}

TEST(Renderer, NoNegativeOrNonFiniteValuesAtGrazingAngles) {
    Fixture f(LampOverFloor(1e10, 0.999));
    for (int i = 0; i < 200; ++i) {
        double a = 1e-7 * std::pow(1.2, i % 100);
        RayResult r = f.Trace({0.5, -3, 1e-3}, {0, 1, -a});
        EXPECT_TRUE(IsFinite(r.value));
        EXPECT_GE(r.value.r, 0.0);
    }
}

}  // namespace
}  // namespace rt

namespace rt {
namespace {

TEST(Renderer, ReportsHowTheFirstSurfaceGotItsIndirectLight) {
    testing::SceneBuilder b;
    int grey = b.AddMaterial("grey50", MaterialType::Plastic, {0.5, 0.5, 0.5, 0, 0});
    b.AddSphere("shell", grey, {0, 0, 0}, 1, /*inward=*/true);
    AmbientOptions amb;
    amb.value = Rgb(1, 1, 1);
    amb.bounces = 1;
    amb.divisions = 64;
    amb.superSamples = 0;
    Fixture f(b, {}, amb);
    RayResult first = f.Trace({0, 0, 0}, {0, 0, -1});
    EXPECT_EQ(first.ambientOutcome, RayResult::AmbientOutcome::Computed);
    // Furnace: the hemisphere sees rho·L = 0.5 everywhere, irradiance π·0.5.
    EXPECT_NEAR(first.indirectIrradiance.g, kPi * 0.5, 1e-9);
    RayResult again = f.Trace({0, 0, 0}, {0, 0, -1});
    EXPECT_EQ(again.ambientOutcome, RayResult::AmbientOutcome::Extrapolated);  // one record
    EXPECT_NEAR(again.indirectIrradiance.g, kPi * 0.5, 1e-9);
    EXPECT_EQ(f.renderer->CacheRecords().size(), 1u);

    AmbientOptions none = amb;
    none.bounces = 0;
    Fixture g(b, {}, none);
    EXPECT_EQ(g.Trace({0, 0, 0}, {0, 0, -1}).ambientOutcome, RayResult::AmbientOutcome::None);
    EXPECT_TRUE(g.renderer->CacheRecords().empty());  // no cache at -ab 0
}

/// Threads share one Renderer::Shared and keep everything a ray changes
/// (random numbers, source statistics, scratch, counters) in their own
/// Renderer: each thread's results are bit for bit those of a private
/// Renderer tracing the same rays in the same order.
TEST(Renderer, ThreadsSharingOneSetUpKeepTheirOwnState) {
    testing::SceneBuilder b;
    // Eight small lamps, so that the -dt test leaves samples untested and
    // estimates them from each source's hit statistics; a box between the
    // lamps and the floor, so that shadows differ by point.
    const int lamp = b.AddMaterial("lamp", MaterialType::Light, {50, 50, 50});
    const int white = b.AddMaterial("white", MaterialType::Plastic, {0.6, 0.6, 0.6, 0.2, 0.05});
    for (int i = 0; i < 8; ++i) {
        const double x = -3 + 0.8 * i;
        b.AddPolygon("lamp" + std::to_string(i), lamp,
                     {{x, -0.1, 3}, {x, 0.1, 3}, {x + 0.2, 0.1, 3}, {x + 0.2, -0.1, 3}});
    }
    b.AddPolygon("floor", white, {{-6, -6, 0}, {6, -6, 0}, {6, 6, 0}, {-6, 6, 0}});
    b.AddPolygon("block", white, {{-1, -1, 1}, {-1, 1, 1}, {1, 1, 1}, {1, -1, 1}});
    const Scene scene = b.Build();
    const RayCore core(scene);
    ShadingOptions shading;
    shading.uncorrelated = true;
    shading.specular.sampling = 2;  // rough highlights (above -st) draw random numbers
    AmbientOptions ambient;
    ambient.bounces = 1;
    ambient.divisions = 32;
    ambient.accuracy = 0;  // no cache: each ray's value depends on its thread only
    constexpr int kRays = 60;
    const auto trace = [&](Renderer& r, int first) {
        std::vector<RayResult> out;
        for (int i = first; i < kRays; i += 2) {
            const Vec3 org(-4 + 8.0 * i / kRays, 0.3 * (i % 5), 2.5);
            out.push_back(r.TraceInput(org, Normalize(Vec3(0.1, 0.05, -1)), 0,
                                       static_cast<std::uint64_t>(i)));
        }
        return out;
    };
    const auto shared = Renderer::Share(scene, core, shading, ambient, {}, nullptr);
    std::vector<RayResult> threaded[2];
    {
        Renderer r0(shared, {}), r1(shared, {});
        std::jthread t0([&] { threaded[0] = trace(r0, 0); });
        std::jthread t1([&] { threaded[1] = trace(r1, 1); });
    }
    for (int half = 0; half < 2; ++half) {
        Renderer alone(scene, core, shading, ambient, {}, nullptr);
        const std::vector<RayResult> expected = trace(alone, half);
        ASSERT_EQ(threaded[half].size(), expected.size());
        for (size_t k = 0; k < expected.size(); ++k) {
            EXPECT_EQ(threaded[half][k].value.r, expected[k].value.r) << half << " " << k;
            EXPECT_EQ(threaded[half][k].value.b, expected[k].value.b) << half << " " << k;
        }
        EXPECT_GT(expected.front().value.g + expected.back().value.g, 0.0);
    }
}

}  // namespace
}  // namespace rt
