// SPDX-License-Identifier: MIT
//
// Shading options: rtrace's -d*, -s*, -l*, -m*, -bv, -i/-I, -u with Radiance
// 5.4a's defaults (radiance-notes.md §1.2). Plain values; rtrace fills them.
#pragma once

#include "core/rgb.h"

namespace rt {

struct DirectOptions {
    double threshold = 0.03;    // -dt
    double certainty = 0.75;    // -dc
    double jitter = 0.0;        // -dj
    double sampling = 0.2;      // -ds (source subdivision ratio; 0 = one sample per source)
    int relays = 2;             // -dr: reflections of light sources in planar mirrors
    int pretest = 512;          // -dp (parsed; lazyrad needs no visibility pretest)
    bool sourcesVisible = true; // -dv
};

struct SpecularOptions {
    double sampling = 1.0;      // -ss
    double threshold = 0.15;    // -st
};

struct LimitOptions {
    int reflections = -10;      // -lr (<= 0: Russian roulette, |lr| caps the depth)
    double weight = 2e-3;       // -lw
};

/// What a ray travels through (Radiance's cext and albedo): the global
/// medium of -me and -ma, or a dielectric's inside.
struct Medium {
    Rgb extinction;  // per unit length, per channel
    Rgb albedo;      // the share of the extinction that is scattering
};

/// Global participating medium (-me -ma -mg -ms): -me and -ma make every
/// primary ray's Medium; -mg and -ms only matter for the in-scattering of
/// mist's light sources, which lazyrad does not load (Radiance lists no
/// sources for the global medium).
struct MediumOptions {
    Rgb extinction;
    Rgb albedo;
    double eccentricity = 0;
    double samplingDistance = 0;
};

enum class IrradianceMode {
    Off,
    AtHit,       // -i: first non-transparent, non-light surface shaded as Lambertian pi
    Immediate,   // -I: input origin/direction are a measurement point and normal
};

struct ShadingOptions {
    DirectOptions direct;
    SpecularOptions specular;
    LimitOptions limits;
    MediumOptions medium;
    bool backfaceVisible = true;        // -bv
    IrradianceMode irradiance = IrradianceMode::Off;
    bool uncorrelated = true;           // -u: every ray its own random stream (false: one
                                        // stream for all rays, correlated sampling)
    unsigned long long seed = 0;        // base seed (-seed); runs with equal seeds are identical
};

}  // namespace rt
