// SPDX-License-Identifier: MIT
#include <gtest/gtest.h>

#include <sstream>

#include "scene/reader.h"
#include "scene/transform.h"
#include "scene_test_util.h"

namespace rt {
namespace {

void ExpectNear(const Vec3& a, const Vec3& b, double tolerance = 1e-12) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

Transform Parse(const std::vector<std::string>& args) {
    const ParsedTransform parsed = ParseTransformArgs(args);
    EXPECT_EQ(parsed.next, args.size());
    return parsed.transform;
}

SceneObject One(const std::string& text) {
    const auto objects = testing::ParseText(text);
    EXPECT_EQ(objects.size(), 1u);
    return objects.at(0);
}

TEST(Transform, RotationsAreCounterClockwise) {
    ExpectNear(Parse({"-rz", "90"}).Point({1, 0, 0}), {0, 1, 0});
    ExpectNear(Parse({"-rx", "90"}).Point({0, 1, 0}), {0, 0, 1});
    ExpectNear(Parse({"-ry", "90"}).Point({0, 0, 1}), {1, 0, 0});
}

TEST(Transform, AppliedInOrder) {
    ExpectNear(Parse({"-rz", "90", "-t", "1", "0", "0"}).Point({1, 0, 0}), {1, 1, 0});
    ExpectNear(Parse({"-t", "1", "0", "0", "-rz", "90"}).Point({1, 0, 0}), {0, 2, 0});
    const Transform scaled = Parse({"-s", "2", "-t", "0", "0", "1"});
    ExpectNear(scaled.Point({1, 1, 1}), {2, 2, 3});
    ExpectNear(scaled.Vector({1, 1, 1}), {2, 2, 2});
    EXPECT_DOUBLE_EQ(scaled.scale, 2);
}

TEST(Transform, MirrorsMakeScaleNegative) {
    const Transform mirror = Parse({"-mx"});
    ExpectNear(mirror.Point({1, 2, 3}), {-1, 2, 3});
    EXPECT_DOUBLE_EQ(mirror.scale, -1);
    EXPECT_DOUBLE_EQ(Parse({"-mx", "-my"}).scale, 1);
    EXPECT_DOUBLE_EQ(Parse({"-s", "-3"}).scale, -3);
}

TEST(Transform, IterationRepeatsTheFollowingGroup) {
    ExpectNear(Parse({"-i", "3", "-t", "1", "0", "0"}).Point({0, 0, 0}), {3, 0, 0});
    // The group before -i applies once, first.
    ExpectNear(Parse({"-t", "0", "0", "1", "-i", "4", "-rz", "90"}).Point({1, 0, 0}), {1, 0, 1});
    ExpectNear(Parse({"-i", "0", "-t", "5", "5", "5"}).Point({1, 1, 1}), {1, 1, 1});
    ExpectNear(Parse({"-i", "1000000", "-t", "1", "0", "0"}).Point({0, 0, 0}), {1e6, 0, 0}, 1e-6);
    const Transform composed = Compose(Parse({"-rz", "90"}), Parse({"-t", "1", "0", "0"}));
    ExpectNear(composed.Point({1, 0, 0}), {1, 1, 0});
}

TEST(Transform, StopsWhereXfStops) {
    const std::vector<std::string> args = {"-t", "1", "2", "3", "scene.rad"};
    EXPECT_EQ(ParseTransformArgs(args).next, 4u);
    EXPECT_EQ(ParseTransformArgs({"-t", "1", "x", "3"}).next, 0u);
    EXPECT_EQ(ParseTransformArgs({"-rz", "10", "-s", "0"}).next, 2u);
    EXPECT_EQ(ParseTransformArgs({"-q"}).next, 0u);
    EXPECT_EQ(ParseTransformArgs({"-rz"}).next, 0u);
    EXPECT_EQ(ParseTransformArgs({"-c", "-rz", "5"}, 1).next, 3u);
}

TEST(TransformSceneObject, PolygonsReverseUnderMirror) {
    XformSettings settings;
    settings.transform = Parse({"-mx"});
    const SceneObject out = TransformSceneObject(One("m polygon p 0 0 9 1 0 0 2 0 0 2 1 0\n"), settings);
    EXPECT_EQ(out.rargs, (std::vector<double>{-2, 1, 0, -2, 0, 0, -1, 0, 0}));
    settings.invert = true;  // mirror and invert cancel
    const SceneObject both = TransformSceneObject(One("m polygon p 0 0 9 1 0 0 2 0 0 2 1 0\n"), settings);
    EXPECT_EQ(both.rargs, (std::vector<double>{-1, 0, 0, -2, 0, 0, -2, 1, 0}));
}

TEST(TransformSceneObject, InvertSurfacesRenameAndRemodify) {
    XformSettings settings;
    settings.transform = Parse({"-s", "2", "-t", "1", "0", "0"});
    settings.invert = true;
    settings.idPrefix = "copy";
    settings.newModifier = "other";
    const SceneObject sphere = TransformSceneObject(One("m sphere s 0 0 4 1 1 1 .5\n"), settings);
    EXPECT_EQ(sphere.type, "bubble");
    EXPECT_EQ(sphere.name, "copy.s");
    EXPECT_EQ(sphere.modifier, "other");
    EXPECT_EQ(sphere.rargs, (std::vector<double>{3, 2, 2, 1}));
    EXPECT_EQ(TransformSceneObject(One("m cylinder c 0 0 7 0 0 0 0 0 1 1\n"), settings).type, "tube");
    EXPECT_EQ(TransformSceneObject(One("m cup c 0 0 8 0 0 0 0 0 1 1 2\n"), settings).type, "cone");
    const SceneObject ring = TransformSceneObject(One("m ring r 0 0 8 0 0 0 0 0 1 0 1\n"), settings);
    EXPECT_EQ(ring.type, "ring");
    EXPECT_EQ(ring.rargs, (std::vector<double>{1, 0, 0, 0, 0, -2, 0, 2}));
    // Materials keep their names and modifiers.
    const SceneObject plastic = TransformSceneObject(One("void plastic m 0 0 5 1 1 1 0 0\n"), settings);
    EXPECT_EQ(plastic.name, "m");
    EXPECT_EQ(plastic.modifier, "void");
    EXPECT_EQ(plastic.rargs, (std::vector<double>{1, 1, 1, 0, 0}));
}

TEST(TransformSceneObject, LengthsInMaterialsAndSources) {
    XformSettings settings;
    settings.transform = Parse({"-rz", "90", "-s", "2"});
    settings.transformArgs = {"-rz", "90", "-s", "2"};
    EXPECT_EQ(TransformSceneObject(One("void glow g 0 0 4 1 1 1 3\n"), settings).rargs[3], 6);
    const SceneObject spot = TransformSceneObject(One("void spotlight s 0 0 7 1 1 1 30 1 0 0\n"), settings);
    EXPECT_NEAR(spot.rargs[4], 0, 1e-12);
    EXPECT_NEAR(spot.rargs[5], 2, 1e-12);
    const SceneObject source = TransformSceneObject(One("void source s 0 0 4 1 0 0 .5\n"), settings);
    EXPECT_NEAR(source.rargs[1], 2, 1e-12);
    EXPECT_EQ(source.rargs[3], .5);
    EXPECT_NEAR(TransformSceneObject(One("void dielectric d 0 0 5 .25 .25 .25 1.5 0\n"), settings)
                    .rargs[0], .5, 1e-12);
    const SceneObject pattern = TransformSceneObject(One("void colorfunc c 4 r g b f.cal 0 0\n"), settings);
    EXPECT_EQ(pattern.sargs, (std::vector<std::string>{"r", "g", "b", "f.cal", "-i", "1", "-rz",
                                                       "90", "-s", "2"}));
}

TEST(TransformSceneObject, BadArgumentsNameTheObject) {
    XformSettings settings;
    const std::string message = testing::ErrorMessage(
        [&] { TransformSceneObject(One("m sphere s 0 0 3 1 1 1\n"), settings); });
    EXPECT_EQ(message, "t.rad:1: bad sphere \"s\"");
}

TEST(FormatSceneObject, RoundTripsThroughTheReader) {
    const auto objects = testing::ParseText(
        "void plastic 'my mat' 0 0 5 .1 .2 .3 0 0\n"
        "'my mat' polygon p 0 0 9 0 0 0 1 0 0 0 1 0.123456789012\n"
        "inherit alias a 'my mat'\n"
        "void colorfunc c 2 \"two words\" x 0 0\n");
    std::string text;
    for (const SceneObject& o : objects) text += FormatSceneObject(o);
    EXPECT_NE(text.find("\n\"my mat\" polygon p\n0\n0\n9\n"), std::string::npos) << text;
    const auto again = testing::ParseText(text);
    ASSERT_EQ(again.size(), objects.size());
    for (std::size_t i = 0; i < again.size(); ++i) {
        EXPECT_EQ(again[i].modifier, objects[i].modifier);
        EXPECT_EQ(again[i].type, objects[i].type);
        EXPECT_EQ(again[i].name, objects[i].name);
        EXPECT_EQ(again[i].sargs, objects[i].sargs);
        EXPECT_EQ(again[i].rargs, objects[i].rargs);
    }
}

}  // namespace
}  // namespace rt
