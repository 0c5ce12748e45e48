// SPDX-License-Identifier: MIT
//
// rtrace's ray quantities as function-language channels (radiance-functions.md
// §10.3): channel n is bound to the global name kRayVariableNames[n - 1], e.g.
// Dx = $1. A shading ChannelSource returns these, in pattern space.
#pragma once

#include <array>

namespace rt::cal {

// clang-format off
enum RayChannel : int {
    kDx = 1, kDy, kDz,     // ray direction (towards the surface), unit length
    kNx, kNy, kNz,         // geometric normal, not flipped for back faces
    kPx, kPy, kPz,         // hit point; 0 0 0 for a ray that hit nothing
    kT,                    // total path length from the eye × S
    kRdot,                 // cosine between -D and N in [-1, 1]
    kS,                    // world-to-pattern scale factor
    kTx, kTy, kTz,         // world origin in pattern space
    kIx, kIy, kIz,         // world x unit vector in pattern space
    kJx, kJy, kJz,         // world y unit vector
    kKx, kKy, kKz,         // world z unit vector
    kTs,                   // length of this shadow-ray segment chain × S
    kLu, kLv,              // mesh (u, v); 0 elsewhere
    // Set only while a BRDF material's function is evaluated (§10.4):
    kNxP, kNyP, kNzP,      // perturbed normal, in function space / S
    kRdotP,                // perturbed cosine, in [-1, 1]
    kCrP, kCgP, kCbP,      // material colour times pattern colour
    // Set only while a prism1/prism2 function is evaluated (m_direct.c):
    kDxA, kDyA, kDzA,      // unit direction to the source aimed at, in function space / S;
                           // 0 0 0 when the ray aims at none
};
// clang-format on

inline constexpr int kRayChannelCount = 27;
inline constexpr int kBrdfChannelCount = 34;
inline constexpr int kRedirectChannelCount = 37;

inline constexpr std::array<const char*, kRayChannelCount> kRayVariableNames = {
    "Dx", "Dy", "Dz", "Nx", "Ny", "Nz", "Px", "Py", "Pz", "T",  "Rdot", "S",  "Tx", "Ty",
    "Tz", "Ix", "Iy", "Iz", "Jx", "Jy", "Jz", "Kx", "Ky", "Kz", "Ts",   "Lu", "Lv"};

inline constexpr std::array<const char*, kBrdfChannelCount - kRayChannelCount> kBrdfVariableNames = {
    "NxP", "NyP", "NzP", "RdotP", "CrP", "CgP", "CbP"};

inline constexpr std::array<const char*, kRedirectChannelCount - kBrdfChannelCount>
    kRedirectVariableNames = {"DxA", "DyA", "DzA"};

}  // namespace rt::cal
