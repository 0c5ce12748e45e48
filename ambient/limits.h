// SPDX-License-Identifier: MIT
//
// Record radius limits from -ar and the scene size (Radiance's setambres(),
// radiance-notes.md §4.2).
#pragma once

namespace rt {

struct AmbientLimits {
    double minRadius = 0;  // scene units
    double maxRadius = 0;

    /// `resolution` is -ar, `cubeSize` oconv's cube size (Scene::cubeSize).
    static AmbientLimits FromResolution(int resolution, double cubeSize) {
        constexpr double kFtinyLocal = 1e-6;
        AmbientLimits l;
        if (resolution > 0) {
            l.minRadius = cubeSize / resolution;
            l.maxRadius = 64.0 * l.minRadius;
            if (l.maxRadius > 0.2 * cubeSize) l.maxRadius = 0.2 * cubeSize;
        } else {
            l.minRadius = 0;
            l.maxRadius = 0.2 * cubeSize;
        }
        if (l.minRadius <= kFtinyLocal) l.minRadius = 10.0 * kFtinyLocal;
        if (l.maxRadius <= l.minRadius) l.maxRadius = 64.0 * l.minRadius;
        return l;
    }
};

}  // namespace rt
