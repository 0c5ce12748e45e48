// SPDX-License-Identifier: MIT
//
// Fuzz target: arbitrary bytes as a .rad stream through ReadSceneObjects (with
// `!command` lines disabled) and BuildScene. rt::Error is the expected way to
// reject input; any other exception, a crash, UB or a hang is a finding.
#include <sstream>
#include <string>

#include "core/error.h"
#include "raycore/hull.h"
#include "scene/loader.h"
#include "tests/fuzz/fuzz_entry.h"

extern "C" int RT_FUZZ_ENTRY(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    std::istringstream in(text);
    rt::SceneLoadOptions options;
    options.runCommands = false;
    const rt::WarningSink warn = [](const std::string&) {};
    try {
        const std::vector<rt::SceneObject> objects =
            rt::ReadSceneObjects(in, "fuzz.rad", options, warn);
        const rt::Scene scene = rt::BuildScene(objects, warn);
        // The ray core's scan for bounding polygons runs on every scene it is
        // given (Embree itself is left out: a device per input is too slow).
        const rt::BoundingPolygons bounds =
            rt::FindBoundingPolygons(scene, 0.01 * scene.distanceTolerance);
        static_cast<void>(bounds.Inside(scene.cubeOrigin));
    } catch (const rt::Error&) {
        // Rejected input: expected.
    }
    return 0;
}
