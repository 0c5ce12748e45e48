// SPDX-License-Identifier: MIT
//
// The direct calculation's shadow rays and source samples (shading/direct.cpp):
// answered by occlusion queries, they must give the values of shadow rays
// followed through every surface; and sample rays that miss their source are
// counted as real Radiance 5.4a counts them.
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "raycore/raycore.h"
#include "scene/loader.h"
#include "shading/renderer.h"

namespace rt {
namespace {

Scene Build(const std::string& text) {
    std::istringstream in(text);
    return BuildScene(ReadSceneObjects(in, "t.rad", {}, {}), {});
}

struct Traced {
    std::vector<Rgb> values;
    std::vector<std::string> warnings;
};

/// Traces `rays` (origin, direction; -I sensors with `immediate`) in one
/// Renderer; with `followShadows`, shadow rays are reported to a trace
/// callback, which makes the direct calculation follow every one of them
/// through the surfaces (as rtrace -oT does) instead of querying.
Traced Trace(const Scene& scene, const std::vector<std::pair<Vec3, Vec3>>& rays,
          ShadingOptions shading, AmbientOptions ambient, bool followShadows) {
    const RayCore core(scene);
    Traced run;
    shading.uncorrelated = false;
    Renderer renderer(scene, core, shading, ambient,
                      [&run](const std::string& m) { run.warnings.push_back(m); });
    if (followShadows) renderer.SetTraceCallback([](const RayResult&) {}, true);
    std::uint64_t index = 0;
    for (const auto& [org, dir] : rays) {
        run.values.push_back(renderer.TraceInput(org, Normalize(dir), 0, index++).value);
    }
    return run;
}

/// A room lit by every kind of source (a parallelogram, a triangle, a
/// sphere, a cylinder, a ring spotlight, and the sun through a glazed
/// opening), with surfaces that transmit shadow rays (glass, a trans without
/// roughness, dielectric, a mirror with a glass alternate, an illum, a
/// mixture) in front of and beside opaque ones, and a rough trans screen,
/// which blocks shadow rays.
const char* const kRoom = R"(
void plastic white 0 0 5 .6 .6 .58 0 0
void metal brushed 0 0 5 .8 .75 .6 .9 .05
void trans screen 0 0 7 .7 .7 .75 .02 .05 .4 .3
void trans film 0 0 7 .7 .75 .7 0 0 .6 .8
void glass pane 0 0 3 .86 .86 .86
void dielectric water 0 0 5 .9 .95 .9 1.33 0
void mirror mirrorpane 1 pane 0 3 .9 .9 .9
void illum portal 0 0 3 2 2 2
void mixfunc stripes 4 pane white if(sin(20*Px),1,0) . 0 0
void light panel 0 0 3 30 30 28
void light tri 0 0 3 20 20 20
void light globe 0 0 3 40 36 30
void spotlight spot 0 0 7 400 380 340 50 0 0 -1
void light tube 0 0 3 20 22 25
void light sun 0 0 3 2e6 1.9e6 1.7e6
white polygon floor 0 0 12 0 0 0  0 5 0  6 5 0  6 0 0
white polygon ceiling 0 0 12 0 0 3  6 0 3  6 5 3  0 5 3
white polygon north 0 0 12 0 5 0  0 5 3  6 5 3  6 5 0
white polygon west 0 0 12 0 0 0  0 0 3  0 5 3  0 5 0
white polygon east 0 0 12 6 0 0  6 5 0  6 5 3  6 0 3
white polygon south_low 0 0 12 0 0 0  6 0 0  6 0 1  0 0 1
white polygon south_high 0 0 12 0 0 2.4  6 0 2.4  6 0 3  0 0 3
white polygon south_left 0 0 12 0 0 1  1.5 0 1  1.5 0 2.4  0 0 2.4
white polygon south_right 0 0 12 4.5 0 1  6 0 1  6 0 2.4  4.5 0 2.4
pane polygon window 0 0 12 1.5 0 1  4.5 0 1  4.5 0 2.4  1.5 0 2.4
sun source sunlight 0 0 4 0.3 -0.7 0.65 0.53
panel polygon ceiling_panel 0 0 12 2.5 2 2.98  2.5 3 2.98  3.5 3 2.98  3.5 2 2.98
tri polygon tri_lamp 0 0 9 0.5 4 2.95  1.2 4 2.95  0.5 4.6 2.95
globe sphere globe_lamp 0 0 4 1 4 2.2 .12
spot ring spot_lamp 0 0 8 5 4 2.95 0 0 -1 0 .1
tube cylinder tube_lamp 0 0 7 .3 .8 2.7 .3 3.8 2.7 .03
brushed cylinder table_top 0 0 7 3 2.5 .72 3 2.5 .75 .6
white cone table_leg 0 0 8 3 2.5 0 3 2.5 .72 .25 .05
screen polygon screen_front 0 0 12 4.8 .8 0  4.8 3.6 0  4.8 3.6 2  4.8 .8 2
film polygon film_back 0 0 12 5.4 .8 0  5.4 3.6 0  5.4 3.6 2.4  5.4 .8 2.4
film cylinder film_shade 0 0 7 1 4 1.9 1 4 2.5 .3
pane sphere glass_ball 0 0 4 2 1.5 .5 .3
water polygon tank 0 0 12 1 3 1.2  2 3 1.2  2 3.6 1.2  1 3.6 1.2
mirrorpane polygon wall_mirror 0 0 12 5.99 3.8 .5  5.99 4.6 .5  5.99 4.6 1.8  5.99 3.8 1.8
portal polygon portal_panel 0 0 12 3.5 4.99 .3  2.5 4.99 .3  2.5 4.99 1.5  3.5 4.99 1.5
stripes polygon striped 0 0 12 4 1 1.5  4.6 1 1.5  4.6 1.6 1.5  4 1.6 1.5
)";

/// Sensors on the floor, the walls and the table, and eye rays.
std::vector<std::pair<Vec3, Vec3>> RoomRays(bool sensors) {
    std::vector<std::pair<Vec3, Vec3>> rays;
    if (sensors) {
        for (double x = 0.25; x < 6; x += 0.5) {
            for (double y = 0.25; y < 5; y += 0.5) rays.push_back({{x, y, 0}, {0, 0, 1}});
        }
        for (double y = 0.3; y < 5; y += 0.6) {
            for (double z = 0.3; z < 3; z += 0.6) {
                rays.push_back({{6, y, z}, {-1, 0, 0}});
                rays.push_back({{0, y, z}, {1, 0, 0}});
            }
        }
        for (double z = 0.3; z < 3; z += 0.3) rays.push_back({{0.3, 0, z}, {0, 1, 0}});
        rays.push_back({{3, 2.5, 0.75}, {0, 0, 1}});
        return rays;
    }
    for (int i = 0; i < 200; ++i) {
        const double a = 0.1 * i, b = 0.037 * i;
        rays.push_back({{3, 2.5, 1.5},
                        {std::cos(a) * std::cos(b), std::sin(a) * std::cos(b), std::sin(b) - 0.6}});
    }
    return rays;
}

TEST(DirectLight, ShadowQueriesGiveTheFollowedShadowRaysValues) {
    const Scene scene = Build(kRoom);
    ASSERT_TRUE(RayCore(scene).HasTransmitting());
    for (const bool sensors : {true, false}) {
        ShadingOptions shading;
        if (sensors) shading.irradiance = IrradianceMode::Immediate;
        AmbientOptions ambient;
        ambient.bounces = 0;
        // Direct light only, then one bounce without a cache (the rays of a
        // hemisphere with their own shadow rays, Russian roulette included).
        for (const int bounces : {0, 1}) {
            ambient.bounces = bounces;
            ambient.accuracy = 0;
            ambient.divisions = 32;
            const auto rays = RoomRays(sensors);
            const Traced queried = Trace(scene, rays, shading, ambient, false);
            const Traced followed = Trace(scene, rays, shading, ambient, true);
            int lit = 0;
            for (size_t i = 0; i < rays.size(); ++i) {
                EXPECT_EQ(queried.values[i], followed.values[i])
                    << (sensors ? "sensor " : "eye ray ") << rays[i].first << " " << rays[i].second
                    << " -ab " << bounces;
                lit += Bright(queried.values[i]) > 0;
            }
            EXPECT_GT(lit, static_cast<int>(rays.size()) / 2);
            EXPECT_EQ(queried.warnings, followed.warnings);
        }
    }
}

const char* const kTube = R"(
void light tube 0 0 3 20 22 25
void plastic wall 0 0 5 .6 .6 .6 0 0
tube cylinder tube_lamp 0 0 7 0.3 0.8 2.7 0.3 3.8 2.7 0.03
wall polygon endwall 0 0 12 0 0 0  6 0 0  6 0 3  0 0 3
)";

/// Warnings after `hits` sensors whose one sample meets the tube (20 m below
/// it, facing up) and `misses` whose sample goes in at one open end of the
/// tube and out at the other (on the end wall, 1.3 radii off its axis), in
/// that order, repeated `rounds` times.
std::vector<std::string> AimWarnings(int hits, int misses, int rounds = 1) {
    const Scene scene = Build(kTube);
    std::vector<std::pair<Vec3, Vec3>> rays;
    for (int r = 0; r < rounds; ++r) {
        for (int i = 0; i < hits; ++i) rays.push_back({{0.3, 2.3, 2.7 - 20}, {0, 0, 1}});
        for (int i = 0; i < misses; ++i) {
            const double a = 0.3 * i;
            rays.push_back({{0.3 + 0.039 * std::cos(a), 0, 2.7 + 0.039 * std::sin(a)}, {0, 1, 0}});
        }
    }
    ShadingOptions shading;
    shading.irradiance = IrradianceMode::Immediate;
    AmbientOptions ambient;
    ambient.bounces = 0;
    return Trace(scene, rays, shading, ambient, false).warnings;
}

// The counts real Radiance 5.4a gives on this scene (rtrace -h -I -ab 0):
// a cylinder source warns at its fourth miss, each hit buys one hundredth of
// a miss more, without limit, and the warning comes once.
TEST(DirectLight, AimingFailuresAreCountedAsRadianceCountsThem) {
    const std::vector<std::string> once = {"aiming failure for light source \"tube_lamp\""};
    EXPECT_TRUE(AimWarnings(0, 3).empty());
    EXPECT_EQ(AimWarnings(0, 4), once);
    EXPECT_TRUE(AimWarnings(100, 4).empty());
    EXPECT_EQ(AimWarnings(100, 5), once);
    EXPECT_TRUE(AimWarnings(300, 6).empty());
    EXPECT_EQ(AimWarnings(300, 7), once);
    EXPECT_TRUE(AimWarnings(1000, 11).empty());
    EXPECT_EQ(AimWarnings(0, 20), once);
    // Once warned, never again, whatever hits come between the misses.
    EXPECT_EQ(AimWarnings(1, 2, 10), once);
    EXPECT_EQ(AimWarnings(100, 4, 10), once);
}

/// Traces `rays` at -dt 0 with -ab 0, without the obstructor cache ([0]) and
/// with it ([1]); `shading` gives the other options.
struct CacheRuns {
    std::vector<Rgb> values[2];
    RenderStats stats[2];
};
CacheRuns TraceWithoutAndWithCache(const Scene& scene,
                                   const std::vector<std::pair<Vec3, Vec3>>& rays,
                                   ShadingOptions shading) {
    const RayCore core(scene);
    CacheRuns runs;
    for (const bool cache : {false, true}) {
        shading.direct.threshold = 0;
        shading.direct.obstructorCache = cache;
        AmbientOptions ambient;
        ambient.bounces = 0;
        Renderer renderer(scene, core, shading, ambient, [](const std::string&) {});
        std::uint64_t index = 0;
        for (const auto& [org, dir] : rays) {
            runs.values[cache].push_back(renderer.TraceInput(org, Normalize(dir), 0, index++).value);
        }
        runs.stats[cache] = renderer.Stats();
    }
    return runs;
}

/// Radiance's obstructor cache: at -dt 0 every sample is tested, so the
/// samples the cache drops are ones whose shadow ray would have been blocked
/// anyway: the same values with and without the cache, and fewer shadow rays
/// with it. (At -dt above 0 it changes which samples are tested, as it does
/// in Radiance: Golden.ObstructorCacheMatchesRadiance.)
TEST(DirectLight, ObstructorCacheSavesShadowRaysWithoutChangingExactAnswers) {
    ShadingOptions shading;
    shading.irradiance = IrradianceMode::Immediate;
    shading.uncorrelated = false;
    const CacheRuns runs = TraceWithoutAndWithCache(Build(kRoom), RoomRays(true), shading);
    EXPECT_EQ(runs.values[false], runs.values[true]);
    EXPECT_EQ(runs.stats[false].samplesObstructed, 0u);
    // Every sample the cache dropped is a shadow ray saved.
    EXPECT_GT(runs.stats[true].samplesObstructed, 0u);
    EXPECT_EQ(runs.stats[true].shadowRays + runs.stats[true].samplesObstructed,
              runs.stats[false].shadowRays);
}

/// The same for the light a mist scatters into rays (Radiance's srcscatter()
/// asks the cache too): level eye rays through a fog around a bulb, under a
/// plate that shades half of their way through it from the bulb, and on into
/// nothing, so that only scattered light reaches them.
TEST(DirectLight, ObstructorCacheSkipsScatterSamplesWithoutChangingAnswers) {
    const Scene scene = Build(R"(
void light lamp 0 0 3 50 50 50
lamp sphere bulb 0 0 4 0 0 2 .1
void plastic grey 0 0 5 .5 .5 .5 0 0
grey polygon plate 0 0 12 -.7 -.7 1.5  -.7 .7 1.5  .7 .7 1.5  .7 -.7 1.5
grey polygon floor 0 0 12 -5 -5 0  -5 5 0  5 5 0  5 -5 0
void mist fog 1 bulb 0 7 .3 .3 .3 .9 .9 .9 0
fog sphere fogball 0 0 4 0 0 1 3
)");
    std::vector<std::pair<Vec3, Vec3>> rays;
    for (int i = 0; i < 100; ++i) rays.push_back({{6, 0, 1}, {-1, 0.002 * (i - 50), 0}});
    ShadingOptions shading;
    shading.uncorrelated = true;  // a random point along each ray, the same in both runs
    const CacheRuns runs = TraceWithoutAndWithCache(scene, rays, shading);
    EXPECT_EQ(runs.values[false], runs.values[true]);
    // Samples under the plate and beside it (one point per ray, at random).
    int lit = 0;
    for (const Rgb& v : runs.values[true]) lit += Bright(v) > 0.0;
    EXPECT_GT(lit, 10);
    EXPECT_LT(lit, 90);
    EXPECT_EQ(runs.stats[false].samplesObstructed, 0u);
    EXPECT_GT(runs.stats[true].samplesObstructed, 0u);
}

/// The materials the cache records stop shadow rays from behind too, -bv-
/// or not (Radiance's normal.c tests for a shadow ray before the side), so a
/// cached surface met from behind blocks: sensors under a plate that faces
/// the bulb are dark with the cache as without, and the cache drops their
/// samples as Radiance 5.4a's does (its -oT trace shows no shadow ray there).
TEST(DirectLight, ObstructorCacheBlocksFromBehindWithoutBackfacesToo) {
    const Scene scene = Build(R"(
void light lamp 0 0 3 50 50 50
lamp sphere bulb 0 0 4 0 0 2 .1
void plastic grey 0 0 5 .5 .5 .5 0 0
grey polygon plate 0 0 12 -1 -1 1  1 -1 1  1 1 1  -1 1 1
)");
    std::vector<std::pair<Vec3, Vec3>> rays;
    for (int i = 0; i < 10; ++i) rays.push_back({{-0.5 + 0.1 * i, 0.05 * i, 0}, {0, 0, 1}});
    ShadingOptions shading;
    shading.irradiance = IrradianceMode::Immediate;
    shading.uncorrelated = false;
    shading.backfaceVisible = false;
    const CacheRuns runs = TraceWithoutAndWithCache(scene, rays, shading);
    EXPECT_EQ(runs.values[false], runs.values[true]);
    for (const Rgb& v : runs.values[true]) EXPECT_EQ(Bright(v), 0.0);
    EXPECT_EQ(runs.stats[true].samplesObstructed, rays.size());
    EXPECT_EQ(runs.stats[true].shadowRays, 0u);
}

}  // namespace
}  // namespace rt
