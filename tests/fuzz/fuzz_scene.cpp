// SPDX-License-Identifier: MIT
//
// Fuzz target: arbitrary bytes as a .rad stream through ReadSceneObjects (with
// `!command` lines and instance files disabled) and BuildScene. rt::Error is the expected way to
// reject input; any other exception, a crash, UB or a hang is a finding.
#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include "core/error.h"
#include "raycore/hull.h"
#include "raycore/source_plane.h"
#include "scene/loader.h"
#include "tests/fuzz/fuzz_entry.h"

extern "C" int RT_FUZZ_ENTRY(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    std::istringstream in(text);
    rt::SceneLoadOptions options;
    options.runCommands = false;
    options.readFiles = false;
    const rt::WarningSink warn = [](const std::string&) {};
    try {
        const std::vector<rt::SceneObject> objects =
            rt::ReadSceneObjects(in, "fuzz.rad", options, warn);
        const rt::Scene scene = rt::BuildScene(objects, warn, options);
        // The ray core's scans for bounding polygons and for the light
        // sources' plane run on every scene it is given (Embree itself is left
        // out: a device per input is too slow).
        const rt::BoundingPolygons bounds =
            rt::FindBoundingPolygons(scene, 0.01 * scene.distanceTolerance);
        static_cast<void>(bounds.Inside(scene.cubeOrigin));
        std::vector<bool> leftOut(scene.surfaces.size(), false);
        for (int i : bounds.surfaces) leftOut[static_cast<std::size_t>(i)] = true;
        const double scale = std::max(1.0, 2 * scene.cubeSize + rt::MaxAbs(scene.cubeOrigin));
        if (const auto plane = rt::FindSourcePlane(scene, leftOut, scale)) {
            static_cast<void>(plane->Clears(scene.cubeOrigin, scene.cubeOrigin + plane->normal));
        }
    } catch (const rt::Error& e) {
        rt::fuzz::ExpectRefusal(e);
        // Rejected input: expected.
    }
    return 0;
}
