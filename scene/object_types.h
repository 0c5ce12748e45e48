// SPDX-License-Identifier: MIT
//
// Radiance's table of primitive type names (otypes.h / otypes.c): which words
// are types at all, which are surfaces and which modifiers take function-file
// arguments (xform appends its transform to those). Used by the reader, the
// scene builder and the xform tool.
#pragma once

#include <string_view>

namespace rt {

/// One of Radiance's 53 built-in type names (radiance-notes.md §2.6), case-sensitive.
bool IsKnownObjectType(std::string_view type);
/// polygon, cone, sphere, ring, cylinder, cup, bubble, tube, instance, mesh, source.
bool IsSurfaceObjectType(std::string_view type);
/// Types whose string arguments end in `funcfile [transform]` (hasfunc() in Radiance),
/// plus instance and mesh: xform appends its own transform to their strings.
bool TakesTransformArgs(std::string_view type);
/// colortext, brighttext, mixtext: vectors in the real arguments.
bool IsTextType(std::string_view type);

}  // namespace rt
