// SPDX-License-Identifier: MIT
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "scene_test_util.h"

namespace rt {
namespace {

using testing::ToolOptions;

const std::string kScenes = RT_SOURCE_DIR "/scenes/";

Scene Load(const std::vector<std::string>& files, std::vector<std::string>* warnings = nullptr) {
    return LoadScene(files, ToolOptions(), [warnings](const std::string& message) {
        if (warnings != nullptr) warnings->push_back(message);
    });
}

/// The scene with `!genbox | xform` lines, run through our tools, must equal the
/// one real Radiance expanded: same surfaces in the same order, names, modifiers,
/// vertex order, coordinates within 1e-9, and the same materials.
void ExpectSameScene(const Scene& ours, const Scene& radiance) {
    ASSERT_EQ(ours.surfaces.size(), radiance.surfaces.size());
    for (std::size_t i = 0; i < ours.surfaces.size(); ++i) {
        const Surface& a = ours.surfaces[i];
        const Surface& b = radiance.surfaces[i];
        SCOPED_TRACE(b.name);
        EXPECT_EQ(a.name, b.name);
        EXPECT_EQ(a.type, b.type);
        EXPECT_EQ(a.modifierName, b.modifierName);
        EXPECT_EQ(a.material, b.material);
        if (const auto* pa = std::get_if<Polygon>(&a.shape)) {
            const auto& pb = std::get<Polygon>(b.shape);
            ASSERT_EQ(pa->vertices.size(), pb.vertices.size());
            for (std::size_t v = 0; v < pa->vertices.size(); ++v) {
                for (int k = 0; k < 3; ++k) EXPECT_NEAR(pa->vertices[v][k], pb.vertices[v][k], 1e-9);
            }
            EXPECT_NEAR(pa->area, pb.area, 1e-9);
        }
    }
    ASSERT_EQ(ours.materials.size(), radiance.materials.size());
    for (std::size_t i = 0; i < ours.materials.size(); ++i) {
        EXPECT_EQ(ours.materials[i].name, radiance.materials[i].name);
        EXPECT_EQ(ours.materials[i].type, radiance.materials[i].type);
        EXPECT_EQ(ours.materials[i].args, radiance.materials[i].args);
    }
    EXPECT_NEAR(ours.cubeSize, radiance.cubeSize, 1e-9);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(ours.cubeOrigin[k], radiance.cubeOrigin[k], 1e-9);
}

TEST(LoadScene, CornellGeneratedMatchesRadiance) {
    std::vector<std::string> warnings;
    const Scene ours = Load({kScenes + "cornell/cornell_src.rad"}, &warnings);
    const Scene radiance = Load({kScenes + "cornell/cornell.rad"}, &warnings);
    EXPECT_TRUE(warnings.empty());
    ASSERT_EQ(ours.surfaces.size(), 18u);
    EXPECT_EQ(ours.surfaces[6].name, "short_block.1540");
    EXPECT_EQ(ours.surfaces[6].loc.file,
              kScenes + "cornell/cornell_src.rad:82: !genbox white short_block 1.65 1.65 1.65 | "
                        "xform -rz -17 -t 1.3 0.9 0");
    ExpectSameScene(ours, radiance);
    EXPECT_NEAR(ours.cubeSize, 5.56002, 1e-9);
    EXPECT_NEAR(ours.cubeOrigin.x, -1e-5, 1e-12);
    EXPECT_NEAR(ours.cubeOrigin.z, (5.48 - 5.56002) / 2, 1e-9);
}

TEST(LoadScene, DaylitRoomGeneratedMatchesRadiance) {
    const Scene ours = Load({kScenes + "daylit_room/daylit_room_src.rad"});
    const Scene radiance = Load({kScenes + "daylit_room/daylit_room.rad"});
    ExpectSameScene(ours, radiance);
    int sources = 0;
    for (const Surface& s : ours.surfaces) sources += s.type == SurfaceType::Source;
    EXPECT_EQ(sources, 2);
}

TEST(LoadScene, AnalyticScenes) {
    const Scene furnace = Load({kScenes + "furnace/furnace.rad"});
    ASSERT_EQ(furnace.surfaces.size(), 1u);
    EXPECT_EQ(furnace.surfaces[0].type, SurfaceType::Bubble);
    EXPECT_NEAR(furnace.cubeSize, 2.00002, 1e-12);
    const Scene sky = Load({kScenes + "skyplane/skyplane.rad"});
    ASSERT_EQ(sky.surfaces.size(), 2u);
    EXPECT_EQ(sky.surfaces[0].type, SurfaceType::Source);
    EXPECT_EQ(sky.surfaces[1].type, SurfaceType::Ring);
    EXPECT_EQ(sky.materials[static_cast<std::size_t>(sky.surfaces[0].material)].type,
              MaterialType::Glow);
}

TEST(LoadScene, SeveralFilesInOrder) {
    const auto dir = std::filesystem::temp_directory_path() / "rt_scene_loader";
    std::filesystem::create_directories(dir);
    const std::string materials = (dir / "materials.rad").string();
    const std::string geometry = (dir / "geometry.rad").string();
    const std::string empty = (dir / "empty.rad").string();
    std::ofstream(materials) << "void plastic m 0 0 5 1 1 1 0 0\n";
    std::ofstream(geometry) << "m sphere s 0 0 4 0 0 0 1\n";
    std::ofstream(empty) << "# nothing\n";
    std::vector<std::string> warnings;
    const Scene scene = Load({materials, empty, geometry}, &warnings);
    ASSERT_EQ(scene.surfaces.size(), 1u);
    EXPECT_EQ(scene.surfaces[0].material, 0);
    EXPECT_EQ(scene.surfaces[0].loc.ToString(), geometry + ":1");
    EXPECT_EQ(warnings, std::vector<std::string>{"(" + empty + "): empty file"});

    // Modifiers must come first, across files too.
    const std::string message =
        testing::ErrorMessage([&] { Load({geometry, materials}); });
    EXPECT_EQ(message, geometry + ":1: undefined modifier \"m\"");
    std::filesystem::remove_all(dir);
}

TEST(LoadScene, AnEmptyFileAloneIsNotAnOctree) {
    // What a failed `oconv > x.oct` leaves; Radiance 5.4a's rtrace: "fatal -
    // (empty.oct): not an octree". Among other files it is only warned about
    // (SeveralFilesInOrder).
    const auto dir = std::filesystem::temp_directory_path() / "rt_scene_loader_empty";
    std::filesystem::create_directories(dir);
    const std::string empty = (dir / "empty.oct").string();
    std::ofstream(empty).close();
    EXPECT_EQ(testing::ErrorMessage([&] { Load({empty}); }), "(" + empty + "): not an octree");
    std::filesystem::remove_all(dir);
}

TEST(LoadScene, UnreadableFileIsSystemError) {
    const std::string missing = "/nonexistent/dir/scene.rad";
    const std::string message =
        testing::ErrorMessage([&] { Load({missing}); }, Error::Kind::System);
    // Radiance 5.4a's words for rtrace's one scene argument.
    EXPECT_EQ(message, "cannot open octree file \"" + missing + "\": No such file or directory");
    const std::string other = testing::ErrorMessage(
        [&] { Load({missing, missing}); }, Error::Kind::System);
    EXPECT_EQ(other, "cannot open scene file \"" + missing + "\": No such file or directory");
    const std::string directory = testing::ErrorMessage(
        [&] { Load({std::filesystem::temp_directory_path().string()}); }, Error::Kind::System);
    EXPECT_NE(directory.find("is a directory"), std::string::npos);
}

}  // namespace
}  // namespace rt
