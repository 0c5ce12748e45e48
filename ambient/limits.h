// SPDX-License-Identifier: MIT
//
// Record radius limits from -ar and the scene size (Radiance's setambres(),
// radiance-notes.md §4.2), and the one absolute length of the lookup.
#pragma once

#include "core/conventions.h"

namespace rt {

struct AmbientLimits {
    double minRadius = 0;  // scene units
    double maxRadius = 0;
    /// Added to minRadius·a in the "behind" test (Radiance's 0.001 scene units).
    double behindMargin = 0.001;

    /// minRadius·a + behindMargin for -aa a: how far a record's plane may lie
    /// in front of a query (the "behind" test), and the distance within which
    /// the leak test's corral ignores occluders (Radiance's minarad·a + 0.001).
    double BehindTolerance(double accuracy) const { return minRadius * accuracy + behindMargin; }

    /// `resolution` is -ar, `cubeSize` oconv's cube size (Scene::cubeSize).
    /// `toleranceScale` (Scene::ToleranceScale(), 1 for scenes of unit size
    /// and up) shrinks Radiance's absolute lengths with smaller scenes.
    static AmbientLimits FromResolution(int resolution, double cubeSize,
                                        double toleranceScale = 1.0) {
        AmbientLimits l;
        if (resolution > 0) {
            l.minRadius = cubeSize / resolution;
            l.maxRadius = 64.0 * l.minRadius;
            if (l.maxRadius > 0.2 * cubeSize) l.maxRadius = 0.2 * cubeSize;
        } else {
            l.minRadius = 0;
            l.maxRadius = 0.2 * cubeSize;
        }
        const double tiny = kFtiny * toleranceScale;
        if (l.minRadius <= tiny) l.minRadius = 10.0 * tiny;
        if (l.maxRadius <= l.minRadius) l.maxRadius = 64.0 * l.minRadius;
        l.behindMargin = 0.001 * toleranceScale;
        return l;
    }
};

}  // namespace rt
