// SPDX-License-Identifier: MIT
#include "scene/object_types.h"

#include <algorithm>
#include <array>

namespace rt {
namespace {

// In Radiance's internal order (the octree type codes), for easy comparison with otypes.h.
constexpr std::array<std::string_view, 53> kTypeNames = {
    "polygon",    "cone",       "sphere",     "texfunc",    "ring",      "cylinder",
    "instance",   "cup",        "bubble",     "tube",       "mesh",      "alias",
    "plastic",    "metal",      "glass",      "trans",      "dielectric", "plastic2",
    "metal2",     "trans2",     "interface",  "plasfunc",   "metfunc",   "brightfunc",
    "brightdata", "brighttext", "colorpict",  "glow",       "source",    "light",
    "illum",      "spotlight",  "mist",       "mirror",     "transfunc", "BRTDfunc",
    "BSDF",       "aBSDF",      "plasdata",   "metdata",    "transdata", "colorfunc",
    "antimatter", "colordata",  "colortext",  "texdata",    "mixfunc",   "mixdata",
    "mixtext",    "mixpict",    "prism1",     "prism2",     "ashik2"};

constexpr std::array<std::string_view, 11> kSurfaceNames = {
    "polygon", "cone", "sphere", "ring", "cylinder", "cup",
    "bubble",  "tube", "instance", "mesh", "source"};

constexpr std::array<std::string_view, 27> kTransformArgNames = {
    "texfunc",  "texdata",  "colorfunc", "brightfunc", "colordata", "brightdata",
    "colorpict", "plasfunc", "metfunc",   "transfunc",  "plasdata",  "metdata",
    "transdata", "BRTDfunc", "mixfunc",   "mixdata",    "mixpict",   "plastic2",
    "metal2",   "trans2",   "ashik2",    "prism1",     "prism2",    "BSDF",
    "aBSDF",    "instance", "mesh"};

template <std::size_t N>
bool Contains(const std::array<std::string_view, N>& names, std::string_view type) {
    return std::find(names.begin(), names.end(), type) != names.end();
}

}  // namespace

bool IsKnownObjectType(std::string_view type) { return Contains(kTypeNames, type); }
bool IsSurfaceObjectType(std::string_view type) { return Contains(kSurfaceNames, type); }
bool TakesTransformArgs(std::string_view type) { return Contains(kTransformArgNames, type); }
bool IsTextType(std::string_view type) {
    return type == "colortext" || type == "brighttext" || type == "mixtext";
}

}  // namespace rt
