// SPDX-License-Identifier: MIT
//
// Noise3 follows Perlin's published reference implementation of Improved
// Noise (SIGGRAPH 2002) with its permutation table. FractalNoise3 follows the
// order of operations of radiance-functions.md §9.9.1; the test values there
// (and tests/data/cal/noise.tsv, made with real rtrace) need that exact order.
#include "cal/noise.h"

#include <array>
#include <cmath>
#include <cstdint>

namespace rt::cal {
namespace {

constexpr std::array<std::uint8_t, 256> kPermutation = {
    151, 160, 137, 91,  90,  15,  131, 13,  201, 95,  96,  53,  194, 233, 7,   225, 140, 36,  103,
    30,  69,  142, 8,   99,  37,  240, 21,  10,  23,  190, 6,   148, 247, 120, 234, 75,  0,   26,
    197, 62,  94,  252, 219, 203, 117, 35,  11,  32,  57,  177, 33,  88,  237, 149, 56,  87,  174,
    20,  125, 136, 171, 168, 68,  175, 74,  165, 71,  134, 139, 48,  27,  166, 77,  146, 158, 231,
    83,  111, 229, 122, 60,  211, 133, 230, 220, 105, 92,  41,  55,  46,  245, 40,  244, 102, 143,
    54,  65,  25,  63,  161, 1,   216, 80,  73,  209, 76,  132, 187, 208, 89,  18,  169, 200, 196,
    135, 130, 116, 188, 159, 86,  164, 100, 109, 198, 173, 186, 3,   64,  52,  217, 226, 250, 124,
    123, 5,   202, 38,  147, 118, 126, 255, 82,  85,  212, 207, 206, 59,  227, 47,  16,  58,  17,
    182, 189, 28,  42,  223, 183, 170, 213, 119, 248, 152, 2,   44,  154, 163, 70,  221, 153, 101,
    155, 167, 43,  172, 9,   129, 22,  39,  253, 19,  98,  108, 110, 79,  113, 224, 232, 178, 185,
    112, 104, 218, 246, 97,  228, 251, 34,  242, 193, 238, 210, 144, 12,  191, 179, 162, 241, 81,
    51,  145, 235, 249, 14,  239, 107, 49,  192, 214, 31,  181, 199, 106, 157, 184, 84,  204, 176,
    115, 121, 50,  45,  127, 4,   150, 254, 138, 236, 205, 93,  222, 114, 67,  29,  24,  72,  243,
    141, 128, 195, 78,  66,  215, 61,  156, 180};

// The table repeated once, so that p[i + 1] and p[p[i] + j] need no wrapping.
int Perm(int i) { return kPermutation[static_cast<std::size_t>(i & 255)]; }

double Fade(double t) { return t * t * t * (t * (t * 6 - 15) + 10); }
double Lerp(double t, double a, double b) { return a + t * (b - a); }

// One of 12 gradient directions (edges of a cube) chosen by the low 4 hash bits.
double Grad(int hash, double x, double y, double z) {
    const int h = hash & 15;
    const double u = h < 8 ? x : y;
    const double v = h < 4 ? y : (h == 12 || h == 14) ? x : z;
    return ((h & 1) == 0 ? u : -u) + ((h & 2) == 0 ? v : -v);
}

// Wraps the cell index into [0, 255] without the undefined behaviour of
// converting a huge double to int.
int Cell(double floored) {
    const double wrapped = floored - 256.0 * std::floor(floored / 256.0);
    const int cell = static_cast<int>(wrapped);
    return cell & 255;
}

constexpr double kGradientStep = 0.0005;

}  // namespace

double Noise3(double x, double y, double z) {
    if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z)) return 0.0;
    const double fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
    const int X = Cell(fx), Y = Cell(fy), Z = Cell(fz);
    x -= fx;
    y -= fy;
    z -= fz;
    const double u = Fade(x), v = Fade(y), w = Fade(z);
    const int A = Perm(X) + Y, AA = Perm(A) + Z, AB = Perm(A + 1) + Z;
    const int B = Perm(X + 1) + Y, BA = Perm(B) + Z, BB = Perm(B + 1) + Z;
    return Lerp(
        w,
        Lerp(v, Lerp(u, Grad(Perm(AA), x, y, z), Grad(Perm(BA), x - 1, y, z)),
             Lerp(u, Grad(Perm(AB), x, y - 1, z), Grad(Perm(BB), x - 1, y - 1, z))),
        Lerp(
            v, Lerp(u, Grad(Perm(AA + 1), x, y, z - 1), Grad(Perm(BA + 1), x - 1, y, z - 1)),
            Lerp(u, Grad(Perm(AB + 1), x, y - 1, z - 1), Grad(Perm(BB + 1), x - 1, y - 1, z - 1))));
}

double Noise3X(double x, double y, double z) {
    return (Noise3(x, y, z) - Noise3(x - kGradientStep, y, z)) / kGradientStep;
}
double Noise3Y(double x, double y, double z) {
    return (Noise3(x, y, z) - Noise3(x, y - kGradientStep, z)) / kGradientStep;
}
double Noise3Z(double x, double y, double z) {
    return (Noise3(x, y, z) - Noise3(x, y, z - kGradientStep)) / kGradientStep;
}

namespace {

// Integer hash to [-1, 1) with 64-bit wrapping arithmetic (unsigned, so the
// wrap is defined), as C's `long` on the 64-bit machines Radiance runs on.
double FractalRandom(std::int64_t seed) {
    const std::uint64_t s0 = static_cast<std::uint64_t>(seed);
    const std::uint64_t s = (s0 << 13) ^ s0;
    const std::uint64_t h = (s * (s * s * 15731u + 789221u) + 1376312589u) & 0x7fffffffu;
    return 1.0 - static_cast<double>(h) / 1073741824.0;
}

double FractalRandom3(std::int64_t x, std::int64_t y, std::int64_t z) {
    const auto u = [](std::int64_t v) { return static_cast<std::uint64_t>(v); };
    return FractalRandom(static_cast<std::int64_t>(17u * u(x) + 23u * u(y) + 29u * u(z)));
}

// Grid coordinate of p: truncation toward zero, saturated so that points far
// outside any sensible scene cannot overflow.
std::int64_t GridCoordinate(double v) {
    constexpr double kLimit = 4.0e15;
    if (!(v > -kLimit)) return static_cast<std::int64_t>(-kLimit);
    if (!(v < kLimit)) return static_cast<std::int64_t>(kLimit);
    return static_cast<std::int64_t>(v);
}

}  // namespace

double FractalNoise3(double x, double y, double z) {
    constexpr double kEpsilon = 0.0005;
    const double p[3] = {x, y, z};
    std::int64_t s = 2000;  // grid cells per unit length, 1/kEpsilon
    std::int64_t t[3], v[3], beg[3];
    for (int i = 0; i < 3; ++i) {
        t[i] = GridCoordinate(static_cast<double>(s) * p[i]);
        beg[i] = GridCoordinate(static_cast<double>(s) * std::floor(p[i]));
    }
    double corner[8];
    for (int j = 0; j < 8; ++j) {
        for (int i = 0; i < 3; ++i) v[i] = beg[i] + ((j & (1 << i)) ? s : 0);
        corner[j] = FractalRandom3(v[0], v[1], v[2]);
    }
    for (;;) {
        double average = 0.0;
        for (double c : corner) average += c;
        average *= 0.125;
        s >>= 1;
        if (s == 0) return average;
        const double weight = static_cast<double>(s) * kEpsilon;
        // The sub-cube containing the point, one bit per axis.
        int branch = 0;
        for (int i = 0; i < 3; ++i) {
            v[i] = beg[i] + s;
            if (t[i] > v[i]) branch |= 1 << i;
        }
        // Centre of the cube: the corner of the sub-cube opposite `branch`.
        corner[~branch & 7] = average + weight * FractalRandom3(v[0], v[1], v[2]);
        // Face centres: the average of the face's 4 corners plus displacement.
        for (int i = 0; i < 3; ++i) {
            v[i] += (branch & (1 << i)) ? s : -s;
            double face = 0.0;
            for (int j = 0; j < 8; ++j) {
                if (~(j ^ branch) & (1 << i)) face += corner[j];
            }
            corner[~(branch ^ (1 << i)) & 7] =
                0.25 * face + weight * FractalRandom3(v[0], v[1], v[2]);
            v[i] = beg[i] + s;
        }
        // Edge midpoints: the average of the edge's 2 ends plus displacement.
        for (int i = 0; i < 3; ++i) {
            const int j1 = (i + 1) % 3, j2 = (i + 2) % 3;
            v[j1] += (branch & (1 << j1)) ? s : -s;
            v[j2] += (branch & (1 << j2)) ? s : -s;
            const double edge = 0.5 * (corner[branch & ~(1 << i)] + corner[branch | (1 << i)]);
            corner[branch ^ (1 << i)] = edge + weight * FractalRandom3(v[0], v[1], v[2]);
            v[j1] = beg[j1] + s;
            v[j2] = beg[j2] + s;
        }
        for (int i = 0; i < 3; ++i) {
            if (branch & (1 << i)) beg[i] += s;
        }
    }
}

}  // namespace rt::cal
