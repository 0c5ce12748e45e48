// SPDX-License-Identifier: MIT
//
// The noise functions rtrace adds to the function language (Radiance's
// src/rt/noise3.c; radiance-functions.md §9.9.1). Pure functions of the point,
// safe to call from any thread.
#pragma once

namespace rt::cal {

/// Ken Perlin's "Improved Noise" (2002): range about [-1, 1], exactly 0 at
/// integer lattice points.
double Noise3(double x, double y, double z);

/// Backward differences of Noise3 with step 0.0005 along x, y and z: Radiance's
/// noise3x/y/z, the (approximate) gradient of Noise3.
double Noise3X(double x, double y, double z);
double Noise3Y(double x, double y, double z);
double Noise3Z(double x, double y, double z);

/// Radiance's fnoise3: fractal midpoint-displacement noise on a grid of 2000
/// cells per unit length, range about [-1, 1].
double FractalNoise3(double x, double y, double z);

}  // namespace rt::cal
