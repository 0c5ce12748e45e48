// SPDX-License-Identifier: MIT
//
// Ward's stratified hemisphere sampling for one irradiance-cache record, with
// adaptive super-sampling and the Ward & Heckbert (1992) translational and
// rotational gradients (radiance-notes.md §4.12, Radiance ≤ 4.2 ambcomp.c).
// The caller supplies the tracing: ambient/ knows nothing of rays or scenes.
//
//   Hemisphere h = SampleHemisphere(normal, options, rng, [&](const Vec3& dir) {
//       return TraceAmbientRay(point, dir);   // radiance and hit distance
//   });
//   if (auto rec = MakeClassicRecord(point, normal, h, level, weight, limits)) cache.Add(*rec);
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <vector>

#include "ambient/limits.h"
#include "ambient/record.h"
#include "core/function_ref.h"
#include "core/random.h"
#include "core/rgb.h"
#include "core/vecmath.h"

namespace rt {

/// What one hemisphere ray returned.
struct AmbientSample {
    Rgb radiance;           // radiance arriving along the ray (W·sr⁻¹·m⁻²)
    double distance = 0;    // effective hit distance (> 0); a miss reports a large distance
};

/// Traces one ray from the record's point in unit direction `dir`; nullopt
/// when the ray was refused (depth limit; the division fails).
/// AmbientTraceFn owns its callable (tests keep environments in one);
/// SampleHemisphere only borrows it for the call, through an AmbientTraceRef,
/// which costs no allocation or type-erased copy per hemisphere.
using AmbientTraceFn = std::function<std::optional<AmbientSample>(const Vec3& dir)>;
using AmbientTraceRef = FunctionRef<std::optional<AmbientSample>(const Vec3& dir)>;

struct HemisphereOptions {
    int divisions = 1024;    // -ad: about this many first-pass samples at weight 1
    int superSamples = 512;  // -as: extra samples at weight 1, sent where neighbours differ most;
                             // at most one per division on average (nt·np)
    double weight = 1;       // record weight: sample counts scale with it (0.5^level)
    bool caching = true;     // -aa > 0: at least 3 rows; without cache at least 1
    /// Without the cache, compute the gradients anyway (only records use them
    /// otherwise): the rotational one turns the value to a textured
    /// surface's shading normal.
    bool gradients = false;
    /// Hessian records below the first level (IrradianceCache): the relative
    /// standard error (-aa) at or above which a first pass takes all its
    /// extra samples; 0 (the first level) takes them always. Only the
    /// Hessian sampler reads it (SuperSamplesForContrast); the classic
    /// sampler keeps Radiance's -as·weight (README, Differences).
    double contrastTarget = 0;
};

/// How many of `budget` extra samples a hemisphere takes whose first pass's
/// neighbour contrasts (the super-sampling priorities, brightness²) sum to
/// `contrastSum` over `cells` divisions of mean brightness `meanBright`: all
/// of them without a target (`target` <= 0), else budget·min(1, V²/target²)
/// rounded at random (expectation exact), where V² = contrastSum /
/// (cells·meanBright)² estimates the relative variance of the hemisphere's
/// mean.
///
/// Why: below the first level a record's error reaches the answer only
/// through the records that look at it, averaged with many others, so extra
/// samples pay only where the first pass is still rough by the relative
/// measure the cache already accepts from interpolation (-aa): a window or a
/// sunlit patch in view, not a smooth room. Below the cap each division gets
/// budget·priority/contrastSum = priority·budget/(cells·meanBright·target)²
/// extra samples: its neighbours' contrast, not the sum over all, decides.
int SuperSamplesForContrast(int budget, double contrastSum, double cells, double meanBright,
                            double target, Rng& rng);

struct Hemisphere {
    Rgb value;                // Ē: cosine-weighted mean incident radiance (= irradiance/π)
    bool complete = false;    // every division has at least one successful sample
    bool anySample = false;   // at least one division has (else the value means nothing)
    int rows = 0;             // nt (altitude divisions)
    int columns = 0;          // np (azimuth divisions)
    int raysTraced = 0;       // first pass + super-samples
    double inverseDistanceSum = 0;  // Σ 1/d over the first sample of each division
    int distanceCount = 0;          // how many samples that sum has
    Frame frame;              // u, v, n used for the divisions
    // Gradients are for records: zero without the cache (options.caching false).
    Vec3 posGradient;         // relative translational gradient, tangent to n (1/length)
    Vec3 dirGradient;         // relative rotational gradient, tangent to n (1/radian)
    /// For the leak test's corral bits (ambient/leak.h), when complete and
    /// caching: per column, the nearest hit (largest 1/d) in its division next
    /// to the horizon.
    std::vector<double> horizonInverseDistance;
};

/// Ward's division counts for `options` (radiance-notes.md §4.12): rows
/// nt = (int)(sqrt(divisions·weight/π) + 0.5), at least 3 when caching and 1
/// otherwise (and at most 1155, so nt·np <= kMaxAmbientDivisions), and columns
/// np = (int)(π·nt + 0.5); without the cache, a single row shrinks to one
/// column once divisions·weight falls below 1/3, so that deep recursions stay
/// linear (Radiance: one sample below ad·wt = 1). SampleHemisphere uses exactly these; the caller
/// needs them to give each sample ray its share of the coefficient.
struct DivisionCounts {
    int rows = 0;
    int columns = 0;
    int total() const { return rows * columns; }
};
DivisionCounts HemisphereDivisions(const HemisphereOptions& options);

/// Samples the hemisphere around unit `normal`. Never returns NaN or
/// negative values; failed samples count as zero radiance and make the
/// result incomplete.
Hemisphere SampleHemisphere(const Vec3& normal, const HemisphereOptions& options, Rng& rng,
                            AmbientTraceRef trace);

namespace detail {

/// How many of `count` extra samples each cell of a rows × columns grid
/// (row-major) gets, the cells coloured as a checkerboard, colour (row +
/// column) % 2, and each cell's `priority` computed from the other colour's
/// samples only. Each colour gets a share of `count` by its number of cells
/// (rounded at random), spread over its cells in proportion to their
/// priorities by systematic sampling (one random offset per colour): exact
/// in total, each cell its share in expectation. So a cell's count depends on
/// no sample of its own colour, its own included, and a cell's mean over its
/// samples stays unbiased. (Normalising all priorities together lets a cell's
/// own sample raise its neighbours' priorities and so lower its own share:
/// a cell that caught a small bright spot keeps it at full weight.)
/// `cut(colour, budget, colourTotal)` may lower a colour's share; it is
/// called after that colour's offset is drawn.
std::vector<int> AllotCheckerboard(const std::vector<double>& priority, int rows, int columns,
                                   int count, Rng& rng,
                                   FunctionRef<int(int colour, int budget, double total)> cut);

/// Each cell's super-sampling priority (brightness²): the variance of the
/// brightness `bright` of its neighbours above, below, left and right in a
/// rows × columns grid (row-major), its own left out. With `wrap` the columns
/// wrap around (the classic sampler's azimuth), except that with an odd
/// column count the two cells meeting across the wrap-around, of one
/// checkerboard colour, are not neighbours; so every cell's priority comes
/// from cells of the other colour only.
std::vector<double> NeighbourVariance(const std::vector<double>& bright, int rows, int columns,
                                      bool wrap);

/// The classic sampler's allotment of `count` extra samples over its
/// divisions, from their first-pass brightness `bright` (row-major, rows ×
/// columns, columns wrapping around the azimuth): each division's priority is
/// the variance of its neighbours of the other colour (above, below, left
/// and right, the wrap-around pair left out where an odd column count puts it
/// in the same colour), then AllotCheckerboard.
std::vector<int> AllotClassicSuperSamples(const std::vector<double>& bright, int rows,
                                          int columns, int count, Rng& rng);

}  // namespace detail

/// Turns a complete hemisphere into a classic (isotropic) record: radius from
/// the harmonic mean distance, limited by the gradient and clamped to
/// [minRadius, maxRadius] after dividing by sqrt(weight), gradients capped so
/// |g|·R <= 1 (radiance-notes.md §4.12). nullopt for an incomplete hemisphere.
std::optional<AmbientRecord> MakeClassicRecord(const Vec3& position, const Vec3& normal,
                                               const Hemisphere& hemisphere, int level,
                                               double weight, const AmbientLimits& limits);

}  // namespace rt
