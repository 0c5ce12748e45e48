// SPDX-License-Identifier: MIT
//
// Radiance 5's hemisphere sampling and record making (ambcomp.c: samp_hemi,
// ambsample, ambsupersamp, ambHessian, eigenvectors, ambdirgrad, doambient;
// radiance-notes.md §4.5–4.7): an ns × ns grid of cells mapped to a
// cosine-weighted hemisphere by the Shirley–Chiu concentric map, whose hit
// points are triangulated to estimate the occlusion-aware Hessian and
// translational gradient of Schwarzhaupt, Jensen & Jarosz (2012), "Practical
// Hessian-based error control for irradiance caching". The Hessian's
// eigen-analysis gives an elliptical record (two radii and a u-axis). The
// classic sampler (hemisphere.h) stays for Radiance ≤ 4.2's records.
//
//   HessianHemisphere h = SampleHessianHemisphere(point, normal, options,
//                                                 HessianFarDistance(cubeSize), rng, trace);
//   if (auto rec = MakeHessianRecord(h, level, weight, accuracy, limits)) cache.Add(*rec);
//   else use h.value unstored (Radiance's "value only" return) when h.anySample.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "ambient/hemisphere.h"
#include "ambient/limits.h"
#include "ambient/record.h"
#include "core/random.h"
#include "core/rgb.h"
#include "core/vecmath.h"

namespace rt {

/// The fewest cells per axis a record is made from (Radiance's MINADIV): with
/// the cache on, hemispheres have at least this many; below it only the value
/// is returned.
inline constexpr int kMinHessianDivisions = 7;

/// Radiance's limit on the stored hit distance, 10·cubeSize + 1000 (scene
/// units): misses (reported at kFhuge) and very distant hits are placed there
/// so the triangulated hemisphere stays finite.
inline double HessianFarDistance(double cubeSize) { return 10.0 * cubeSize + 1000.0; }

/// Shirley & Chiu's concentric map from the unit square onto the unit disc,
/// as Radiance's SDsquare2disk: continuous, area-preserving (Jacobian π/4
/// everywhere), and the disc radius is scaled by 1 − 1e-13 so that a point
/// lifted to the hemisphere never lies exactly on the horizon.
struct DiscPoint {
    double x = 0, y = 0;
};
DiscPoint SquareToDisc(double x, double y);

/// One cell of the ns × ns grid (Radiance's AMBSAMP).
struct HessianCell {
    Rgb radiance;                // mean radiance over its samples (W·sr⁻¹·m⁻²); 0 if failed
    Vec3 offset;                 // hit point of its first sample minus the hemisphere's point:
                                 // dir·min(distance, farDistance) (scene units)
    double inverseDistance = 0;  // 1/nearest distance over its samples (1/scene units);
                                 // 0 = never sampled
    int samples = 0;             // successful samples; 0 = the cell failed
};

/// Radiance 5's sampled hemisphere. Cell (i, j) covers the square
/// [j/ns, (j+1)/ns) × [i/ns, (i+1)/ns) (x along frame.u, y along frame.v)
/// before the concentric map.
struct HessianHemisphere {
    Rgb value;               // Ē: cosine-weighted mean radiance, Σ cell means / ns² (= E/π)
    bool complete = false;   // every cell has a successful sample
    bool anySample = false;  // at least one has (else the value means nothing)
    int ns = 0;              // cells per axis
    int raysTraced = 0;      // first pass + super-samples, including failed ones
    int superSamples = 0;    // successful super-samples
    Vec3 point;              // where the hemisphere was sampled
    Frame frame;             // u, v = n × u (random azimuth), n the unit normal
    std::vector<HessianCell> cells;  // row-major: cells[i·ns + j]

    const HessianCell& At(int i, int j) const {
        return cells[static_cast<std::size_t>(i) * static_cast<std::size_t>(ns) +
                     static_cast<std::size_t>(j)];
    }
};

/// Cells per axis for `options`: ns = (int)(sqrt(divisions·weight) + 0.5), at
/// least kMinHessianDivisions with the cache and 1 without, at most 2048 (so
/// ns² <= kMaxAmbientDivisions). Radiance 5 takes exactly this many first-pass
/// samples, and the caller needs it to give each sample ray its 1/ns² share of
/// the coefficient. The no-cache weight reduction of §4.5 step 2 is the
/// caller's, through options.weight.
int HessianDivisions(const HemisphereOptions& options);

/// Samples the hemisphere around unit `normal` at `point` (radiance-notes.md
/// §4.5–4.6): one sample per cell in a stratified, cosine-weighted layout,
/// first samples re-drawn when they would fall within π/(4ns) of a neighbour's,
/// then (int)(min(superSamples·weight, ns²) + 0.5) extra samples, if more
/// than 8, allotted before any is taken in proportion to the contrast among
/// each cell's neighbours (detail::NeighbourContrast; only for complete
/// hemispheres of more than 49 cells). Unlike Radiance's, this allocation
/// leaves every cell's mean unbiased. As in Radiance, extra samples change a
/// cell's mean and nearest distance but not its hit point, which pulls the
/// translational gradient low where they land. `farDistance` (see
/// HessianFarDistance) bounds the stored hit points. Never returns NaN or
/// negative values; a failed sample counts as zero radiance and makes the
/// result incomplete.
HessianHemisphere SampleHessianHemisphere(const Vec3& point, const Vec3& normal,
                                          const HemisphereOptions& options, double farDistance,
                                          Rng& rng, AmbientTraceRef trace);

/// A symmetric 3×3 matrix (the Hessian), world axes.
struct Matrix3 {
    double m[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
    /// aᵀ·M·b.
    double Form(const Vec3& a, const Vec3& b) const;
};

/// The Hessian and translational gradient of the normalised brightness
/// Y_k = 0.99·bright(L_k)/bright(Ē) + 0.01 (mean 1) over the triangulated
/// hemisphere, each triangle taking its farthest vertex's Y, with respect to
/// moving the hemisphere's point (§4.7 steps 1–2). When Ē is black
/// (bright(Ē)·0.5 <= 1e-6, Radiance's threshold on its AVGREFL-scaled value)
/// Y is 1 everywhere: a purely geometric Hessian, and no gradient.
struct HessianEstimate {
    Matrix3 hessian;          // 1/length²: ≈ −0.99 × the relative Hessian of the irradiance.
                              // The sign is Radiance's: its edge formula is the negative
                              // of the form factor's Hessian. Radii use |λ| and do not
                              // care; the frame rotation's |λ| quirk (EllipseFromHessian)
                              // does, and is reproduced with this sign.
    Vec3 gradient;            // 1/length: ≈ 0.99 × ∇E/E; zero when !radiometric or uniform
    bool radiometric = true;  // false: geometric fallback, no gradients or corral
    /// The hemisphere's brightness is uniform within rounding: it has no
    /// gradient, translational or rotational.
    bool uniform = false;
};
/// Requires a complete hemisphere with ns >= 2.
HessianEstimate EstimateHessian(const HessianHemisphere& hemisphere);

/// Radii and axes of a record from the Hessian projected on the tangent plane
/// (§4.7 step 3, Radiance's eigenvectors()): r = (4/|λ|)^¼ for the two
/// eigenvalues, radius[0] <= radius[1]; u, v = n × u rotated so that v follows
/// the eigenvector of the smaller |λ|. Radiance's quirks are kept: the
/// rotation solves for the eigenvector with |λ| in place of λ, and is skipped
/// when the off-diagonal term is at most 1e-6 (so radius[0] may then lie
/// along v's curvature). Both radii are `maxRadius` and the frame unchanged
/// when an eigenvalue is within 1e-12 of zero.
struct HessianEllipse {
    double radius[2] = {0, 0};
    Vec3 u, v;
};
HessianEllipse EllipseFromHessian(const Matrix3& hessian, const Frame& frame, double maxRadius);

/// The relative rotational gradient (1/radian) along unit tangents u and v
/// (v = n × u) from the hemisphere's normalised brightness (§4.7 step 5,
/// Radiance's ambdirgrad): rotating the normal by δ about a tangent axis a
/// changes E by the factor 1 + δ·a·(g[0]·u + g[1]·v). nullopt when the
/// hemisphere is incomplete, has fewer than kMinHessianDivisions cells per
/// axis or is black. For -aa 0 callers in the hemisphere's own frame.
/// Radiance's estimate as it is: MakeHessianRecord gives a uniform hemisphere
/// none (HessianEstimate::uniform).
std::optional<std::array<double, 2>> HessianRotationalGradient(const HessianHemisphere& hemisphere,
                                                               const Vec3& u, const Vec3& v);

/// §4.7 step 6, in Radiance's order: each radius at most 1/|posGradient| along
/// its axis (when `posGradient` is given) and radius[0] <= radius[1]; at least
/// minRadius; divided by sqrt(weight); radius[1] <= 2·radius[0]; at most
/// maxRadius.
void LimitHessianRadii(double radius[2], const double* posGradient, double weight,
                       const AmbientLimits& limits);

/// §4.7 step 8: scales posGradient so that its change across the ellipse,
/// sqrt((g0·r0)² + (g1·r1)²), is at most 1.
void CapHessianGradient(double posGradient[2], const double radius[2]);

/// Radiance 5's record from a hemisphere (§4.7): radii and u-axis from the
/// Hessian, translational and rotational gradients, the limits of step 6 for
/// record `weight` (> 0), corral bits for -aa `accuracy` (ambient/leak.h) and
/// the gradient cap. nullopt for an incomplete hemisphere or one with fewer
/// than kMinHessianDivisions cells per axis (use its value unstored), and for
/// hit points so degenerate that the Hessian is not finite.
std::optional<AmbientRecord> MakeHessianRecord(const HessianHemisphere& hemisphere, int level,
                                               double weight, double accuracy,
                                               const AmbientLimits& limits);

namespace detail {

/// Form factor derivatives of one directed edge p0 → p1 of a polygon seen from
/// a point with unit normal n, r0 = p0 − point, r1 = p1 − point (Schwarzhaupt
/// et al. 2012; §4.7 step 2). Summed over the edges of a polygon above the
/// point's tangent plane, counter-clockwise seen from +n, they give the
/// derivatives of its form factor F = (1/2π)·Σ angle(r0, r1)·n·unit(r0 × r1)
/// with respect to the point.
struct FormFactorEdge {
    Vec3 gradient;    // 1/length: sums to ∇F
    Matrix3 hessian;  // 1/length²: sums to −∇∇F (Radiance's sign, see HessianEstimate)
};
FormFactorEdge FormFactorEdgeTerms(const Vec3& r0, const Vec3& r1, const Vec3& n);

/// atan(x)/x for z = x² <= 1/16 by its Taylor series through x²⁶ (the first
/// term left out is below 1e-17 relative), and atan(x) = x·AtanOverX(x²):
/// within an ulp of std::atan, for the small angles between neighbouring
/// cells, without std::atan2's cost (nor the square root and division that
/// would give it |r0 × r1|).
double AtanOverX(double z);
inline double AtanSmall(double x) { return x * AtanOverX(x * x); }

/// angle(r0, r1)/|r0 × r1| from r01 = r0·r1 and cc = |r0 × r1|² > 0, within
/// a few ulps of std::atan2(√cc, r01)/√cc and mostly without calling it.
double AngleOverSine(double r01, double cc);

/// A running sum of coefficient × FormFactorEdgeTerms over many edges, kept
/// without the constant factors (1/2π, −1/π) and with the Hessian's six
/// distinct entries only, which a hemisphere's ~3·ns² edges would otherwise
/// pay for each time. FormFactorEdgeTerms is one Add and To.
struct EdgeSums {
    double gradient[3] = {0, 0, 0};
    double hessian[6] = {0, 0, 0, 0, 0, 0};  // xx, xy, xz, yy, yz, zz
    void Add(const Vec3& r0, const Vec3& r1, const Vec3& n, double coefficient) {
        Add(r0, r1, 1.0 / LengthSquared(r0), 1.0 / LengthSquared(r1), n, coefficient);
    }
    /// As Add, with s0 = 1/|r0|² and s1 = 1/|r1|² given: a hemisphere's hit
    /// points each end six edges, so they are inverted once per cell.
    void Add(const Vec3& r0, const Vec3& r1, double s0, double s1, const Vec3& n,
             double coefficient);
    void To(Vec3& gradientOut, Matrix3& hessianOut) const;
};

/// The super-sampling priorities: for each cell (row-major), the variance of
/// the first-pass brightness of its neighbours above, below, left and right
/// (those that exist), leaving the cell's own sample out. Units: radiance².
/// Radiance's getambdiffs() compares each cell with its neighbours, so a cell
/// whose first sample caught a small bright patch is refined (its mean pulled
/// down to the truth) while one that missed it stays dark: the hemisphere
/// comes out biased low (README, Differences). Left out, a cell's own value
/// does not decide how many extra samples it gets, and its mean stays unbiased.
std::vector<double> NeighbourContrast(const HessianHemisphere& hemisphere);

/// How many of `count` extra samples each cell (row-major) gets: each colour
/// of the grid's checkerboard a share by its number of cells, spread by
/// NeighbourContrast with systematic sampling (random offsets from `rng`).
/// A cell's count depends on no cell of its own colour, itself included.
/// With `options`' contrast target (records below the first level), each
/// colour's share is cut by SuperSamplesForContrast, the whole hemisphere's
/// contrast and mean brightness estimated from the other colour's samples.
std::vector<int> AllotSuperSamples(const HessianHemisphere& hemisphere, int count, Rng& rng,
                                   const HemisphereOptions& options = {});

}  // namespace detail

}  // namespace rt
