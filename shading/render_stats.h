// SPDX-License-Identifier: MIT
//
// Counters a Renderer keeps for rtrace's end-of-run report (-t): how many
// rays were traced, and (IrradianceCounters) what the ambient cache did.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "ambient/irradiance_cache.h"

namespace rt {

struct RenderStats : IrradianceCounters {
    std::uint64_t raysTraced = 0;        // every ray sent into the scene (not shadow rays)
    std::uint64_t shadowRays = 0;        // shadow rays actually tested
    std::uint64_t samplesObstructed = 0; // source samples the obstructor cache dropped
    std::uint64_t recordsLoaded = 0;     // records added from outside (ambient files)

    // Only measured when timing is on (Renderer::EnableTiming; rtrace -t),
    // because reading the clock costs time of its own. secondsSampling (in
    // IrradianceCounters) has the direct lighting at its samples' hits taken off.
    double secondsDirect = 0;    // direct lighting, shadow rays included; an estimate
                                 // from a sample of the calls (DirectLight::Add)

    /// Adds another thread's counts, level by level.
    RenderStats& operator+=(const RenderStats& other) {
        raysTraced += other.raysTraced;
        shadowRays += other.shadowRays;
        samplesObstructed += other.samplesObstructed;
        leakRays += other.leakRays;
        ambientLookups += other.ambientLookups;
        ambientHits += other.ambientHits;
        hemispheres += other.hemispheres;
        if (recordsPerLevel.size() < other.recordsPerLevel.size())
            recordsPerLevel.resize(other.recordsPerLevel.size());
        for (std::size_t i = 0; i < other.recordsPerLevel.size(); ++i)
            recordsPerLevel[i] += other.recordsPerLevel[i];
        recordsLoaded += other.recordsLoaded;
        secondsSampling += other.secondsSampling;
        secondsLookup += other.secondsLookup;
        secondsDirect += other.secondsDirect;
        return *this;
    }
};

}  // namespace rt
