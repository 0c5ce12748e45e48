// SPDX-License-Identifier: MIT
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/conventions.h"
#include "scene_test_util.h"

namespace rt {
namespace {

using testing::BuildError;
using testing::BuildText;

constexpr const char* kPlastic = "void plastic white 0 0 5 .5 .5 .5 0 0\n";

void ExpectNear(const Vec3& a, const Vec3& b, double tolerance = 1e-12) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(BuildScene, MaterialsAndArgumentCounts) {
    const Scene scene = BuildText(
        "void plastic p 0 0 5 1 1 1 0 0\n"
        "void metal m 0 0 5 1 1 1 .9 .1\n"
        "void trans t 0 0 7 1 1 1 0 0 .5 .5\n"
        "void light l 0 0 3 10 10 10\n"
        "void illum i 1 p 0 3 1 1 1\n"
        "void illum i2 1 void 0 3 1 1 1\n"
        "void glow g 0 0 4 1 1 1 0\n"
        "void spotlight s 0 0 7 1 1 1 30 0 0 -1\n"
        "void mirror mi 0 0 3 .9 .9 .9\n"
        "void glass g3 0 0 3 .9 .9 .9\n"
        "void glass g4 0 0 4 .9 .9 .9 1.5\n"
        "void dielectric d 0 0 5 .9 .9 .9 1.5 0\n"
        "void interface f 0 0 8 1 1 1 1.3 1 1 1 1\n");
    ASSERT_EQ(scene.materials.size(), 13u);
    EXPECT_EQ(scene.materials[4].type, MaterialType::Illum);
    EXPECT_EQ(scene.materials[4].alternate, 0);
    EXPECT_EQ(scene.materials[5].alternate, -1);
    EXPECT_EQ(scene.materials[12].type, MaterialType::Interface);
    EXPECT_EQ(scene.materials[12].loc.ToString(), "t.rad:13");
    // Parameters by name, read once here.
    const auto& trans = std::get<NormalParams>(scene.materials[2].params);
    EXPECT_EQ(trans.transmissivity, 0.5);
    EXPECT_EQ(trans.transmittedSpecular, 0.5);
    EXPECT_EQ(std::get<NormalParams>(scene.materials[1].params).roughness, 0.1);
    EXPECT_EQ(std::get<LightParams>(scene.materials[7].params).coneAngleDegrees, 30);
    EXPECT_EQ(std::get<LightParams>(scene.materials[7].params).aim, Vec3(0, 0, -1));
    EXPECT_EQ(std::get<GlassParams>(scene.materials[9].params).index, 1.52);
    EXPECT_EQ(std::get<GlassParams>(scene.materials[10].params).index, 1.5);
    EXPECT_EQ(std::get<DielectricParams>(scene.materials[12].params).outsideIndex, 1);
    EXPECT_EQ(std::get<DielectricParams>(scene.materials[12].params).insideIndex, 1.3);
    EXPECT_TRUE(scene.surfaces.empty());
}

TEST(BuildScene, WrongArgumentCountsNameTheMaterial) {
    EXPECT_EQ(BuildError("\nvoid plastic p 0 0 4 1 1 1 0\n"),
              "t.rad:2: bad number of arguments for plastic \"p\"");
    EXPECT_EQ(BuildError("void glass g 0 0 5 1 1 1 1.5 0\n"),
              "t.rad:1: bad number of arguments for glass \"g\"");
    EXPECT_EQ(BuildError("void metal m 1 x 0 5 1 1 1 0 0\n"),
              "t.rad:1: bad number of arguments for metal \"m\"");
    EXPECT_EQ(BuildError("void illum i 2 a b 0 3 1 1 1\n"),
              "t.rad:1: bad number of arguments for illum \"i\"");
    EXPECT_EQ(BuildError("void interface f 0 0 4 1 1 1 1\n"),
              "t.rad:1: bad number of arguments for interface \"f\"");
    EXPECT_EQ(BuildError(std::string(kPlastic) + "white sphere s 0 0 3 0 0 0\n"),
              "t.rad:2: bad number of arguments for sphere \"s\"");
    EXPECT_EQ(BuildError(std::string(kPlastic) + "white polygon p 0 0 6 0 0 0 1 0 0\n"),
              "t.rad:2: bad number of arguments for polygon \"p\"");
    EXPECT_EQ(BuildError("void spotlight s 0 0 7 1 1 1 30 0 0 0\n"),
              "t.rad:1: spotlight \"s\": zero focus vector");
}

TEST(BuildScene, UnsupportedTypesAreRejected) {
    // BSDF files are read (tests/scene/klems_bsdf_test.cpp); a missing one
    // names the material.
    EXPECT_EQ(testing::ErrorMessage([] { testing::BuildText("void BSDF b 6 0 blinds.xml 0 0 1 . 0 0\n"); },
                           Error::Kind::System),
              "t.rad:1: BSDF \"b\": cannot find BSDF file \"blinds.xml\"");
    EXPECT_EQ(BuildError("void aBSDF b 5 blinds.xml 0 0 1 . 0 2 1 1\n"),
              "t.rad:1: bad number of arguments for aBSDF \"b\"");
    // prism1 and prism2 need their function file after the expressions.
    EXPECT_EQ(BuildError("void prism2 p 8 1 0 0 0 1 0 0 0 0 1 1\n"),
              "t.rad:1: prism2 \"p\": too few string arguments");
    EXPECT_EQ(BuildError("void prism1 p 4 1 0 0 0 0 1 1\n"),
              "t.rad:1: prism1 \"p\": too few string arguments");
    // The text types read their font when the scene loads (Radiance: at
    // the first ray that meets them), and check their frame and arguments.
    EXPECT_EQ(BuildError("void brighttext t 3 nosuch.fnt . IO 0 11 0 1 0 1 0 0 0 -1 0 5 .5\n"),
              "t.rad:1: brighttext \"t\": font load error: cannot find font file \"nosuch.fnt\"");
    EXPECT_EQ(BuildError("void colortext t 3 nosuch.fnt . IO 0 15 0 1 0 1 0 0 2 0 0 1 1 1 0 0 0\n"),
              "t.rad:1: colortext \"t\": illegal motion vector");
    EXPECT_EQ(BuildError("void mixtext t 3 void void nosuch.fnt 0 9 0 1 0 1 0 0 0 -1 0\n"),
              "t.rad:1: bad number of arguments for mixtext \"t\"");
    EXPECT_EQ(BuildError("void mixtext t 4 red void f.fnt . 0 9 0 1 0 1 0 0 0 -1 0\n"),
              "t.rad:1: undefined modifier \"red\" for mixtext \"t\"");
    // A missing text file is a system error (exit 2), as Radiance's.
    EXPECT_EQ(testing::ErrorMessage(
                  [] { testing::BuildText("void brighttext t 2 f.fnt nosuch.txt 0 11 0 1 0 1 0 0 0 -1 0 5 .5\n"); },
                  Error::Kind::System),
              "t.rad:1: brighttext \"t\": cannot find text file \"nosuch.txt\"");
    EXPECT_NO_THROW(testing::BuildText("void prism1 p 5 1 0 0 0 . 0 0\n"));
    // mist: Radiance's words (and, for too many sources, its internal
    // error, exit 3), when the scene loads rather than at the first ray.
    EXPECT_EQ(BuildError("void mist m 0 0 8 1 1 1 .5 .5 .5 0 0\n"),
              "t.rad:1: bad arguments for mist \"m\"");
    std::string names;
    for (int i = 0; i < 33; ++i) names += " s" + std::to_string(i);
    EXPECT_EQ(testing::ErrorMessage([&] { testing::BuildText("void mist m 33" + names + " 0 3 1 1 1\n"); },
                                    Error::Kind::Internal),
              "t.rad:1: too many sources in list for mist \"m\"");
    // A material in a material's own modifier chain (Radiance: fatal).
    EXPECT_EQ(BuildError("void plastic a 0 0 5 1 1 1 0 0\na plastic b 0 0 5 1 1 1 0 0\n"),
              "t.rad:2: conflicting material \"a\" in the modifiers of plastic \"b\"");
}

// The materials with functions of their own: what Radiance finds at the
// first ray that meets them, lazyrad finds when the scene loads, in
// Radiance's words.
TEST(BuildScene, FunctionMaterialErrorsAreOneLineAtLoad) {
    EXPECT_EQ(BuildError("void plastic2 m 4 1 0 0 . 0 6 .5 .5 .5 .05 0 .1\n"),
              "t.rad:1: plastic2 \"m\": roughness too small");
    EXPECT_EQ(BuildError("void metal2 m 4 1 0 0 . 0 5 .5 .5 .5 .05 .1\n"),
              "t.rad:1: metal2 \"m\": bad number of real arguments");
    EXPECT_EQ(BuildError("void trans2 m 3 1 0 0 0 8 .5 .5 .5 .05 .1 .1 .5 .5\n"),
              "t.rad:1: trans2 \"m\": too few string arguments");
    EXPECT_EQ(BuildError("void ashik2 m 4 1 0 0 . 0 7 .3 .3 .3 .2 .2 .2 10\n"),
              "t.rad:1: ashik2 \"m\": bad number of real arguments");
    EXPECT_EQ(BuildError("void ashik2 m 3 1 0 0 0 8 .3 .3 .3 .2 .2 .2 10 10\n"),
              "t.rad:1: ashik2 \"m\": too few string arguments");
    EXPECT_EQ(BuildError("void plasfunc m 1 refl 0 4 .5 .5 .5 .5\n"),
              "t.rad:1: bad number of arguments for plasfunc \"m\"");
    EXPECT_EQ(BuildError("void transfunc m 2 refl . 0 5 .5 .5 .5 .5 .5\n"),
              "t.rad:1: bad number of arguments for transfunc \"m\"");
    EXPECT_EQ(BuildError("void BRTDfunc m 9 0 0 0 0 0 0 0 0 0 0 9 0 0 0 0 0 0 0 0 0\n"),
              "t.rad:1: bad number of arguments for BRTDfunc \"m\"");
    EXPECT_EQ(BuildError("void metfunc m 2 nosuch . 0 4 .5 .5 .5 .5\n"),
              "t.rad:1: metfunc \"m\": nosuch: undefined function");
    // A BRTDfunc's directional function named from '0' is none, not a name.
    EXPECT_EQ(BuildError("void BRTDfunc m 10 .1 .1 .1 0 0 0 0 nosuch 0 . 0 9 0 0 0 0 0 0 0 0 0\n"),
              "t.rad:1: BRTDfunc \"m\": nosuch: undefined function");
}

// antimatter (m_clip.c): what it clips is a modifier's definition, not its
// name; Radiance's argument limits and warnings.
TEST(BuildScene, AntimatterClipsDefinitions) {
    std::vector<std::string> warnings;
    const Scene scene = BuildText(
        "void plastic w 0 0 5 .5 .5 .5 0 0\n"
        "void alias w2 w\n"
        "w polygon a 0 0 9 0 0 0 1 0 0 0 1 0\n"
        "w2 polygon b 0 0 9 0 0 1 1 0 1 0 1 1\n"
        "void antimatter cut 4 w void nosuch w 0 0\n"
        "void plastic w 0 0 5 .5 .5 .5 0 0\n"
        "w polygon c 0 0 9 0 0 2 1 0 2 0 1 2\n"
        "cut sphere s 0 0 4 0 0 0 .5\n",
        &warnings);
    ASSERT_EQ(scene.surfaces.size(), 4u);
    EXPECT_TRUE(scene.MayBeClipped(scene.surfaces[0].modifierId));
    EXPECT_FALSE(scene.MayBeClipped(scene.surfaces[1].modifierId));  // the alias
    EXPECT_FALSE(scene.MayBeClipped(scene.surfaces[2].modifierId));  // w defined after
    EXPECT_FALSE(scene.MayBeClipped(scene.surfaces[3].modifierId));
    EXPECT_EQ(scene.surfaces[1].material, scene.surfaces[0].material);  // still shaded as w
    const auto cut = std::find_if(scene.materials.begin(), scene.materials.end(),
                                  [](const Material& m) { return m.name == "cut"; });
    ASSERT_NE(cut, scene.materials.end());
    const auto& clip = std::get<ClipParams>(cut->params);
    EXPECT_EQ(clip.clipped, std::vector<int>{scene.surfaces[0].modifierId});
    EXPECT_EQ(warnings, (std::vector<std::string>{
                            "t.rad:5: unknown modifier \"nosuch\" for antimatter \"cut\"",
                            "t.rad:5: duplicate modifier for antimatter \"cut\""}));
    // One to Radiance's MAXSET (511) names.
    EXPECT_EQ(BuildError("void antimatter a 0 0 0\n"),
              "t.rad:1: bad number of arguments for antimatter \"a\"");
    std::string many = "void antimatter a 512";
    for (int k = 0; k < 512; ++k) many += " void";
    EXPECT_EQ(BuildError(many + " 0 0\n"), "t.rad:1: bad number of arguments for antimatter \"a\"");
    many = "void antimatter a 511";
    for (int k = 0; k < 511; ++k) many += " void";
    EXPECT_NO_THROW(BuildText(many + " 0 0\n"));
}

TEST(BuildScene, UndefinedModifiers) {
    EXPECT_EQ(BuildError(std::string(kPlastic) + "\nred sphere s 0 0 4 0 0 0 1\n"),
              "t.rad:3: undefined modifier \"red\"");
    // A modifier defined after its use does not count (lookup at parse time).
    EXPECT_EQ(BuildError("p sphere s 0 0 4 0 0 0 1\nvoid plastic p 0 0 5 1 1 1 0 0\n"),
              "t.rad:1: undefined modifier \"p\"");
    // Surfaces are not modifiers.
    EXPECT_EQ(BuildError(std::string(kPlastic) + "white sphere s 0 0 4 0 0 0 1\ns sphere t 0 0 4 0 0 0 1\n"),
              "t.rad:3: undefined modifier \"s\"");
    EXPECT_EQ(BuildError("void illum i 1 nothing 0 3 1 1 1\n"),
              "t.rad:1: undefined alternate material \"nothing\" for illum \"i\"");
    EXPECT_EQ(BuildError("void alias a b\n"),
              "t.rad:1: undefined alias reference \"b\" in alias \"a\"");
}

TEST(BuildScene, MostRecentDefinitionWins) {
    const Scene scene = BuildText(
        "void plastic m 0 0 5 1 0 0 0 0\n"
        "m sphere a 0 0 4 0 0 0 1\n"
        "void metal m 0 0 5 0 1 0 0 0\n"
        "m sphere b 0 0 4 3 0 0 1\n"
        "void sphere c 0 0 4 6 0 0 1\n");
    ASSERT_EQ(scene.surfaces.size(), 3u);
    EXPECT_EQ(scene.surfaces[0].material, 0);
    EXPECT_EQ(scene.surfaces[1].material, 1);
    EXPECT_EQ(scene.surfaces[1].modifierName, "m");
    EXPECT_EQ(scene.surfaces[2].material, -1);
    EXPECT_EQ(scene.surfaces[2].modifierName, "void");
}

TEST(BuildScene, AliasesResolveAsRadianceDoes) {
    const Scene scene = BuildText(
        "void plastic base 0 0 5 .2 .3 .4 0 0\n"
        "inherit alias syn base\n"          // pure synonym
        "void alias same base\n"            // same modifier as base (void): synonym
        "void alias copy syn\n"             // syn is base, whose modifier is void: a synonym
        "syn polygon p1 0 0 9 0 0 0 1 0 0 0 1 0\n"
        "same polygon p2 0 0 9 0 0 0 1 0 0 0 1 0\n"
        "copy polygon p3 0 0 9 0 0 0 1 0 0 0 1 0\n");
    ASSERT_EQ(scene.surfaces.size(), 3u);
    EXPECT_EQ(scene.surfaces[0].material, 0);
    EXPECT_EQ(scene.surfaces[0].modifierName, "syn");
    EXPECT_EQ(scene.surfaces[1].material, 0);
    ASSERT_EQ(scene.materials.size(), 1u);
    EXPECT_EQ(scene.surfaces[2].material, 0);
    EXPECT_EQ(scene.surfaces[2].modifierName, "copy");

    // With another modifier, an alias is a copy of its reference's type and
    // arguments under that modifier (radiance-functions.md §11.12).
    const Scene patterned = BuildText(
        "void brightfunc b3 2 3 . 0 0\n"
        "void light l1 0 0 3 1 2 3\n"
        "b3 alias l1b l1\n"
        "l1b polygon p1 0 0 9 0 0 0 1 0 0 0 1 0\n");
    ASSERT_EQ(patterned.materials.size(), 2u);
    EXPECT_EQ(patterned.materials[1].name, "l1b");
    EXPECT_EQ(patterned.materials[1].args, patterned.materials[0].args);
    EXPECT_EQ(patterned.materials[1].patterns, std::vector<int>{0});
    EXPECT_TRUE(patterned.materials[0].patterns.empty());
    EXPECT_EQ(patterned.surfaces[0].material, 1);

    EXPECT_EQ(BuildError("void plastic a 0 0 5 1 1 1 0 0\nvoid plastic b 0 0 5 1 1 1 0 0\n"
                         "a alias c b\n"),
              "t.rad:3: conflicting material \"a\" in the modifiers of alias \"c\"");
}

TEST(BuildScene, PolygonNormalAreaOffset) {
    const Scene scene = BuildText(std::string(kPlastic) +
                                  "white polygon tri 0 0 9  0 0 2  2 0 2  0 3 2\n"
                                  "white polygon quad 0 0 15  0 0 0  0 1 0  0 1 1  0 0 1  0 0 0\n");
    ASSERT_EQ(scene.surfaces.size(), 2u);
    const auto& tri = std::get<Polygon>(scene.surfaces[0].shape);
    ExpectNear(tri.normal, {0, 0, 1});
    EXPECT_DOUBLE_EQ(tri.area, 3.0);
    EXPECT_DOUBLE_EQ(tri.offset, 2.0);
    const auto& quad = std::get<Polygon>(scene.surfaces[1].shape);
    EXPECT_EQ(quad.vertices.size(), 4u);  // closing vertex dropped
    ExpectNear(quad.normal, {1, 0, 0});
    EXPECT_DOUBLE_EQ(quad.area, 1.0);
    EXPECT_EQ(scene.surfaces[1].type, SurfaceType::Polygon);
}

TEST(BuildScene, ConcavePolygonAccepted) {
    // An L shape (area 3), listed clockwise seen from +z: normal -z.
    const Scene scene = BuildText(std::string(kPlastic) +
                                  "white polygon ell 0 0 18  0 0 0  0 2 0  1 2 0  1 1 0  2 1 0  2 0 0\n");
    ASSERT_EQ(scene.surfaces.size(), 1u);
    const auto& ell = std::get<Polygon>(scene.surfaces[0].shape);
    EXPECT_EQ(ell.vertices.size(), 6u);
    ExpectNear(ell.normal, {0, 0, -1});
    EXPECT_DOUBLE_EQ(ell.area, 3.0);
}

TEST(BuildScene, DegeneratePolygonsWarn) {
    std::vector<std::string> warnings;
    const Scene scene = BuildText(std::string(kPlastic) +
                                      "white polygon flat 0 0 9  0 0 0  1 1 1  2 2 2\n"
                                      "white polygon bent 0 0 12  0 0 0  1 0 0  1 1 0.1  0 1 0\n",
                                  &warnings);
    ASSERT_EQ(scene.surfaces.size(), 1u);  // zero-area polygon skipped
    EXPECT_EQ(scene.surfaces[0].name, "bent");
    ASSERT_EQ(warnings.size(), 2u);
    EXPECT_EQ(warnings[0], "t.rad:2: polygon \"flat\": zero area");
    EXPECT_EQ(warnings[1], "t.rad:3: polygon \"bent\": non-planar vertex");
}

TEST(BuildScene, SpheresAndBubbles) {
    std::vector<std::string> warnings;
    const Scene scene = BuildText(std::string(kPlastic) +
                                      "white sphere s 0 0 4 1 2 3 2\n"
                                      "white bubble b 0 0 4 0 0 0 1\n"
                                      "white sphere n 0 0 4 0 0 0 -1.5\n",
                                  &warnings);
    ASSERT_EQ(scene.surfaces.size(), 3u);
    EXPECT_EQ(scene.surfaces[0].type, SurfaceType::Sphere);
    EXPECT_FALSE(std::get<Sphere>(scene.surfaces[0].shape).inward);
    EXPECT_EQ(scene.surfaces[1].type, SurfaceType::Bubble);
    EXPECT_TRUE(std::get<Sphere>(scene.surfaces[1].shape).inward);
    EXPECT_EQ(scene.surfaces[2].type, SurfaceType::Bubble);
    EXPECT_DOUBLE_EQ(std::get<Sphere>(scene.surfaces[2].shape).radius, 1.5);
    EXPECT_EQ(warnings, std::vector<std::string>{"t.rad:4: sphere \"n\": negative radius"});
}

// A degenerate shape is dropped with oconv's warning, as Radiance's oconv
// leaves it out of the octree; as a light source it is Radiance's rtrace's
// fatal error (marksources() meets every source object).
TEST(BuildScene, DegenerateShapesAreDroppedUnlessTheyAreSources) {
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"sphere z 0 0 4 0 0 0 1e-7", "sphere \"z\": zero radius"},
        {"bubble z 0 0 4 0 0 0 0", "bubble \"z\": zero radius"},
        {"cone z 0 0 8 1 1 1 1 1 1 1 2", "cone \"z\": unknown orientation"},
        {"cone z 0 0 8 0 0 0 0 0 1 1 -1", "cone \"z\": illegal radii"},
        {"cup z 0 0 8 0 0 0 0 0 1 0 0", "cup \"z\": illegal radii"},
        {"cylinder z 0 0 7 0 0 0 0 0 1 0", "cylinder \"z\": illegal radii"},
        {"tube z 0 0 7 0 0 1 0 0 1 .5", "tube \"z\": unknown orientation"},
        {"ring z 0 0 8 0 0 0 0 0 1 1 1", "ring \"z\": illegal radii"},
        {"ring z 0 0 8 0 0 0 0 0 1 -1 2", "ring \"z\": illegal radii"},
        {"ring z 0 0 8 0 0 0 0 0 0 0 2", "ring \"z\": unknown orientation"},
        {"polygon z 0 0 9 0 0 0 1 0 0 2 0 0", "polygon \"z\": zero area"},
    };
    for (const auto& [object, warning] : cases) {
        std::vector<std::string> warnings;
        const Scene scene = BuildText(std::string(kPlastic) + "white " + object +
                                          "\nwhite sphere kept 0 0 4 0 0 0 1\n",
                                      &warnings);
        ASSERT_EQ(scene.surfaces.size(), 1u) << object;
        EXPECT_EQ(scene.surfaces[0].name, "kept");
        EXPECT_EQ(warnings, std::vector<std::string>{"t.rad:2: " + warning}) << object;
    }
    const std::string lamp = "void light lamp 0 0 3 1 1 1\n";
    EXPECT_EQ(BuildError(lamp + "lamp sphere z 0 0 4 0 0 0 0\n"),
              "t.rad:2: sphere \"z\": illegal source radius");
    EXPECT_EQ(BuildError(lamp + "lamp bubble z 0 0 4 0 0 0 0\n"),
              "t.rad:2: bubble \"z\": illegal material");
    EXPECT_EQ(BuildError(lamp + "lamp cylinder z 0 0 7 0 0 0 0 0 0 1\n"),
              "t.rad:2: cylinder \"z\": illegal source");
    EXPECT_EQ(BuildError(lamp + "lamp cone z 0 0 8 0 0 0 0 0 1 0 0\n"),
              "t.rad:2: cone \"z\": illegal material");
    EXPECT_EQ(BuildError(lamp + "lamp ring z 0 0 8 0 0 0 0 0 1 1 1\n"),
              "t.rad:2: ring \"z\": illegal source");
    // Not sources: a black light, a glow without radius; they are dropped.
    for (const std::string& m : {std::string("void light dark 0 0 3 0 0 0\n"),
                                 std::string("void glow dark 0 0 4 1 1 1 0\n")}) {
        std::vector<std::string> warnings;
        const Scene scene = BuildText(m + "dark sphere z 0 0 4 0 0 0 0\n", &warnings);
        EXPECT_TRUE(scene.surfaces.empty()) << m;
        EXPECT_EQ(warnings, std::vector<std::string>{"t.rad:2: sphere \"z\": zero radius"}) << m;
    }
}

TEST(BuildScene, ConesFollowConeC) {
    std::vector<std::string> warnings;
    const Scene scene = BuildText(std::string(kPlastic) +
                                      "white cone wide_first 0 0 8  0 0 0  0 0 2  1 .5\n"
                                      "white cone same 0 0 8  0 0 0  0 0 2  1 1\n"
                                      "white cup neg 0 0 8  0 0 0  0 0 2  -1 0\n"
                                      "white cylinder c 0 0 7  0 0 0  1 0 0  .5\n"
                                      "white tube t 0 0 7  0 0 0  1 0 0  -.5\n",
                                  &warnings);
    ASSERT_EQ(scene.surfaces.size(), 5u);
    const auto& wide = std::get<Cone>(scene.surfaces[0].shape);
    EXPECT_EQ(scene.surfaces[0].type, SurfaceType::Cone);
    ExpectNear(wide.p0, {0, 0, 2});  // narrow end first
    EXPECT_DOUBLE_EQ(wide.r0, .5);
    EXPECT_DOUBLE_EQ(wide.r1, 1);
    EXPECT_EQ(scene.surfaces[1].type, SurfaceType::Cylinder);
    EXPECT_EQ(scene.surfaces[2].type, SurfaceType::Cone);  // negative radii invert the cup
    EXPECT_FALSE(std::get<Cone>(scene.surfaces[2].shape).inward);
    EXPECT_EQ(scene.surfaces[3].type, SurfaceType::Cylinder);
    EXPECT_EQ(scene.surfaces[4].type, SurfaceType::Cylinder);  // negative tube radius
    EXPECT_EQ(warnings, (std::vector<std::string>{"t.rad:4: cup \"neg\": negative radii",
                                                  "t.rad:6: tube \"t\": negative radius"}));
}

TEST(BuildScene, RingsAndSources) {
    const Scene scene = BuildText(std::string(kPlastic) +
                                  "white ring r 0 0 8  1 2 3  0 0 2  2 .5\n"
                                  "void light l 0 0 3 1 1 1\n"
                                  "l source sun 0 0 4  0 3 4  0.5\n");
    ASSERT_EQ(scene.surfaces.size(), 2u);
    const auto& ring = std::get<Ring>(scene.surfaces[0].shape);
    ExpectNear(ring.normal, {0, 0, 1});
    EXPECT_DOUBLE_EQ(ring.r0, .5);
    EXPECT_DOUBLE_EQ(ring.r1, 2);
    const auto& sun = std::get<DistantSource>(scene.surfaces[1].shape);
    EXPECT_EQ(scene.surfaces[1].type, SurfaceType::Source);
    ExpectNear(sun.direction, {0, .6, .8});
    EXPECT_DOUBLE_EQ(sun.angleDegrees, .5);
    EXPECT_EQ(scene.surfaces[1].material, 1);

    EXPECT_EQ(BuildError("void source s 0 0 4 0 0 0 1\n"), "t.rad:1: source \"s\": zero direction");
    EXPECT_EQ(BuildError("void source s 0 0 4 0 0 1 0\n"), "t.rad:1: source \"s\": zero size");
}

/// Instance and mesh files that are nowhere on RAYPATH are system errors,
/// as in Radiance (exit status 2).
TEST(BuildScene, MissingInstanceFilesAreSystemErrors) {
    const auto missing = [](const std::string& text) {
        return rt::testing::ErrorMessage([&] { rt::testing::BuildText(text); }, Error::Kind::System);
    };
    EXPECT_EQ(missing("void instance i 1 x.oct 0 0\n"), "t.rad:1: cannot find octree file \"x.oct\"");
    EXPECT_EQ(missing("void mesh m 1 x.rtm 0 0\n"), "t.rad:1: cannot find mesh file \"x.rtm\"");
}

/// For untrusted input (the fuzzers) instance and mesh files are not read.
TEST(BuildScene, InstanceFilesCanBeDisabled) {
    SceneLoadOptions options;
    options.readFiles = false;
    const std::string square = std::string(RT_SOURCE_DIR) + "/tests/data/instance/square_frozen.oct";
    const auto objects = rt::testing::ParseText("void instance a 1 " + square + " 0 0\n");
    EXPECT_EQ(rt::testing::ErrorMessage([&] { BuildScene(objects, {}, options); }),
              "t.rad:1: instance \"a\": files disabled");
    EXPECT_NO_THROW(BuildScene(objects, {}));
}

/// oconv bounds an instance by its octree's cube, placed (radiance-functions.md
/// §13.1): two instances of a unit square, verified with Radiance's getinfo -d.
TEST(BuildScene, InstancesBoundTheCubeByTheirPlacedCubes) {
    const std::string square = std::string(RT_SOURCE_DIR) + "/tests/data/instance/square_frozen.oct";
    const Scene scene = BuildText("void instance a 7 " + square + " -s 2 -t 10 0 0 0 0\n" +
                                  "void instance b 5 " + square + " -t 0 10 0 0 0\n");
    ASSERT_EQ(scene.instances.size(), 2u);
    ASSERT_EQ(scene.prototypes.size(), 1u);  // one file, loaded once
    EXPECT_NEAR(scene.cubeOrigin.x, -2e-05, 1e-10);
    EXPECT_NEAR(scene.cubeOrigin.y, -0.50003, 1e-10);
    EXPECT_NEAR(scene.cubeOrigin.z, -6.000025, 1e-10);
    EXPECT_NEAR(scene.cubeSize, 12.00005, 1e-10);
}

TEST(BuildScene, CubeAsOconv) {
    // radiance-notes.md §2.2: a 4×4×3 box gives origin (−1e-5, −1e-5, −0.50001), size 4.00002.
    const Scene scene = BuildText(std::string(kPlastic) +
                                  "white polygon a 0 0 12 0 0 0 4 0 0 4 4 0 0 4 0\n"
                                  "white polygon b 0 0 12 0 0 3 0 4 3 4 4 3 4 0 3\n"
                                  "void glow sky 0 0 4 1 1 1 0\nsky source s 0 0 4 0 0 1 180\n");
    EXPECT_NEAR(scene.cubeSize, 4.00002, 1e-12);
    ExpectNear(scene.cubeOrigin, {-1e-5, -1e-5, -0.50001});

    const Scene empty = BuildText("void glow sky 0 0 4 1 1 1 0\nsky source s 0 0 4 0 0 1 180\n");
    EXPECT_EQ(empty.cubeSize, 1.0);
    ExpectNear(empty.cubeOrigin, {-0.5, -0.5, -0.5});
}

TEST(BuildScene, DistanceToleranceFollowsSmallScenes) {
    const auto box = [](double size, double x) {
        std::string text = kPlastic;
        for (double z : {0.0, size}) {
            text += "white polygon p 0 0 12 ";
            for (double v : {x, 0.0, z, x + size, 0.0, z, x + size, size, z, x, size, z}) {
                text += std::to_string(v) + " ";
            }
            text += "\n";
        }
        return BuildText(text);
    };
    // Unit size and up: Radiance's FTINY and OMARGIN exactly.
    EXPECT_EQ(box(1, 0).distanceTolerance, kFtiny);
    EXPECT_EQ(box(5000, 0).distanceTolerance, kFtiny);
    EXPECT_NEAR(box(5000, 0).cubeSize, 5000.00002, 1e-9);
    // Smaller scenes: in proportion, margin included, so a scaled model keeps
    // its proportions.
    const Scene small = box(0.001, 0);
    EXPECT_NEAR(small.distanceTolerance, 1e-9, 1e-21);
    EXPECT_NEAR(small.ToleranceScale(), 1e-3, 1e-15);
    EXPECT_NEAR(small.cubeSize, 0.001 * 1.00002, 1e-15);
    // A small scene far out: never below 1000 ulps of its coordinates.
    const Scene far = box(0.001, 1e6);
    EXPECT_NEAR(far.distanceTolerance, 1e3 * 2.220446049250313e-16 * (1e6 + 0.001), 1e-15);
}

TEST(SurfaceBounds, ExactForCurvedSurfaces) {
    const Scene scene = BuildText(std::string(kPlastic) +
                                  "white sphere s 0 0 4 1 2 3 2\n"
                                  "white ring r 0 0 8 0 0 0 0 0 1 0 2\n"
                                  "white cylinder c 0 0 7 0 0 0 0 0 4 1\n"
                                  "void source d 0 0 4 0 0 1 1\n");
    const Bounds3 sphere = SurfaceBounds(scene.surfaces[0]);
    ExpectNear(sphere.lo, {-1, 0, 1});
    ExpectNear(sphere.hi, {3, 4, 5});
    const Bounds3 ring = SurfaceBounds(scene.surfaces[1]);
    ExpectNear(ring.lo, {-2, -2, 0});
    ExpectNear(ring.hi, {2, 2, 0});
    const Bounds3 cylinder = SurfaceBounds(scene.surfaces[2]);
    ExpectNear(cylinder.lo, {-1, -1, 0});
    ExpectNear(cylinder.hi, {1, 1, 4});
    EXPECT_TRUE(SurfaceBounds(scene.surfaces[3]).Empty());

    // A tilted ring: every point of the circle lies inside its bounds.
    const Scene tilted = BuildText(std::string(kPlastic) + "white ring t 0 0 8 1 1 1 1 1 1 0 1\n");
    const auto& ring2 = std::get<Ring>(tilted.surfaces[0].shape);
    const Bounds3 b = SurfaceBounds(tilted.surfaces[0]);
    const Vec3 u = Perpendicular(ring2.normal), v = Cross(ring2.normal, u);
    for (int i = 0; i < 360; ++i) {
        const double a = i * kPi / 180;
        const Vec3 p = ring2.center + (u * std::cos(a) + v * std::sin(a)) * ring2.r1;
        for (int k = 0; k < 3; ++k) {
            EXPECT_GE(p[k], b.lo[k] - 1e-12);
            EXPECT_LE(p[k], b.hi[k] + 1e-12);
        }
    }
}

TEST(MaterialType, NamesAndClasses) {
    EXPECT_STREQ(MaterialTypeName(MaterialType::Plastic), "plastic");
    EXPECT_STREQ(MaterialTypeName(MaterialType::Interface), "interface");
    EXPECT_STREQ(MaterialTypeName(MaterialType::Spotlight), "spotlight");
    EXPECT_TRUE(IsTransparentType(MaterialType::Trans));
    EXPECT_TRUE(IsTransparentType(MaterialType::Glass));
    EXPECT_TRUE(IsTransparentType(MaterialType::Dielectric));
    EXPECT_TRUE(IsTransparentType(MaterialType::Interface));
    EXPECT_FALSE(IsTransparentType(MaterialType::Mirror));
    EXPECT_FALSE(IsTransparentType(MaterialType::Plastic));
    EXPECT_TRUE(IsLightType(MaterialType::Light));
    EXPECT_TRUE(IsLightType(MaterialType::Illum));
    EXPECT_TRUE(IsLightType(MaterialType::Glow));
    EXPECT_TRUE(IsLightType(MaterialType::Spotlight));
    EXPECT_FALSE(IsLightType(MaterialType::Mirror));
}

}  // namespace
}  // namespace rt

namespace rt {
namespace {

TEST(BuildScenePatterns, ChainsOnBothSidesOfTheMaterial) {
    const Scene scene = BuildText(
        "void brightfunc b3 2 3 . 0 0\n"
        "b3 brightfunc b2 2 2 . 0 0\n"          // a pattern modified by a pattern
        "b2 light l1 0 0 3 1 2 3\n"             // the material's own chain: b2, b3
        "l1 colorfunc c 4 1 2 Px . 0 0\n"       // between the surface and the material
        "c polygon p 0 0 9 0 0 0 1 0 0 0 1 0\n");
    ASSERT_EQ(scene.patterns.size(), 3u);
    EXPECT_EQ(scene.patterns[0].type, PatternType::BrightFunc);
    EXPECT_EQ(scene.patterns[2].type, PatternType::ColorFunc);
    EXPECT_EQ(scene.patterns[2].values.size(), 3u);
    EXPECT_EQ(scene.patterns[2].owner, "colorfunc \"c\"");
    ASSERT_EQ(scene.materials.size(), 1u);
    EXPECT_EQ(scene.materials[0].patterns, (std::vector<int>{1, 0}));
    ASSERT_EQ(scene.surfaces.size(), 1u);
    EXPECT_EQ(scene.surfaces[0].material, 0);
    EXPECT_EQ(scene.surfaces[0].patterns, std::vector<int>{2});
    EXPECT_EQ(scene.surfaces[0].modifierName, "c");
    EXPECT_NE(scene.functions, nullptr);
    // Without patterns, no function language at all.
    EXPECT_EQ(BuildText("void plastic w 0 0 5 .5 .5 .5 0 0\n").functions, nullptr);
}

TEST(BuildScenePatterns, TransformIsInvertedIntoPatternSpace) {
    const Scene scene = BuildText(
        "void brightfunc b 9 Px . junk -s 2 -t 1 0 0\n0\n0\n"
        "void brightfunc m 3 Px . -mx\n0\n0\n");
    ASSERT_EQ(scene.patterns.size(), 2u);
    // The arguments scale by 2, then move by 1 along x; pattern space undoes it.
    const Transform& f = scene.patterns[0].patternFromWorld;
    const Vec3 p = f.Point(Vec3(3, 4, 6));
    EXPECT_NEAR(p.x, 1, 1e-12);
    EXPECT_NEAR(p.y, 2, 1e-12);
    EXPECT_NEAR(p.z, 3, 1e-12);
    EXPECT_NEAR(f.scale, 0.5, 1e-15);
    // A mirror's scale factor S is positive.
    EXPECT_EQ(scene.patterns[1].patternFromWorld.scale, 1.0);
}

TEST(BuildScenePatterns, Errors) {
    EXPECT_EQ(BuildError("void brightfunc b 1 Px 0 0\n"),
              "t.rad:1: bad number of arguments for brightfunc \"b\"");
    EXPECT_EQ(BuildError("void brightfunc b 4 Px . -t 1\n0\n0\n"),
              "t.rad:1: bad transform for brightfunc \"b\"");
    EXPECT_NE(BuildError("void brightfunc b 2 Px+*2 .\n0\n0\n").find("t.rad:1: brightfunc \"b\":1:"),
              std::string::npos);
    // A missing function file is a system error, as in Radiance.
    EXPECT_EQ(testing::ErrorMessage(
                  [] { BuildText("void brightfunc b 2 x no_such_file_anywhere.cal\n0\n0\n"); },
                  Error::Kind::System),
              "t.rad:1: cannot find function file \"no_such_file_anywhere.cal\"");
    EXPECT_EQ(BuildError("void plastic a 0 0 5 1 1 1 0 0\nvoid brightfunc b 2 1 . 0 0\n"
                         "b alias c a\nc plastic d 0 0 5 1 1 1 0 0\n"),
              "t.rad:4: conflicting material \"c\" in the modifiers of plastic \"d\"");
}

TEST(BuildSceneTextures, TexfuncIsATextureInTheChain) {
    const Scene scene = BuildText(
        "void colorfunc c 4 1 2 3 . 0 0\n"
        "c texfunc t 8 .5 0 0 . -rz 90 -s 2\n0\n0\n"
        "t plastic m 0 0 5 .5 .5 .5 0 0\n"
        "m polygon p 0 0 9 0 0 0 1 0 0 0 1 0\n");
    ASSERT_EQ(scene.patterns.size(), 2u);
    const Pattern& t = scene.patterns[1];
    EXPECT_EQ(t.kind, ModifierKind::Texture);
    EXPECT_EQ(t.values.size(), 3u);
    EXPECT_EQ(scene.materials[0].patterns, (std::vector<int>{1, 0}));
    // Its displacement turns with the transform as written (§11.8): x to y;
    // the scale is divided out where it is applied.
    const Vec3 d = t.worldFromPattern.Vector(Vec3(0.5, 0, 0)) / t.worldFromPattern.scale;
    ExpectNear(d, Vec3(0, 0.5, 0), 1e-15);
    EXPECT_EQ(BuildError("void texfunc t 3 1 0 0 0 0\n"),
              "t.rad:1: bad number of arguments for texfunc \"t\"");
}

TEST(BuildSceneMixtures, SidesAreTheChainsDefinedBefore) {
    const Scene scene = BuildText(
        "void plastic a 0 0 5 .5 .5 .5 0 0\n"
        "void brightfunc b 2 2 . 0 0\n"
        "b metal c 0 0 5 .5 .5 .5 .9 0\n"
        "c brightfunc q 2 3 . 0 0\n"             // a pattern, then c (with b)
        "void mixfunc mx 4 a q .5 . 0 0\n"
        "void mixfunc nest 4 mx void .5 . 0 0\n"
        "nest polygon s 0 0 9 0 0 0 1 0 0 0 1 0\n"
        "void plastic a 0 0 5 1 1 1 0 0\n");     // later: not the mixture's
    ASSERT_EQ(scene.patterns.size(), 4u);
    const Pattern& mx = scene.patterns[2];
    EXPECT_EQ(mx.kind, ModifierKind::Mixture);
    EXPECT_EQ(mx.values.size(), 1u);
    EXPECT_EQ(mx.fore.material, 0);
    EXPECT_TRUE(mx.fore.modifiers.empty());
    EXPECT_EQ(mx.back.modifiers, std::vector<int>{1});
    EXPECT_EQ(mx.back.material, 1);
    EXPECT_EQ(scene.materials[1].patterns, std::vector<int>{0});
    const Pattern& nest = scene.patterns[3];
    EXPECT_EQ(nest.fore.modifiers, std::vector<int>{2});
    EXPECT_EQ(nest.fore.material, -1);
    EXPECT_EQ(nest.back.material, -1);
    // The surface's chain ends at the mixture: no single material.
    EXPECT_EQ(scene.surfaces[0].patterns, std::vector<int>{3});
    EXPECT_EQ(scene.surfaces[0].material, -1);
}

TEST(BuildSceneMixtures, PatternMixtureKeepsItsModifier) {
    const Scene scene = BuildText(
        "void light l 0 0 3 1 1 1\n"
        "void brightfunc b2 2 2 . 0 0\nvoid brightfunc b4 2 4 . 0 0\n"
        "l mixfunc mx 4 b2 b4 .25 . 0 0\n"
        "mx polygon s 0 0 9 0 0 0 1 0 0 0 1 0\n");
    EXPECT_EQ(scene.surfaces[0].patterns, std::vector<int>{2});
    EXPECT_EQ(scene.surfaces[0].material, 0);
}

TEST(BuildSceneMixtures, Errors) {
    EXPECT_EQ(BuildError("void mixfunc mx 3 a b .5 0 0\n"),
              "t.rad:1: bad number of arguments for mixfunc \"mx\"");
    EXPECT_EQ(BuildError("void plastic a 0 0 5 1 1 1 0 0\n"
                         "void mixfunc mx 4 a nosuch .5 . 0 0\n"),
              "t.rad:2: undefined modifier \"nosuch\" for mixfunc \"mx\"");
    // Defined only after the mixture: undefined for it.
    EXPECT_EQ(BuildError("void mixfunc mx 4 void a .5 . 0 0\n"
                         "void plastic a 0 0 5 1 1 1 0 0\n"),
              "t.rad:1: undefined modifier \"a\" for mixfunc \"mx\"");
    EXPECT_EQ(BuildError("void plastic a 0 0 5 1 1 1 0 0\n"
                         "a mixfunc mx 4 a void .5 . 0 0\n"),
              "t.rad:2: inappropriate modifier for mixfunc \"mx\"");
    EXPECT_EQ(BuildError("void plastic a 0 0 5 1 1 1 0 0\n"
                         "void mixfunc mx 4 a void .5 . 0 0\n"
                         "void brightfunc b 2 1 . 0 0\nb alias mx2 mx\n"),
              "t.rad:4: inappropriate modifier for mixfunc \"mx2\"");
    // A mixture with a material in a material's own chain is a second material.
    EXPECT_EQ(BuildError("void plastic a 0 0 5 1 1 1 0 0\n"
                         "void mixfunc mx 4 a void .5 . 0 0\n"
                         "mx plastic d 0 0 5 1 1 1 0 0\n"),
              "t.rad:3: conflicting material \"mx\" in the modifiers of plastic \"d\"");
}

}  // namespace
}  // namespace rt
