// SPDX-License-Identifier: MIT
//
// Units and conventions used throughout lazyrad (style.md §4.7), and the
// numeric constants of Radiance (radiance-notes.md §0) that behaviour depends on.
//
// - Radiance in W·sr⁻¹·m⁻² per RGB channel, irradiance in W·m⁻².
// - Luminous efficacy 179 lm/W; luminance weights are Radiance's default
//   primaries (see Bright() in core/rgb.h).
// - Distances and ambient radii are in scene units.
// - Angles are radians inside the code, degrees only where Radiance's command
//   line or scene arguments use them (suffix `Degrees`).
// - Directions are unit vectors unless a name says otherwise; Vec3 is double.
// - A local shading frame has z along the normal; normals are flipped to face
//   the incoming ray by the material, not by the geometry.
// - Transforms are named aFromB.
#pragma once

namespace rt {

/// Radiance's generic epsilon (FTINY) in a double-precision build.
inline constexpr double kFtiny = 1e-6;
/// Rounding of positions, in double ulps of the largest coordinate in play:
/// distances below this many ulps of it cannot separate a surface from itself.
/// The floor of Scene::distanceTolerance, and the nearest a ray leaving a
/// surface may meet one crossing it (RayCore::Intersect's `leaving`).
inline constexpr double kCoordinateUlps = 1e3;
/// Radiance's "infinite" distance (FHUGE): reported as the length of a miss.
inline constexpr double kFhuge = 1e10;
inline constexpr double kPi = 3.14159265358979323846;
/// Lumens per watt of Radiance's equal-energy white.
inline constexpr double kWhiteEfficacy = 179.0;

}  // namespace rt
