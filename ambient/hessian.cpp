// SPDX-License-Identifier: MIT
//
// Radiance 5's hemisphere sampler, super-sampling, occlusion-aware Hessian,
// elliptical radii, gradients and corral (radiance-notes.md §4.5–4.7,
// Radiance 5.4 ambcomp.c), after Schwarzhaupt, Jensen & Jarosz (2012).
// Written from the formulas, not from that code.
#include "ambient/hessian.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "ambient/leak.h"
#include "ambient/ambient_options.h"
#include "core/check.h"
#include "core/conventions.h"

namespace rt {
namespace {

/// Radiance makes records with the coefficient AVGREFL = 0.5 and tests its
/// values scaled by it (bright(0.5·Ē) > FTINY).
constexpr double kAvgRefl = 0.5;
/// ns² = kMaxAmbientDivisions at most, whatever -ad·weight asks for.
constexpr int kMaxDivisionsPerAxis = 2048;
static_assert(kMaxDivisionsPerAxis * kMaxDivisionsPerAxis <= kMaxAmbientDivisions);
/// Super-sampling needs more than this many extra samples and more than this
/// many cells (Radiance's n > 8 and sampOK > MINADIV²).
constexpr int kMinSuperSamples = 9;
constexpr int kMinSuperSampleCells = kMinHessianDivisions * kMinHessianDivisions + 1;
/// Radiance re-draws a colliding first sample until it fits and never gives
/// up; a neighbour's exclusion cone (half-angle π/(4ns)) is too small to cover
/// a cell, so this bound only stops a trace callback that returns nonsense.
constexpr int kMaxRedraws = 64;

/// The six orders of the three axes, one picked at random by Radiance's
/// getperpendicular().
constexpr int kAxisOrders[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2},
                                   {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};

/// The disc radius scale that keeps lifted directions off the horizon.
constexpr double kDiscScale = 0.9999999999999;

/// Radiance's getperpendicular(n, randomize = 1): the azimuth of the frame is
/// random but not uniform (it leans toward the chosen axis), and Radiance 5
/// draws it for every hemisphere, even with -u-.
Vec3 RandomPerpendicular(const Vec3& n, Rng& rng) {
    Vec3 v;
    for (int i = 0; i < 3; ++i)
        v[i] = 0.5 - rng.Uniform();
    const int pick = std::min(5, static_cast<int>(6.0 * rng.Uniform()));
    const int* order = kAxisOrders[pick];
    for (int i = 2; i >= 0; --i) {
        if (std::fabs(n[order[i]]) < 0.6) {
            v[order[i]] = 1.0;
            break;
        }
    }
    // v has a unit component where |n| < 0.6 and the others within ±0.5, so
    // it is never parallel to n.
    return Normalize(Cross(v, n));
}

/// The cosine-weighted direction of square point ((j + xi1)/ns, (i + xi0)/ns),
/// given invNs = 1/ns (a multiplication where two divisions were, per ray).
Vec3 CellDirection(const Frame& frame, double invNs, int i, int j, double xi0, double xi1) {
    const DiscPoint p = SquareToDisc((j + xi1) * invNs, (i + xi0) * invNs);
    const double z = std::sqrt(std::max(0.0, 1.0 - p.x * p.x - p.y * p.y));
    return frame.u * p.x + frame.v * p.y + frame.n * z;
}

std::size_t Index(int ns, int i, int j) {
    return static_cast<std::size_t>(i) * static_cast<std::size_t>(ns) + static_cast<std::size_t>(j);
}

/// Radiance's ambcollision(): whether unit `dir` for cell (i, j) lies within
/// π/(4ns) of the hit direction of an already sampled neighbour. Coincident
/// directions would make the triangles between them degenerate. The first
/// pass samples the cells last first, so only the neighbours after (i, j) in
/// row-major order can have been sampled: (i, j+1) and the three of row i+1.
bool Collides(const HessianHemisphere& h, int i, int j, const Vec3& dir) {
    const double limit = kPi / (4.0 * h.ns);
    const double cosLimit = 1.0 - 0.5 * limit * limit;
    const double cosLimit2 = cosLimit * cosLimit;
    const auto near = [&](int ii, int jj) {
        const HessianCell& c = h.At(ii, jj);
        if (c.samples == 0)
            return false;
        // Dot >= cosLimit·|offset| (cosLimit > 0), squared to spare a sqrt.
        const double d = Dot(c.offset, dir);
        return d > 0 && d * d >= cosLimit2 * LengthSquared(c.offset);
    };
    if (j + 1 < h.ns && near(i, j + 1))
        return true;
    if (i + 1 < h.ns) {
        for (int jj = std::max(0, j - 1); jj <= std::min(h.ns - 1, j + 1); ++jj) {
            if (near(i + 1, jj))
                return true;
        }
    }
    return false;
}

/// Traces sample `n` (0 = first) of cell (i, j) along unit `dir` and folds it
/// into the cell; false when the ray failed (the cell keeps what it had).
bool SampleCell(HessianHemisphere& h, int i, int j, const Vec3& dir, int n, double farDistance,
                AmbientTraceRef trace) {
    ++h.raysTraced;
    const std::optional<AmbientSample> s = trace(dir);
    // A distance may be below Radiance's FTINY (a wall meeting the record's
    // surface at its edge) but never zero from a real trace.
    if (!s || !(s->distance > 0) || !IsFinite(s->radiance))
        return false;
    const Rgb radiance(std::max(s->radiance.r, 0.0), std::max(s->radiance.g, 0.0),
                       std::max(s->radiance.b, 0.0));
    HessianCell& c = h.cells[Index(h.ns, i, j)];
    c.inverseDistance = std::max(c.inverseDistance, 1.0 / s->distance);
    if (n == 0) {
        c.offset = dir * std::min(s->distance, farDistance);
        c.radiance = radiance;
        c.samples = 1;
    } else {
        // Radiance's (n·v + L)/(n + 1), written so a constant stays exact.
        c.radiance += (radiance - c.radiance) * (1.0 / (n + 1));
        ++c.samples;
    }
    return true;
}

}  // namespace

namespace detail {

std::vector<double> NeighbourContrast(const HessianHemisphere& h) {
    std::vector<double> bright(h.cells.size());
    for (std::size_t k = 0; k < bright.size(); ++k) bright[k] = Bright(h.cells[k].radiance);
    return NeighbourVariance(bright, h.ns, h.ns, /*wrap=*/false);
}

std::vector<int> AllotSuperSamples(const HessianHemisphere& h, int count, Rng& rng,
                                   const HemisphereOptions& options) {
    const std::vector<double> e = NeighbourContrast(h);
    // Every cell's neighbours are of the other colour of the checkerboard:
    // AllotCheckerboard's contract holds.
    const int cells = h.ns * h.ns;
    const int evenCells = (cells + 1) / 2;  // the colour of cell (0, 0)
    const auto cut = [&](int colour, int budget, double total) {
        if (!(options.contrastTarget > 0)) return budget;
        // The whole hemisphere's contrast and mean estimated from the other
        // colour's samples alone (this colour's priorities come from them
        // too), so no cell's count depends on a cell of its colour.
        const int colourCells = colour == 0 ? evenCells : cells - evenCells;
        double otherBright = 0;
        for (int i = 0; i < h.ns; ++i) {
            for (int j = (i + colour + 1) % 2; j < h.ns; j += 2) {
                otherBright += Bright(h.At(i, j).radiance);
            }
        }
        return SuperSamplesForContrast(budget, total * cells / colourCells, cells,
                                       otherBright / (cells - colourCells),
                                       options.contrastTarget, rng);
    };
    return AllotCheckerboard(e, h.ns, h.ns, count, rng, cut);
}

}  // namespace detail

namespace {

/// Radiance's ambsupersamp(): `count` extra samples shared out in one pass
/// over the cells in proportion to their contrast estimates, each cell's share
/// rounded at random; never more than `count` in total.
void SuperSample(HessianHemisphere& h, int count, const HemisphereOptions& options,
                 double farDistance, Rng& rng, AmbientTraceRef trace) {
    const std::vector<int> counts = detail::AllotSuperSamples(h, count, rng, options);
    const double invNs = 1.0 / h.ns;
    for (int i = 0; i < h.ns; ++i) {
        for (int j = 0; j < h.ns; ++j) {
            for (int n = 1; n <= counts[Index(h.ns, i, j)]; ++n) {
                const double xi0 = rng.Uniform();
                const double xi1 = rng.Uniform();
                const Vec3 dir = CellDirection(h.frame, invNs, i, j, xi0, xi1);
                if (!SampleCell(h, i, j, dir, n, farDistance, trace)) break;
                ++h.superSamples;
            }
        }
    }
}

/// Normalised brightness of each cell (see HessianEstimate); `radiometric`
/// receives whether Ē was bright enough for it.
std::vector<double> NormalisedBrightness(const HessianHemisphere& h, bool* radiometric) {
    std::vector<double> y(h.cells.size(), 1.0);
    const double b = Bright(h.value);
    // Radiance treats a hemisphere as black below an absolute brightness
    // (B·AVGREFL <= FTINY: no gradients, no corral bits), which makes the
    // answers depend on the unit of light: a near-black room lit by a lamp
    // of radiance 1 took other records than the same room lit at 1e10
    // (BrightSource.ScalesWithSourceRadiance). Here only a black hemisphere
    // (or one so dim that 0.99/b would overflow) is, and the normalised
    // values below depend on ratios alone.
    *radiometric = b >= std::numeric_limits<double>::min();
    // Otherwise Radiance's Y = bright(v)·B + 1 differs from 1 by under 1e-12.
    if (*radiometric) {
        const double scale = 0.99 / b;
        for (std::size_t k = 0; k < y.size(); ++k)
            y[k] = Bright(h.cells[k].radiance) * scale + 0.01;
    }
    return y;
}

std::array<double, 2> RotationalGradientOf(const HessianHemisphere& h, const std::vector<double>& y,
                                           const Vec3& u, const Vec3& v) {
    // Per cell, brightness times tanθ resolved along the azimuth + 90°: the
    // cosine-weighted mean of L·(ω·(a × n))/(ω·n) is the relative change of E
    // as n turns about a.
    double sum0 = 0, sum1 = 0;
    const Vec3& n = h.frame.n;
    for (std::size_t k = 0; k < h.cells.size(); ++k) {
        const Vec3& w = h.cells[k].offset;
        const double f = y[k] / Dot(n, w);
        sum0 -= Dot(v, w) * f;
        sum1 += Dot(u, w) * f;
    }
    const double cells = static_cast<double>(h.cells.size());
    return {sum0 / cells, sum1 / cells};
}

bool IsFinite(const Matrix3& a) {
    for (const auto& row : a.m) {
        for (const double x : row) {
            if (!std::isfinite(x))
                return false;
        }
    }
    return true;
}

/// Radiance's quadratic() for a = 1: real roots of λ² + bλ + c in ascending
/// order, a discriminant within ±1e-12 counting as one double root.
int MonicRoots(double b, double c, double roots[2]) {
    const double halfB = 0.5 * b;
    double disc = halfB * halfB - c;
    constexpr double kTiny2 = kFtiny * kFtiny;
    if (disc < -kTiny2)
        return 0;
    if (disc <= kTiny2) {
        roots[0] = -halfB;
        return 1;
    }
    disc = std::sqrt(disc);
    roots[0] = -halfB - disc;
    roots[1] = -halfB + disc;
    return 2;
}

}  // namespace

DiscPoint SquareToDisc(double x, double y) {
    const double a = 2.0 * x - 1.0;
    const double b = 2.0 * y - 1.0;
    // φ lies in one of four quarter turns around the axes; within it φ is a
    // multiple of π/2 plus or minus t = (π/4)·ratio with |t| <= π/4, so
    // cos φ and sin φ are ±cos t and ±sin t, swapped on the y quarters.
    double r, sinT, cosT;
    if (a > -b) {
        if (a > b) {  // φ = t
            r = a;
            SinCosSmall(0.25 * kPi * (b / a), cosT, sinT);
            r *= kDiscScale;
            return {r * cosT, r * sinT};
        }
        r = b;  // φ = π/2 − t
        SinCosSmall(0.25 * kPi * (a / b), cosT, sinT);
        r *= kDiscScale;
        return {r * sinT, r * cosT};
    }
    if (a < b) {  // φ = π + t
        r = -a;
        SinCosSmall(0.25 * kPi * (b / a), cosT, sinT);
        r *= kDiscScale;
        return {-r * cosT, -r * sinT};
    }
    // φ = 3π/2 − t; the square's centre (a = b = 0) maps to the origin.
    r = -b;
    if (b == 0.0) return {r, 0.0 * r};
    SinCosSmall(0.25 * kPi * (a / b), cosT, sinT);
    r *= kDiscScale;
    return {-r * sinT, -r * cosT};
}

int HessianDivisions(const HemisphereOptions& options) {
    const double wanted = static_cast<double>(options.divisions) * options.weight;
    int ns = 0;
    // !(wanted > 0) also catches a NaN weight.
    if (wanted > 0)
        ns = static_cast<int>(std::sqrt(std::min(wanted, 1e12)) + 0.5);
    return std::clamp(ns, options.caching ? kMinHessianDivisions : 1, kMaxDivisionsPerAxis);
}

HessianHemisphere SampleHessianHemisphere(const Vec3& point, const Vec3& normal,
                                          const HemisphereOptions& options, double farDistance,
                                          Rng& rng, AmbientTraceRef trace) {
    RT_DCHECK(LengthSquared(normal) > 0);
    HessianHemisphere h;
    h.point = point;
    const Vec3 n = Normalize(normal);
    const Vec3 u = RandomPerpendicular(n, rng);
    h.frame = Frame{u, Cross(n, u), n};
    const int ns = HessianDivisions(options);
    h.ns = ns;
    h.cells.assign(static_cast<std::size_t>(ns) * static_cast<std::size_t>(ns), HessianCell{});
    const double invNs = 1.0 / ns;

    // Radiance's order, last cell first: the collision test looks at whichever
    // neighbours are already sampled.
    int succeeded = 0;
    for (int i = ns - 1; i >= 0; --i) {
        for (int j = ns - 1; j >= 0; --j) {
            Vec3 dir;
            for (int draw = 0; draw <= kMaxRedraws; ++draw) {
                const double xi0 = rng.Uniform();
                const double xi1 = rng.Uniform();
                dir = CellDirection(h.frame, invNs, i, j, xi0, xi1);
                if (!Collides(h, i, j, dir))
                    break;
            }
            succeeded += SampleCell(h, i, j, dir, 0, farDistance, trace) ? 1 : 0;
        }
    }
    const int cells = ns * ns;
    h.complete = succeeded == cells;
    h.anySample = succeeded > 0;

    // -as·weight, but at most one extra sample per cell on average: the
    // priorities are fixed before any extra sample is taken, so beyond that
    // the extra samples only pile up in the same few cells (as the classic
    // sampler, README Differences).
    const double extraWanted = std::max(0.0, options.superSamples * options.weight);
    const int extra = static_cast<int>(std::min(extraWanted, static_cast<double>(cells)) + 0.5);
    if (h.complete && cells >= kMinSuperSampleCells && extra >= kMinSuperSamples)
        SuperSample(h, extra, options, farDistance, rng, trace);

    Rgb sum;
    for (const HessianCell& c : h.cells)
        sum += c.radiance;
    h.value = sum * (1.0 / cells);
    return h;
}

double Matrix3::Form(const Vec3& a, const Vec3& b) const {
    double s = 0;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j)
            s += a[i] * m[i][j] * b[j];
    }
    return s;
}

namespace detail {

double AtanOverX(double z) {
    // Σ c_k z^k with c_k = (−1)^k/(2k+1), k = 0…13, by Estrin's scheme: the
    // terms pair up in a tree four deep instead of a Horner chain of
    // thirteen, so independent edges overlap in the pipeline.
    constexpr double c[14] = {1.0,       -1.0 / 3,  1.0 / 5,  -1.0 / 7,  1.0 / 9,
                              -1.0 / 11, 1.0 / 13,  -1.0 / 15, 1.0 / 17, -1.0 / 19,
                              1.0 / 21,  -1.0 / 23, 1.0 / 25,  -1.0 / 27};
    const double z2 = z * z;
    const double z4 = z2 * z2;
    const double z8 = z4 * z4;
    const double p0 = c[0] + c[1] * z, p1 = c[2] + c[3] * z, p2 = c[4] + c[5] * z;
    const double p3 = c[6] + c[7] * z, p4 = c[8] + c[9] * z, p5 = c[10] + c[11] * z;
    const double p6 = c[12] + c[13] * z;
    const double q0 = p0 + p1 * z2, q1 = p2 + p3 * z2, q2 = p4 + p5 * z2;
    const double r0 = q0 + q1 * z4, r1 = q2 + p6 * z4;
    return r0 + r1 * z8;
}

double AngleOverSine(double r01, double cc) {
    // atan2 rather than Radiance's acos of the cosine, which loses half its
    // digits for the small angles between neighbours. Those angles are mostly
    // below 14° (tan <= 1/4), where the series gives atan(x)/x · 1/r01 with
    // x² = cc/r01², as exact and without std::atan2, the square root or two
    // divisions (three edges per hemisphere ray). Up to 56° (tan <= 1.5), as
    // coarse hemispheres' neighbours are, the angle is atan(c) + atan(t) with
    // t = (x − c)/(1 + c·x) for c = 1/2 or 1: |t| <= 0.23, where the same
    // series is as exact, for one square root and division.
    if (r01 > 0 && cc <= 0.0625 * r01 * r01) {
        const double ir = 1.0 / r01;
        return AtanOverX(cc * ir * ir) * ir;
    }
    const double rc = std::sqrt(cc);
    if (r01 > 0 && cc <= 2.25 * r01 * r01) {
        constexpr double kAtanHalf = 0.46364760900080611621;  // atan(1/2)
        const bool low = rc <= 0.7 * r01;                     // x <= 0.7: c = 1/2
        const double c = low ? 0.5 : 1.0;
        const double t = (rc - c * r01) / (r01 + c * rc);
        return ((low ? kAtanHalf : 0.25 * kPi) + t * AtanOverX(t * t)) / rc;
    }
    return std::atan2(rc, r01) / rc;
}

void EdgeSums::Add(const Vec3& r0, const Vec3& r1, double s0, double s1, const Vec3& n,
                   double coefficient) {
    const Vec3 e = r1 - r0;
    const Vec3 c = Cross(r0, r1);
    const double cc = LengthSquared(c);
    const double ee = LengthSquared(e);
    const double er0 = Dot(e, r0);
    const double er1 = Dot(e, r1);
    const double se = 1.0 / ee;
    // I1 = angle(r0, r1)/|c|.
    const double i1 = AngleOverSine(Dot(r0, r1), cc);
    const double icc = 1.0 / cc;
    const double i2 = (er1 * s1 - er0 * s0 + ee * i1) * 0.5 * icc;
    const double j2 = (0.5 * (s0 - s1) - er0 * i2) * se;
    const Vec3 q = r0 * i2 + e * j2;
    const Vec3 nxe = Cross(n, e);
    const double nc = Dot(n, c);

    const double gq = 2.0 * nc;
    gradient[0] += coefficient * (nxe.x * i1 + q.x * gq);
    gradient[1] += coefficient * (nxe.y * i1 + q.y * gq);
    gradient[2] += coefficient * (nxe.z * i1 + q.z * gq);

    const double i3 = (er1 * s1 * s1 - er0 * s0 * s0 + 3.0 * ee * i2) * 0.25 * icc;
    const double j3 = 0.25 * se * (s0 * s0 - s1 * s1) - er0 * se * i3;
    const double k3 = se * (i2 - i3 / s0 - 2.0 * er0 * j3);
    // The Hessian term is sym(nxe, q) + 2nc·i3·sym(r0, r0) + 2nc·k3·sym(e, e)
    // + 4nc·j3·sym(r0, e) − nc·i2·I with sym(a, b) = a·bᵀ + b·aᵀ; the last
    // three outer products regroup as r0·xᵀ + e·yᵀ (symmetric as a whole) with
    // x = 4nc·i3·r0 + 4nc·j3·e and y = 4nc·k3·e + 4nc·j3·r0. Written out per
    // entry: Vec3's indexed access does not vectorise.
    const double a = 4.0 * nc * i3, b = 4.0 * nc * k3, d = 4.0 * nc * j3;
    const Vec3 x = r0 * a + e * d;
    const Vec3 y = e * b + r0 * d;
    const double diagonal = nc * i2;
    hessian[0] += coefficient * (2.0 * nxe.x * q.x + r0.x * x.x + e.x * y.x - diagonal);
    hessian[1] += coefficient * (nxe.x * q.y + q.x * nxe.y + r0.x * x.y + e.x * y.y);
    hessian[2] += coefficient * (nxe.x * q.z + q.x * nxe.z + r0.x * x.z + e.x * y.z);
    hessian[3] += coefficient * (2.0 * nxe.y * q.y + r0.y * x.y + e.y * y.y - diagonal);
    hessian[4] += coefficient * (nxe.y * q.z + q.y * nxe.z + r0.y * x.z + e.y * y.z);
    hessian[5] += coefficient * (2.0 * nxe.z * q.z + r0.z * x.z + e.z * y.z - diagonal);
}

void EdgeSums::To(Vec3& gradientOut, Matrix3& hessianOut) const {
    gradientOut = Vec3(gradient[0], gradient[1], gradient[2]) * (0.5 / kPi);
    int u = 0;
    for (int i = 0; i < 3; ++i) {
        for (int j = i; j < 3; ++j, ++u)
            hessianOut.m[i][j] = hessianOut.m[j][i] = hessian[u] * (-1.0 / kPi);
    }
}

FormFactorEdge FormFactorEdgeTerms(const Vec3& r0, const Vec3& r1, const Vec3& n) {
    EdgeSums sums;
    sums.Add(r0, r1, n, 1.0);
    FormFactorEdge out;
    sums.To(out.gradient, out.hessian);
    return out;
}

}  // namespace detail

namespace {

/// Relative spread of a hemisphere's normalised brightness within which it
/// counts as uniform: far above the rounding of interpolated values (about
/// 1e-9 relative in a furnace), at most float rounding (records read from an
/// ambient file), far below any real contrast.
constexpr double kUniformBrightness = 1e-6;

/// EstimateHessian() for normalised brightness `y`.
HessianEstimate EstimateFrom(const HessianHemisphere& h, const std::vector<double>& y,
                             bool radiometric) {
    HessianEstimate est;
    est.radiometric = radiometric;
    const int ns = h.ns;
    const Vec3& n = h.frame.n;
    // Each triangle takes the brightness of its farthest vertex (smallest
    // 1/d; ties as Radiance's back_ambval), so a triangle spanning a depth
    // edge belongs to the background and the near occluder's silhouette
    // stands out: that is what makes the Hessian occlusion-aware.
    auto farthest = [&](std::size_t a, std::size_t b, std::size_t c) {
        const double da = h.cells[a].inverseDistance;
        const double db = h.cells[b].inverseDistance;
        const double dc = h.cells[c].inverseDistance;
        if (da <= db)
            return da <= dc ? y[a] : y[c];
        return db <= dc ? y[b] : y[c];
    };
    // Cell (i, j)'s two triangles, counter-clockwise seen from above:
    // T1 = (i,j) → (i,j+1) → (i+1,j) and T2 = (i+1,j+1) → (i+1,j) → (i,j+1).
    auto t1 = [&](int i, int j) {
        return farthest(Index(ns, i, j), Index(ns, i, j + 1), Index(ns, i + 1, j));
    };
    auto t2 = [&](int i, int j) {
        return farthest(Index(ns, i + 1, j + 1), Index(ns, i + 1, j), Index(ns, i, j + 1));
    };
    detail::EdgeSums sums;
    std::vector<double> inverseSquare(h.cells.size());
    for (std::size_t k = 0; k < inverseSquare.size(); ++k) {
        inverseSquare[k] = 1.0 / LengthSquared(h.cells[k].offset);
    }
    // Σ_T Y_T Σ_{edges of T} is summed per edge: an inner edge is traversed
    // once each way by its two triangles, so it counts (Y_T − Y_T') times and
    // drops out where both have the same brightness (Radiance's book-keeping
    // optimisation, exact here).
    auto edge = [&](int ia, int ja, int ib, int jb, double coefficient) {
        if (coefficient == 0)
            return;
        const std::size_t a = Index(ns, ia, ja), b = Index(ns, ib, jb);
        sums.Add(h.cells[a].offset, h.cells[b].offset, inverseSquare[a], inverseSquare[b], n,
                 coefficient);
    };
    const int last = ns - 1;
    for (int i = 0; i < ns; ++i) {
        for (int j = 0; j < last; ++j) {
            // (i,j) → (i,j+1): in T1(i,j); reversed in T2(i−1,j).
            edge(i, j, i, j + 1, (i < last ? t1(i, j) : 0.0) - (i > 0 ? t2(i - 1, j) : 0.0));
        }
    }
    for (int i = 0; i < last; ++i) {
        for (int j = 0; j < ns; ++j) {
            // (i,j) → (i+1,j): in T2(i,j−1); reversed in T1(i,j).
            edge(i, j, i + 1, j, (j > 0 ? t2(i, j - 1) : 0.0) - (j < last ? t1(i, j) : 0.0));
        }
        for (int j = 0; j < last; ++j) {
            // (i,j+1) → (i+1,j): in T1(i,j); reversed in T2(i,j).
            edge(i, j + 1, i + 1, j, t1(i, j) - t2(i, j));
        }
    }
    sums.To(est.gradient, est.hessian);
    // A uniform hemisphere has no gradient. Radiance's triangles reach only
    // the outermost samples, not the horizon, so its edge terms give one a
    // gradient all the same (0.1–0.5 per unit length at -ad 16 in a furnace,
    // 2 % brighter per bounce); and near a corner (samples 1e-4 away) they
    // turn even the rounding of the sampled values into gradients that the
    // cap lets extrapolate by up to ±a, which the level above samples as
    // real differences (in a furnace at -ab 50 that chain grew from 1e-9 to
    // 13 %). So brightness spread within kUniformBrightness gives none.
    const auto [low, high] = std::minmax_element(y.begin(), y.end());
    est.uniform = *high - *low <= kUniformBrightness * *high;
    if (!est.radiometric || est.uniform)
        est.gradient = Vec3();
    return est;
}

}  // namespace

HessianEstimate EstimateHessian(const HessianHemisphere& h) {
    RT_CHECK(h.complete && h.ns >= 2);
    bool radiometric = false;
    const std::vector<double> y = NormalisedBrightness(h, &radiometric);
    return EstimateFrom(h, y, radiometric);
}

HessianEllipse EllipseFromHessian(const Matrix3& hessian, const Frame& frame, double maxRadius) {
    HessianEllipse out;
    out.u = frame.u;
    out.v = frame.v;
    const double h00 = hessian.Form(frame.u, frame.u);
    const double h01 = hessian.Form(frame.u, frame.v);
    const double h10 = hessian.Form(frame.v, frame.u);
    const double h11 = hessian.Form(frame.v, frame.v);
    double lambda[2] = {0, 0};
    const int roots = MonicRoots(-(h00 + h11), h00 * h11 - h01 * h10, lambda);
    if (roots == 1)
        lambda[1] = lambda[0];
    lambda[0] = std::fabs(lambda[0]);
    lambda[1] = std::fabs(lambda[1]);
    constexpr double kTiny2 = kFtiny * kFtiny;
    if (roots == 0 || lambda[0] <= kTiny2 || lambda[1] <= kTiny2) {
        out.radius[0] = out.radius[1] = maxRadius;
        return out;
    }
    const double large = std::max(lambda[0], lambda[1]);
    const double small = std::min(lambda[0], lambda[1]);
    out.radius[0] = std::sqrt(std::sqrt(4.0 / large));
    out.radius[1] = std::sqrt(std::sqrt(4.0 / small));
    if (std::fabs(h01) <= kFtiny)
        return out;
    // (1, s) solves (h − λ)x = 0 for λ = `small` (exactly so only when that
    // eigenvalue is positive): the direction of least curvature becomes v.
    const double s = (small - h00) / h01;
    const double m = std::sqrt(1.0 / (1.0 + s * s));
    out.v = frame.u * m + frame.v * (s * m);
    out.u = frame.u * (s * m) - frame.v * m;
    return out;
}

std::optional<std::array<double, 2>> HessianRotationalGradient(const HessianHemisphere& h,
                                                               const Vec3& u, const Vec3& v) {
    if (!h.complete || h.ns < kMinHessianDivisions)
        return std::nullopt;
    bool radiometric = false;
    const std::vector<double> y = NormalisedBrightness(h, &radiometric);
    if (!radiometric)
        return std::nullopt;
    return RotationalGradientOf(h, y, u, v);
}

void LimitHessianRadii(double radius[2], const double* posGradient, double weight,
                       const AmbientLimits& limits) {
    if (posGradient != nullptr) {
        // Where E changes fast the ellipse must not reach further than 1/|g|.
        const double g0 = std::fabs(posGradient[0]);
        const double g1 = std::fabs(posGradient[1]);
        if (radius[0] * g0 > 1.0)
            radius[0] = 1.0 / g0;
        if (radius[1] * g1 > 1.0)
            radius[1] = 1.0 / g1;
        if (radius[0] > radius[1])
            radius[0] = radius[1];
    }
    if (radius[0] < limits.minRadius) {
        radius[0] = limits.minRadius;
        if (radius[1] < limits.minRadius)
            radius[1] = limits.minRadius;
    }
    // Weak records (deeper bounces) may be used further away.
    const double scale = 1.0 / std::sqrt(weight);
    radius[0] *= scale;
    radius[1] *= scale;
    if (radius[1] > 2.0 * radius[0])
        radius[1] = 2.0 * radius[0];
    if (radius[1] > limits.maxRadius) {
        radius[1] = limits.maxRadius;
        if (radius[0] > limits.maxRadius)
            radius[0] = limits.maxRadius;
    }
}

void CapHessianGradient(double posGradient[2], const double radius[2]) {
    const double change = posGradient[0] * posGradient[0] * radius[0] * radius[0] +
                          posGradient[1] * posGradient[1] * radius[1] * radius[1];
    if (change > 1.0) {
        const double scale = 1.0 / std::sqrt(change);
        posGradient[0] *= scale;
        posGradient[1] *= scale;
    }
}

std::optional<AmbientRecord> MakeHessianRecord(const HessianHemisphere& h, int level, double weight,
                                               double accuracy, const AmbientLimits& limits) {
    if (!h.complete || h.ns < kMinHessianDivisions || !(weight > 0) || !IsFinite(h.value))
        return std::nullopt;
    bool radiometric = false;
    const std::vector<double> y = NormalisedBrightness(h, &radiometric);
    const HessianEstimate est = EstimateFrom(h, y, radiometric);
    if (!IsFinite(est.hessian) || !IsFinite(est.gradient))
        return std::nullopt;
    const HessianEllipse ellipse = EllipseFromHessian(est.hessian, h.frame, limits.maxRadius);

    AmbientRecord rec;
    rec.position = h.point;
    rec.normal = h.frame.n;
    rec.uAxis = ellipse.u;
    rec.value = h.value;
    rec.radius[0] = ellipse.radius[0];
    rec.radius[1] = ellipse.radius[1];
    rec.level = level;
    rec.weight = weight;
    if (est.radiometric) {
        rec.posGradient[0] = Dot(est.gradient, ellipse.u);
        rec.posGradient[1] = Dot(est.gradient, ellipse.v);
        // Turning the normal in a uniform field changes nothing; the
        // estimate's sum of sample directions is not exactly zero, and on a
        // curved surface (records interpolated across normals) it made the
        // sphere furnace 0.04 % off.
        if (!est.uniform) {
            const std::array<double, 2> g = RotationalGradientOf(h, y, ellipse.u, ellipse.v);
            rec.dirGradient[0] = g[0];
            rec.dirGradient[1] = g[1];
        }
    }
    LimitHessianRadii(rec.radius, est.radiometric ? rec.posGradient : nullptr, weight, limits);
    if (est.radiometric) {
        // The corral sees the ellipse the lookup accepts, a·radius.
        rec.corral = CorralBits(h, ellipse.u, rec.radius[0] * accuracy, rec.radius[1] * accuracy);
        CapHessianGradient(rec.posGradient, rec.radius);
    }
    if (!(rec.radius[0] > 0) || !std::isfinite(rec.radius[1]) ||
        !std::isfinite(rec.dirGradient[0]) || !std::isfinite(rec.dirGradient[1]))
        return std::nullopt;
    return rec;
}

}  // namespace rt
