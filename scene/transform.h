// SPDX-License-Identifier: MIT
//
// Radiance's transform arguments (`-t -rx -ry -rz -s -mx -my -mz -i`, xf.c) as
// a 4×4 row-vector matrix, and xform's per-type rewriting of a primitive under
// such a transform (xform.c). Used by the xform tool; reusable for instances.
//
//   auto [worldFromObject, next] = ParseTransformArgs({"-rz", "90", "-t", "1", "0", "0"});
//   Vec3 p = worldFromObject.Point({1, 0, 0});   // (1, 1, 0)
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "core/affine.h"
#include "core/vecmath.h"
#include "scene/scene.h"

namespace rt {

struct ParsedTransform {
    Transform transform;
    std::size_t next = 0;  // index of the first argument not consumed
};

/// Reads transform options from args[start] on, in order, exactly as xf.c does:
/// it stops at the first word that is not a transform option or whose values are
/// missing or not numeric (`-s 0` also stops), leaving that word at `next`.
ParsedTransform ParseTransformArgs(const std::vector<std::string>& args, std::size_t start = 0);

/// What xform applies to every primitive.
struct XformSettings {
    Transform transform;
    bool invert = false;             // -I: turn surfaces inside out
    std::string newModifier;         // -m: replaces every surface's modifier; empty keeps it
    std::string idPrefix;            // -n: surfaces become prefix.name; empty keeps names
    std::vector<std::string> transformArgs;  // the transform words, appended to function types
};

/// The primitive as xform writes it: geometry transformed, polygons reversed
/// under a mirror (or -I), radii and glow distances scaled, surface types
/// inverted by -I, the transform appended to the strings of pattern/texture/
/// instance types. Throws rt::Error (User) "loc: bad <type> \"name\"" when the
/// argument counts do not fit the type.
SceneObject TransformSceneObject(const SceneObject& object, const XformSettings& settings);

/// Radiance scene text for one primitive, preceded by a blank line, laid out
/// as Radiance's xform writes each type: reals as " %18.12g", polygons, cones,
/// cylinders, rings and text patterns three to a line, a spotlight's aim on a
/// line of its own, dielectric, interface and mist as "%12.6g".
std::string FormatSceneObject(const SceneObject& object);

}  // namespace rt
