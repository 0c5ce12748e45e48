// SPDX-License-Identifier: MIT
//
// One ambient (irradiance cache) record, as Radiance's AMBVAL (ambient.h)
// minus its list bookkeeping: a plain value type. Classic records (Ward &
// Heckbert, radiance-notes.md §4.12) have radius[0] == radius[1]; records read
// from Radiance 5 files are anisotropic (§4.8).
#pragma once

#include <cstdint>
#include <ostream>

#include "core/rgb.h"
#include "core/vecmath.h"

namespace rt {

struct AmbientRecord {
    Vec3 position;              // sample point (scene units); double in memory, float on disk
    Vec3 normal;                // unit, unperturbed surface normal the hemisphere was taken around
    Vec3 uAxis;                 // unit tangent: axis of radius[0] and of the 2D gradients;
                                // v = Cross(normal, uAxis)
    Rgb value;                  // Ē = irradiance/π (W·sr⁻¹·m⁻²), cosine-weighted mean radiance
    double radius[2] = {0, 0};  // validity radii along u and v, 0 < radius[0] <= radius[1]
    double posGradient[2] = {0, 0};  // relative change of value per unit length along u, v
    double dirGradient[2] = {0, 0};  // relative change of value per radian of normal rotation
                                     // (used with Cross(normal, newNormal) projected on u, v)
    int level = 0;              // ambient depth of the ray that created it (0 = first bounce)
    double weight = 1;          // 0.5^level, or 1.25·ray weight for weak rays (§4.4)
    std::uint32_t corral = 0;   // Radiance 5 leak-sector bits; 0 for classic records

    bool operator==(const AmbientRecord&) const = default;

    Vec3 VAxis() const { return Cross(normal, uAxis); }
};

inline std::ostream& operator<<(std::ostream& os, const AmbientRecord& r) {
    return os << "AmbientRecord{pos " << r.position << " n " << r.normal << " u " << r.uAxis
              << " val " << r.value << " rad " << r.radius[0] << "," << r.radius[1] << " gpos "
              << r.posGradient[0] << "," << r.posGradient[1] << " gdir " << r.dirGradient[0]
              << "," << r.dirGradient[1] << " lvl " << r.level << " w " << r.weight
              << " corral " << r.corral << "}";
}

}  // namespace rt
