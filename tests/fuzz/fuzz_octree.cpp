// SPDX-License-Identifier: MIT
//
// Fuzz target: arbitrary bytes as an octree file through ReadOctree, and for
// a frozen octree its objects through the stale checks and BuildScene; then
// the same bytes as LoadScene reads them, each object built as it is read. rt::Error is the expected way to reject input;
// any other exception, a crash, UB, a hang or memory out of proportion to the
// input is a finding.
#include <sstream>
#include <string>

#include "core/error.h"
#include "scene/loader.h"
#include "scene/octree.h"
#include "tests/fuzz/fuzz_entry.h"

extern "C" int RT_FUZZ_ENTRY(const std::uint8_t* data, std::size_t size) {
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    std::istringstream in(bytes);
    const rt::WarningSink warn = [](const std::string&) {};
    rt::SceneLoadOptions options;  // untrusted: no commands, no instance files
    options.runCommands = false;
    options.readFiles = false;
    try {
        if (!rt::LooksLikeOctree(in)) return 0;
        const rt::OctreeFile octree = rt::ReadOctree(in, "fuzz.oct");
        if (octree.frozen()) {
            rt::CheckOctreeObjects(octree, octree.objects, "fuzz.oct");
            static_cast<void>(rt::BuildScene(octree.objects, warn, options));
        }
    } catch (const rt::Error& e) {
        rt::fuzz::ExpectRefusal(e);
        // Rejected input: expected.
    }
    try {
        std::istringstream again(bytes);
        rt::SceneAssembler assembler(warn, options);
        const rt::OctreeFile octree = rt::ReadOctree(
            again, "fuzz.oct", false, [&assembler](rt::SceneObject& o) { assembler.Add(o); });
        if (octree.frozen()) static_cast<void>(assembler.Finish());
    } catch (const rt::Error& e) {
        rt::fuzz::ExpectRefusal(e);
    }
    return 0;
}
