// SPDX-License-Identifier: MIT
//
// Shading options: rtrace's -d*, -s*, -l*, -m*, -bv, -i/-I, -u with Radiance
// 5.4a's defaults (radiance-notes.md §1.2). Plain values; rtrace fills them.
#pragma once

#include <array>

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
    /// Radiance's obstructor cache (shading/obstructors.h); no option turns
    /// it off in Radiance or rtrace, only tests do, to compare.
    bool obstructorCache = true;
};

struct SpecularOptions {
    double sampling = 1.0;      // -ss
    double threshold = 0.15;    // -st
};

struct LimitOptions {
    int reflections = -10;      // -lr (<= 0: Russian roulette, |lr| caps the depth)
    double weight = 2e-3;       // -lw
};

/// Radiance's MAXSLIST: the most light sources a medium scatters from.
inline constexpr int kMaxScatterSources = 32;

/// What a ray travels through (Radiance's cext, albedo, gecc and slights):
/// the global medium of -me, -ma and -mg, a dielectric's inside, or either
/// changed by the mist volumes the ray's path has entered.
struct Medium {
    Rgb extinction;  // per unit length, per channel
    Rgb albedo;      // the share of the extinction that is scattering
    double eccentricity = 0;  // Henyey–Greenstein g of the scattering
    /// The light sources whose light the medium scatters into rays (the
    /// lists of the mists entered), indices into ShadingSetup::sources; the
    /// first `scatterCount` entries count.
    std::array<int, kMaxScatterSources> scatterSources{};
    int scatterCount = 0;
};

/// Global participating medium (-me -ma -mg -ms): -me, -ma and -mg make
/// every primary ray's Medium; -ms spaces the samples of the light mist's
/// sources scatter into a ray (Radiance lists no sources for the global
/// medium, so -mg and -ms matter only inside mist).
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
    /// Input rays are only intersected, never shaded (Radiance's castonly:
    /// rtrace's output asks for nothing that needs a value, e.g. -oLps).
    bool castOnly = false;
};

}  // namespace rt
