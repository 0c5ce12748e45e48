// SPDX-License-Identifier: MIT
//
// Radiance's octree files as scene input (radiance-notes.md §2.1-2.2, written
// by oconv's writeoct.c, read by readoct.c): the information header, the
// cube, the names of the scene files or, for a frozen octree (`oconv -f`),
// the scene itself. lazyrad builds its own acceleration structure, so the
// tree is only checked (every leaf names an existing surface), not kept.
#pragma once

#include <istream>
#include <string>
#include <vector>

#include "core/function_ref.h"
#include "core/vecmath.h"
#include "scene/scene.h"

namespace rt {

struct OctreeFile {
    /// Header lines between "#?RADIANCE" and the blank line, without the
    /// FORMAT line: what rtrace copies into its own output header.
    std::vector<std::string> headerLines;
    Vec3 cubeOrigin;
    double cubeSize = 0;
    /// Scene files to re-read (relative to the current directory); empty for
    /// a frozen octree.
    std::vector<std::string> sceneFiles;
    long long objectCount = 0;
    /// Every object index that a leaf of the tree lists, ascending, unique.
    std::vector<long long> leafObjects;
    /// A frozen octree's objects, in order; locations are byte offsets.
    std::vector<SceneObject> objects;
    bool frozen() const { return sceneFiles.empty(); }
};

/// True if `in` starts with a Radiance header whose FORMAT is Radiance_octree.
/// Leaves the stream at its start.
bool LooksLikeOctree(std::istream& in);

/// Reads a whole octree file and nothing after it (rays may follow it on
/// standard input). `name` is used in error locations. With `firstLineRead`
/// the caller has already consumed the "#?RADIANCE" line. Throws rt::Error
/// "name: byte N: ..." for anything malformed or truncated.
OctreeFile ReadOctree(std::istream& in, const std::string& name, bool firstLineRead = false);

/// The same, but a frozen octree's objects are handed to `onObject` one by
/// one as they are read (it may take their strings) and not kept, and the
/// leaves are checked against them here (CheckOctreeObjects' "modifier in
/// tree"): a large scene's objects are never all held at once. `onCount`
/// first hears how many objects the octree says it holds, frozen or not (a
/// claim, checked only once they have been read).
OctreeFile ReadOctree(std::istream& in, const std::string& name, bool firstLineRead,
                      FunctionRef<void(SceneObject&)> onObject,
                      FunctionRef<void(long long)> onCount = [](long long) {});

/// What the stale-octree checks need of each object, noted as the objects go
/// by (so that they need not be kept): whether it is a surface, its name.
struct OctreeObjectTally {
    std::vector<bool> surface;
    std::vector<std::string> names;
    void Add(const SceneObject& object);
};

/// Radiance's stale-octree checks, once the scene files of a non-frozen octree
/// have been read: the same object count, and leaves that list only
/// surfaces. Throws rt::Error naming the octree.
void CheckOctreeObjects(const OctreeFile& octree, const OctreeObjectTally& objects,
                        const std::string& name);
/// The same for objects kept.
void CheckOctreeObjects(const OctreeFile& octree, const std::vector<SceneObject>& objects,
                        const std::string& name);

}  // namespace rt
