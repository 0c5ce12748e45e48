// SPDX-License-Identifier: MIT
//
// Ambient (indirect) calculation options, rtrace's -a* family with Radiance
// 5.4a's defaults (radiance-notes.md §1.2).
#pragma once

#include <string>
#include <vector>

#include "core/rgb.h"

namespace rt {

/// The most divisions one hemisphere may have, and so the largest -ad the front
/// end accepts (above it: a one-line error, not a silent clamp). Each division
/// holds 48 bytes while its hemisphere is sampled, and a hemisphere's samples
/// nest hemispheres of at most half its weight, so one thread holds at most
/// about 2 × 48 B × 2^22 = 400 MB of divisions. Radiance has no limit: it
/// allocates ad·wt samples of 40 bytes and fails with "out of memory in
/// samp_hemi" only when malloc does.
inline constexpr int kMaxAmbientDivisions = 1 << 22;

/// -ah (lazyrad's own): the methods that make new records. Radiance 5's
/// Hessian records (elliptical radii, occlusion-aware gradients) are half as
/// many as the classic split-sphere ones where queries are dense; the classic
/// stratified hemisphere is the less noisy where a sensor's own first-level
/// record decides its value (README, "Record methods"). Mixed is the
/// default: the lowest error x time on the shared jobs at Radiance's default
/// settings and a daylight tool's; the Hessian records alone are three times
/// less accurate in the daylit rooms.
enum class RecordMethods {
    Classic,  // -ah-: classic records at every level
    Hessian,  // -ah+: Hessian records at every level
    Mixed,    // -ahm, the default: classic first-level records, Hessian deeper ones
};

struct AmbientOptions {
    Rgb value;                  // -av: ambient radiance used where bounces stop
    int valueWeight = 0;        // -aw: weight of -av in the running average
    int bounces = 0;            // -ab
    double accuracy = 0.1;      // -aa (0 = no cache)
    int resolution = 256;       // -ar
    int divisions = 1024;       // -ad
    int superSamples = 512;     // -as
    /// -ah (lazyrad's own): which method makes new records at each level
    /// (ambient/irradiance_cache.h RecordMethod).
    RecordMethods recordMethods = RecordMethods::Mixed;
    std::string file;           // -af, empty for none
    /// -ae/-aE (exclude) or -ai/-aI (include) modifier names; the first use of
    /// the other kind restarts the list (Radiance's rule).
    std::vector<std::string> modifierList;
    bool listIsInclude = false;
};

}  // namespace rt
