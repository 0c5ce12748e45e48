// SPDX-License-Identifier: MIT
//
// The obstructor cache's layout (shading/obstructors.h, Radiance's
// srcobstr.c): every cell has a fill ray of its own, whose blocker, as
// Radiance records it, lands in that cell and no other; rays with no cell
// are told apart.
#include "shading/obstructors.h"

#include <limits>
#include <map>
#include <set>
#include <sstream>

#include <gtest/gtest.h>

#include "scene/loader.h"

namespace rt {
namespace {

Scene Build(const std::string& text) {
    std::istringstream in(text);
    return BuildScene(ReadSceneObjects(in, "t.rad", {}, {}), {});
}

/// Each cell's fill ray is a unit ray away from the source, and the ray
/// aimed back at the source along it, from a point `back` along it, lands in
/// that cell.
void ExpectEveryCellItsOwnRay(const ObstructorLayout& layout, const LightSource& src,
                              double back) {
    for (int c = 0; c < layout.CellCount(); ++c) {
        const ObstructorFillRay fill = MakeObstructorFillRay(layout, src, c);
        ASSERT_NEAR(Length(fill.dir), 1.0, 1e-12) << "cell " << c;
        EXPECT_EQ(layout.Cell(fill.org + fill.dir * back, -fill.dir), c);
    }
}

const char* const kLights = R"(
void light lamp 0 0 3 10 10 10
void spotlight spot 0 0 7 10 10 10 60 0 0 -1
void glow halo 0 0 4 1 1 1 2
void glow skyglow 0 0 4 1 1 1 0
lamp polygon panel 0 0 12 1 1 3  1 2 3  2 2 3  2 1 3
lamp sphere globe 0 0 4 3 3 2 .1
lamp cylinder tube 0 0 7 4 1 2.5 4 3 2.5 .05
lamp source sun 0 0 4 .3 -.7 .65 .5
spot ring spotlamp 0 0 8 5 4 2.95 0 0 -1 0 .1
halo sphere halobulb 0 0 4 1 4 1 .1
skyglow source sky 0 0 4 0 0 1 180
void plastic grey 0 0 5 .5 .5 .5 0 0
grey polygon floor 0 0 12 0 0 0  6 0 0  6 5 0  0 5 0
)";

TEST(Obstructors, EachCellHasAFillRayOfItsOwn) {
    const Scene scene = Build(kLights);
    std::vector<std::string> warnings;
    Rng rng(1);
    const auto sources = FindLightSources(
        scene, [&](const std::string& m) { warnings.push_back(m); }, false, rng);
    std::set<ObstructorLayout::Kind> kinds;
    for (const LightSource& src : sources) {
        const ObstructorLayout layout = MakeObstructorLayout(src, scene.cubeOrigin, scene.cubeSize);
        const std::string& name = scene.surfaces[static_cast<size_t>(src.surface)].name;
        kinds.insert(layout.kind);
        SCOPED_TRACE(name);
        // What is not a number has no cell: for a distant source the origin
        // (its cells are places on a plane), for the others the direction.
        const double nan = std::numeric_limits<double>::quiet_NaN();
        if (layout.kind == ObstructorLayout::Kind::Distant) {
            EXPECT_EQ(layout.Cell({nan, nan, nan}, {0, 0, 1}), -1);
        } else if (layout.kind != ObstructorLayout::Kind::None) {
            EXPECT_EQ(layout.Cell({1, 1, 1}, {nan, nan, nan}), -1);
        }
        if (name == "spotlamp" || name == "halobulb" || name == "sky") {
            // Spotlights, glows with a radius and skies are not cached.
            EXPECT_EQ(layout.kind, ObstructorLayout::Kind::None);
            EXPECT_EQ(layout.CellCount(), 0);
            continue;
        }
        if (name == "sun") {
            ASSERT_EQ(layout.kind, ObstructorLayout::Kind::Distant);
            EXPECT_EQ(layout.CellCount(), 4 * kObstructorResolution * kObstructorResolution);
            // The cell comes from the ray's origin, carried along the source
            // direction to the plane the fill rays start from: any point
            // along a fill ray past the plane lands in that ray's cell...
            ExpectEveryCellItsOwnRay(layout, src, 2.0);
            // ...and a point on the source's side of the plane in none.
            for (int c = 0; c < layout.CellCount(); ++c) {
                const ObstructorFillRay fill = MakeObstructorFillRay(layout, src, c);
                EXPECT_EQ(layout.Cell(fill.org - fill.dir * 0.5, -fill.dir), -1);
            }
            continue;
        }
        const bool flat = name == "panel";
        ASSERT_EQ(layout.kind,
                  flat ? ObstructorLayout::Kind::Flat : ObstructorLayout::Kind::Radial);
        EXPECT_EQ(layout.CellCount(),
                  (flat ? 3 : 6) * kObstructorResolution * kObstructorResolution);
        // Directions only: the cell is the same wherever along the ray.
        ExpectEveryCellItsOwnRay(layout, src, 0.0);
        ExpectEveryCellItsOwnRay(layout, src, -7.5);
        if (flat) {
            // From behind a flat source, no cell.
            EXPECT_EQ(layout.Cell({1.5, 1.5, 4}, {0, 0, -1}), -1);
            EXPECT_GE(layout.Cell({1.5, 1.5, 1}, {0, 0, 1}), 0);
        }
    }
    EXPECT_EQ(kinds.size(), 4u);
}

TEST(Obstructors, OnlyOpaqueMaterialsAreReliableBlockers) {
    const Scene scene = Build(R"(
void plastic p 0 0 5 .5 .5 .5 0 0
void metal m 0 0 5 .5 .5 .5 0 0
void light l 0 0 3 1 1 1
void glass g 0 0 3 .9 .9 .9
void trans t 0 0 7 .5 .5 .5 0 0 .5 .5
void mirror mi 0 0 3 .9 .9 .9
void brightfunc b 2 1 . 0 0
b plastic patterned 0 0 5 .5 .5 .5 0 0
void mixfunc mx 4 p g .5 . 0 0
void plastic cutp 0 0 5 .5 .5 .5 0 0
void antimatter cut 1 cutp 0 0
p polygon a 0 0 9 0 0 0 1 0 0 0 1 0
m sphere b1 0 0 4 0 0 2 .5
l polygon c 0 0 9 0 0 1 1 0 1 0 1 1
g polygon d 0 0 9 0 0 2 1 0 2 0 1 2
t polygon e 0 0 9 0 0 3 1 0 3 0 1 3
mi polygon f 0 0 9 0 0 4 1 0 4 0 1 4
patterned polygon h 0 0 9 0 0 5 1 0 5 0 1 5
mx polygon i 0 0 9 0 0 6 1 0 6 0 1 6
cutp polygon j 0 0 9 0 0 7 1 0 7 0 1 7
cut sphere k 0 0 4 .2 .2 7 .1
)");
    std::map<std::string, bool> reliable;
    for (const Surface& s : scene.surfaces) reliable[s.name] = IsReliableBlocker(scene, s);
    EXPECT_TRUE(reliable["a"]);
    EXPECT_TRUE(reliable["b1"]);
    EXPECT_TRUE(reliable["c"]);   // a light blocks the other sources
    EXPECT_TRUE(reliable["h"]);   // a pattern does not change what it blocks
    EXPECT_FALSE(reliable["d"]);  // glass
    EXPECT_FALSE(reliable["e"]);  // trans
    EXPECT_FALSE(reliable["f"]);  // mirror (it can relay a virtual source)
    EXPECT_FALSE(reliable["i"]);  // a mixture may be a hole
    EXPECT_FALSE(reliable["j"]);  // antimatter may clip it
}

}  // namespace
}  // namespace rt
