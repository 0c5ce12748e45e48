// SPDX-License-Identifier: MIT
//
// Ambient (indirect) calculation options, rtrace's -a* family with Radiance
// 5.4a's defaults (radiance-notes.md §1.2).
#pragma once

#include <string>
#include <vector>

#include "core/rgb.h"

namespace rt {

struct AmbientOptions {
    Rgb value;                  // -av: ambient radiance used where bounces stop
    int valueWeight = 0;        // -aw: weight of -av in the running average
    int bounces = 0;            // -ab
    double accuracy = 0.1;      // -aa (0 = no cache)
    int resolution = 256;       // -ar
    int divisions = 1024;       // -ad
    int superSamples = 512;     // -as
    std::string file;           // -af, empty for none
    /// -ae/-aE (exclude) or -ai/-aI (include) modifier names; the first use of
    /// the other kind restarts the list (Radiance's rule).
    std::vector<std::string> modifierList;
    bool listIsInclude = false;
};

}  // namespace rt
