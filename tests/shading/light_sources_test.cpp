// Light-source set-up and sampling (Radiance's srcsupp.c/srcsamp.c): sample
// solid angles against exact ones, subdivision with -ds, and the cases where a
// source yields no sample.
#include "shading/light_sources.h"

#include <cmath>

#include <gtest/gtest.h>

#include "core/conventions.h"
#include "tests/testing/scene_builder.h"

namespace rt {
namespace {

using testing::SceneBuilder;

/// Exact solid angle of a rectangle seen from a point on its axis.
double RectangleSolidAngle(double a, double b, double d) {
    return 4.0 * std::asin(a * b / std::sqrt((a * a + 4 * d * d) * (b * b + 4 * d * d)));
}

std::vector<SourceSample> Samples(const Scene& scene, Vec3 p, double ds = 0.2, double weight = 1) {
    Rng rng(1);
    auto sources = FindLightSources(scene, nullptr, false, rng);
    DirectOptions opts;
    opts.sampling = ds;
    std::vector<SourceSample> out;
    std::vector<SourcePartition> scratch;
    CollectSourceSamples(sources, p, weight, opts, rng, out, scratch);
    return out;
}

Scene SquareLamp() {
    SceneBuilder b;
    int lamp = b.AddMaterial("lamp", MaterialType::Light, {1, 1, 1});
    b.AddPolygon("panel", lamp, {{-0.5, -0.5, 0}, {-0.5, 0.5, 0}, {0.5, 0.5, 0}, {0.5, -0.5, 0}});
    return b.Build();  // faces down (-z)
}

TEST(LightSources, QuadUsesItsSidesAsSamplingFrame) {
    Scene scene = SquareLamp();
    Rng rng(1);
    auto sources = FindLightSources(scene, nullptr, true, rng);
    ASSERT_EQ(sources.size(), 1u);
    EXPECT_EQ(sources[0].size[0], Vec3(0, 0.5, 0));
    EXPECT_EQ(sources[0].size[1], Vec3(0.5, 0, 0));
    EXPECT_DOUBLE_EQ(sources[0].area, 1.0);
    EXPECT_EQ(sources[0].normal, Vec3(0, 0, -1));
}

TEST(LightSources, FarPointGetsOneSampleNearPointIsSubdivided) {
    Scene scene = SquareLamp();
    // Subdivide while distance < 2·weight/ds · half-size = 5 (ds 0.2).
    EXPECT_EQ(Samples(scene, {0, 0, -6}).size(), 1u);
    EXPECT_GT(Samples(scene, {0, 0, -1}).size(), 4u);
    EXPECT_EQ(Samples(scene, {0, 0, -1}, 0.0).size(), 1u);  // -ds 0: never subdivide
    EXPECT_LE(Samples(scene, {0, 0, -1e-3}).size(), 64u);  // Radiance's MAXSPART
}

TEST(LightSources, SampleSolidAnglesSumToTheExactOne) {
    Scene scene = SquareLamp();
    for (double d : {0.5, 1.0, 3.0, 10.0}) {
        double sum = 0;
        for (const auto& s : Samples(scene, {0, 0, -d})) sum += s.omega;
        double exact = RectangleSolidAngle(1, 1, d);
        // Midpoint sampling of each partition: a few per cent at worst up close.
        EXPECT_NEAR(sum, exact, 0.03 * exact) << "distance " << d;
    }
}

TEST(LightSources, NothingBehindAFlatSource) {
    EXPECT_TRUE(Samples(SquareLamp(), {0, 0, 1}).empty());
}

TEST(LightSources, SphereAndDistantSolidAngles) {
    SceneBuilder b;
    int lamp = b.AddMaterial("lamp", MaterialType::Light, {1, 1, 1});
    b.AddSphere("bulb", lamp, {0, 0, 0}, 0.1);
    b.AddDistant("sun", lamp, {0, 0, 1}, 0.5);
    auto samples = Samples(b.Build(), {0, 3, 0});
    ASSERT_EQ(samples.size(), 2u);
    EXPECT_NEAR(samples[0].omega, kPi * 0.01 / 9.0, 1e-15);
    EXPECT_EQ(samples[0].dir, Vec3(0, -1, 0));
    // A distant source's solid angle is kept in a float, as Radiance keeps it.
    EXPECT_NEAR(samples[1].omega, static_cast<float>(2 * kPi * (1 - std::cos(0.25 * kPi / 180))),
                1e-15);
    EXPECT_EQ(samples[1].distance, kFhuge);
}

TEST(LightSources, GlowWithoutRadiusAndDistantGlowAreNotSampled) {
    SceneBuilder b;
    int glow = b.AddMaterial("g", MaterialType::Glow, {1, 1, 1, 0});
    int sky = b.AddMaterial("sky", MaterialType::Glow, {1, 1, 1, 0});
    b.AddSphere("ball", glow, {0, 0, 0}, 1);
    b.AddDistant("dome", sky, {0, 0, 1}, 180);
    Scene scene = b.Build();
    Rng rng(1);
    std::vector<std::string> warnings;
    auto sources = FindLightSources(scene, [&](const std::string& m) { warnings.push_back(m); },
                                    false, rng);
    ASSERT_EQ(sources.size(), 1u);  // only the sky, as a skipped source
    EXPECT_TRUE(sources[0].skip);
    EXPECT_EQ(warnings, std::vector<std::string>{"no light sources found"});
    EXPECT_TRUE(Samples(scene, {0, 0, 5}).empty());
}

TEST(LightSources, LightOnABubbleIsAnError) {
    SceneBuilder b;
    int lamp = b.AddMaterial("lamp", MaterialType::Light, {1, 1, 1});
    b.AddSphere("inside_out", lamp, {0, 0, 0}, 1, true);
    Scene scene = b.Build();
    Rng rng(1);
    EXPECT_THROW(FindLightSources(scene, nullptr, false, rng), Error);
}

}  // namespace
}  // namespace rt
