// SPDX-License-Identifier: MIT
//
// Everything rtrace's -o letters can print about one evaluated ray
// (radiance-notes.md §1.6): Radiance's RAY fields that reach the output.
#pragma once

#include <cstdint>
#include <string_view>

#include "core/conventions.h"
#include "core/rgb.h"
#include "core/vecmath.h"

namespace rt {

struct RayResult {
    Vec3 origin;                // -oo
    Vec3 direction;             // -od, unit
    Rgb value;                  // -ov: radiance (irradiance with -i/-I)
    Rgb mirrored;               // -or: part due to pure specular reflection (mcol)
    double mirrorLength = kFhuge;      // -oR (rmt)
    double unmirroredLength = kFhuge;  // -oX (rxt)
    double firstLength = kFhuge;       // -oL (rot); kFhuge on a miss
    Vec3 point;                 // -op: hit point; the origin on a miss
    Vec3 normal;                // -on: raynormal(), textures included, as shading left it; 0 if none
    Vec3 geometricNormal;       // -oN: unperturbed normal as the surface defines it; 0 if none
    double weight = 1;          // -ow
    Rgb coefficient{1, 1, 1};   // -oW: product of coefficients up the ray tree
    Rgb contribution;           // -oV: value ⊗ coefficient
    double u = 0, v = 0;        // -oc: local (u,v) coordinates: a mesh's, 0 elsewhere
    std::string_view surfaceName = "*";   // -os: hit surface or "*"
    std::string_view modifierName = "*";  // -om: immediate modifier, "void", or "*"
    std::string_view materialName = "*";  // -oM: resolved material, "void", or "*"
    int depth = 0;              // ray-tree depth (trace output indentation)

    /// How the first surface this ray shaded got its indirect light (for
    /// pictures of the cache; rtrace prints none of this).
    enum class AmbientOutcome : std::uint8_t {
        None,          // no indirect calculation there (-ab 0, excluded, miss, light)
        Interpolated,  // from two or more cache records
        Extrapolated,  // from a single record and its gradients
        Computed,      // a new hemisphere was sampled (a record made, or -aa 0)
        Fallback,      // the -av/-aw ambient value
    };
    AmbientOutcome ambientOutcome = AmbientOutcome::None;
    /// Indirect irradiance π·Ē at that surface (W/m²), zero if none.
    Rgb indirectIrradiance;

    /// Radiance's raydistance() (-ol): the mirror length when the mirrored part
    /// dominates the value, else the unmirrored length.
    double EffectiveLength() const {
        return Bright(mirrored) > 0.5 * Bright(value) ? mirrorLength : unmirroredLength;
    }
};

}  // namespace rt
