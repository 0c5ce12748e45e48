// SPDX-License-Identifier: MIT
//
// Counters a Renderer keeps for rtrace's end-of-run report (-t): what the
// ambient cache did and how many rays were traced.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace rt {

struct RenderStats {
    std::uint64_t raysTraced = 0;        // every ray sent into the scene (not shadow rays)
    std::uint64_t shadowRays = 0;        // shadow rays actually tested
    std::uint64_t leakRays = 0;          // leak-test rays of cache lookups (ambient/leak.h)
    std::uint64_t ambientLookups = 0;    // cache queries
    std::uint64_t ambientHits = 0;       // queries answered by interpolation
    std::uint64_t hemispheres = 0;       // hemispheres sampled (records made or not)
    std::vector<std::uint64_t> recordsPerLevel;  // records created, by ambient level
    std::uint64_t recordsLoaded = 0;     // records added from outside (ambient files)

    // Only measured when timing is on (Renderer::EnableTiming; rtrace -t),
    // because reading the clock costs time of its own.
    double secondsSampling = 0;  // hemisphere sampling, less the direct lighting and
                                 // lookups done at its samples' hits
    double secondsLookup = 0;    // cache lookups (interpolation)
    double secondsDirect = 0;    // direct lighting, shadow rays included; an estimate
                                 // from a sample of the calls (Integrator::Direct)

    /// Adds another thread's counts, level by level.
    RenderStats& operator+=(const RenderStats& other) {
        raysTraced += other.raysTraced;
        shadowRays += other.shadowRays;
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
