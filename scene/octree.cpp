// SPDX-License-Identifier: MIT
#include "scene/octree.h"

#include "core/error.h"
#include "scene/object_types.h"
#include "scene/radiance_binary.h"

namespace rt {
namespace {

// 283 + sizeof(OBJECT): the octree magic number (OCTMAGIC in Radiance).
constexpr long long kOctreeMagicBase = 283;

using detail::RadianceBinaryReader;

void ReadHeader(RadianceBinaryReader& r, OctreeFile& oct, bool firstLineRead) {
    oct.headerLines = detail::ReadRadianceHeader(r, firstLineRead, "Radiance_octree",
                                                 "not a Radiance octree", "truncated octree header")
                          .lines;
}

[[noreturn]] void ThrowModifierInTree(const std::string& name, long long index,
                                      const std::string& objectName) {
    ThrowUserError(name + ": modifier in tree; octree stale? (object " + std::to_string(index) +
                   ", \"" + objectName + "\")");
}

/// Everything up to a frozen octree's object section: header, cube, scene
/// file names, object count and the tree's leaves.
OctreeFile ReadUpToObjects(RadianceBinaryReader& r, bool firstLineRead, int& size) {
    OctreeFile oct;
    ReadHeader(r, oct, firstLineRead);
    const long long magicAt = r.offset();
    const long long magic = r.Int(2, "magic number");
    const long long objsize = magic - kOctreeMagicBase;
    if (objsize < 1 || objsize > detail::kMaxObjectSize) {
        r.Fail(magicAt, "bad octree magic number " + std::to_string(magic));
    }
    size = static_cast<int>(objsize);
    oct.cubeOrigin.x = detail::ReadCubeNumber(r, "cube origin");
    oct.cubeOrigin.y = detail::ReadCubeNumber(r, "cube origin");
    oct.cubeOrigin.z = detail::ReadCubeNumber(r, "cube origin");
    const long long sizeAt = r.offset();
    oct.cubeSize = detail::ReadCubeNumber(r, "cube size");
    if (!(oct.cubeSize > 0)) r.Fail(sizeAt, "bad cube size");
    for (std::string f = r.String("scene file name"); !f.empty(); f = r.String("scene file name")) {
        oct.sceneFiles.push_back(std::move(f));
    }
    const long long countAt = r.offset();
    oct.objectCount = r.Int(size, "object count");
    if (oct.objectCount < 0) r.Fail(countAt, "bad object count");
    for (const detail::LeafEntry& leaf : detail::ReadTreeLeaves(r, size, oct.objectCount)) {
        oct.leafObjects.push_back(leaf.index);
    }
    return oct;
}

void CheckObjectCount(const RadianceBinaryReader& r, const OctreeFile& oct, std::size_t read) {
    if (static_cast<long long>(read) != oct.objectCount) {
        r.Fail("the octree holds " + std::to_string(read) + " objects, its count says " +
               std::to_string(oct.objectCount));
    }
}

}  // namespace

bool LooksLikeOctree(std::istream& in) {
    const auto start = in.tellg();
    std::string line;
    bool octree = false;
    if (std::getline(in, line) && line == "#?RADIANCE") {
        // Header lines are short text; stop at the blank line or after a bound.
        for (int k = 0; k < 4096 && std::getline(in, line) && !line.empty(); ++k) {
            if (line.rfind("FORMAT=", 0) == 0) {
                octree = line == "FORMAT=Radiance_octree";
                break;
            }
        }
    }
    in.clear();
    in.seekg(start);
    return octree;
}

OctreeFile ReadOctree(std::istream& in, const std::string& name, bool firstLineRead) {
    RadianceBinaryReader r(in, name, firstLineRead ? sizeof("#?RADIANCE") : 0, "truncated octree");
    int size = 0;
    OctreeFile oct = ReadUpToObjects(r, firstLineRead, size);
    if (oct.frozen()) {
        detail::ReadObjectSection(r, size, oct.objectCount, oct.objects);
        CheckObjectCount(r, oct, oct.objects.size());
    }
    return oct;
}

OctreeFile ReadOctree(std::istream& in, const std::string& name, bool firstLineRead,
                      FunctionRef<void(SceneObject&)> onObject,
                      FunctionRef<void(long long)> onCount) {
    RadianceBinaryReader r(in, name, firstLineRead ? sizeof("#?RADIANCE") : 0, "truncated octree");
    int size = 0;
    OctreeFile oct = ReadUpToObjects(r, firstLineRead, size);
    onCount(oct.objectCount);
    if (!oct.frozen()) return oct;
    // Sized once from the count, and the names taken from the reader's own
    // list: growing and copying them cost a large model's start-up page
    // faults (docs/measured-choices.md).
    OctreeObjectTally tally;
    tally.surface.reserve(static_cast<std::size_t>(std::min(oct.objectCount, detail::kMaxReservedObjects)));
    tally.names = detail::ReadObjectSection(r, size, oct.objectCount, [&](SceneObject& o) {
        tally.surface.push_back(IsSurfaceObjectType(o.type));
        onObject(o);
    });
    CheckObjectCount(r, oct, tally.names.size());
    CheckOctreeObjects(oct, tally, name);
    return oct;
}

void OctreeObjectTally::Add(const SceneObject& object) {
    surface.push_back(IsSurfaceObjectType(object.type));
    names.push_back(object.name);
}

void CheckOctreeObjects(const OctreeFile& octree, const OctreeObjectTally& objects,
                        const std::string& name) {
    if (static_cast<long long>(objects.names.size()) != octree.objectCount) {
        ThrowUserError(name + ": bad object count; octree stale? (" +
                       std::to_string(objects.names.size()) + " objects in its scene files, " +
                       std::to_string(octree.objectCount) + " in the octree)");
    }
    for (const long long index : octree.leafObjects) {
        if (!objects.surface[static_cast<std::size_t>(index)]) {
            ThrowModifierInTree(name, index, objects.names[static_cast<std::size_t>(index)]);
        }
    }
}

void CheckOctreeObjects(const OctreeFile& octree, const std::vector<SceneObject>& objects,
                        const std::string& name) {
    OctreeObjectTally tally;
    for (const SceneObject& o : objects) tally.Add(o);
    CheckOctreeObjects(octree, tally, name);
}

}  // namespace rt
