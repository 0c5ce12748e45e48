// SPDX-License-Identifier: MIT
//
// Ward's classic stratified hemisphere sampler, adaptive super-sampling and
// the Ward & Heckbert (1992) irradiance gradients (radiance-notes.md §4.12,
// Radiance ≤ 4.2 ambcomp.c: inithemi, divsample, comperrs, posgradient,
// dirgradient, doambient). Written from the formulas, not from that code.
#include "ambient/hemisphere.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

#include "ambient/ambient_options.h"
#include "core/check.h"
#include "core/conventions.h"

namespace rt {
namespace {

/// Super-sampling needs more than 8 extra samples (Radiance 5's threshold,
/// applied to the classic sampler: fewer cannot move the estimate usefully).
constexpr int kMinSuperSamples = 9;
/// ...and at least this many rows, so every division has a neighbour above or
/// below for the variance estimate.
constexpr int kMinSuperSampleRows = 2;
/// The most rows: nt·np stays at or below kMaxAmbientDivisions however large
/// -ad·weight is, so memory per hemisphere is bounded even for callers that
/// bypass the front end's -ad check (1155 rows × 3629 columns = 4 191 495).
constexpr int kMaxRows = 1155;
constexpr int ColumnsFor(int rows) { return static_cast<int>(kPi * rows + 0.5); }
static_assert(kMaxRows * ColumnsFor(kMaxRows) <= kMaxAmbientDivisions);
static_assert((kMaxRows + 1) * ColumnsFor(kMaxRows + 1) > kMaxAmbientDivisions);

/// One (row t, column p) cell of the hemisphere.
struct Division {
    Rgb mean;                           // running mean radiance over its samples
    double nearestInverseDistance = 0;  // max 1/d over its samples (0: misses at infinity)
    int samples = 0;                    // successful samples; 0 = the division failed
};

/// The nt × np divisions, row-major (row t = sin²θ in [t/nt, (t+1)/nt)).
class DivisionGrid {
  public:
    DivisionGrid(int rows, int columns)
        : rows_(rows),
          columns_(columns),
          cells_(static_cast<std::size_t>(rows) * static_cast<std::size_t>(columns)) {}

    int Rows() const { return rows_; }
    int Columns() const { return columns_; }
    int Size() const { return rows_ * columns_; }
    Division& operator[](int i) { return cells_[static_cast<std::size_t>(i)]; }
    const Division& operator[](int i) const { return cells_[static_cast<std::size_t>(i)]; }
    Division& At(int t, int p) { return (*this)[t * columns_ + p]; }
    const Division& At(int t, int p) const { return (*this)[t * columns_ + p]; }
    /// Column before p, wrapping around the azimuth.
    int Previous(int p) const { return p > 0 ? p - 1 : columns_ - 1; }
    const std::vector<Division>& Cells() const { return cells_; }

  private:
    int rows_, columns_;
    std::vector<Division> cells_;
};

}  // namespace

int SuperSamplesForContrast(int budget, double contrastSum, double cells, double meanBright,
                            double target, Rng& rng) {
    if (!(target > 0) || budget <= 0) return budget;
    // Drawn whatever the ratio: otherwise whether it is drawn would depend on
    // the samples, and so would every random number after it (the other
    // checkerboard colour's shares in the Hessian sampler).
    const double u = rng.Uniform();
    const double scale = cells * meanBright * target;
    const double ratio = contrastSum / (scale * scale);
    if (!(ratio < 1)) return budget;  // NaN (a black first pass) too
    return static_cast<int>(std::floor(budget * ratio + u));
}

DivisionCounts HemisphereDivisions(const HemisphereOptions& options) {
    const double x = static_cast<double>(options.divisions) * options.weight / kPi;
    int rows = 0;
    // !(x > 0) also catches a NaN weight.
    if (x > 0)
        rows = static_cast<int>(std::sqrt(std::min(x, 1e9)) + 0.5);
    rows = std::clamp(rows, options.caching ? 3 : 1, kMaxRows);
    int columns = ColumnsFor(rows);
    if (!options.caching && rows == 1) {
        // Without the cache each sample carries 1/total of the weight. Ward's
        // minimum row of 1×3 is kept while divisions·weight is at least 1/3:
        // at the cornell floor's second bounce (-aa 0 -ad 1024, where it is
        // 0.88) three samples halved error²·time against one. Below that one
        // sample, as Radiance's ns² = ad·wt. Each split divides the weight by
        // 3/ρ or more, so a path splits at most log3(3·ad·wt) times; a fixed
        // 1×3 made deep recursions grow as 3^depth (-ab 50 -aa 0 -ad 1 never
        // finished).
        constexpr double kMinSplitWorth = 1.0 / 3.0;
        const double wanted = static_cast<double>(options.divisions) * options.weight;
        if (wanted < kMinSplitWorth) columns = 1;
    }
    return {rows, columns};
}

namespace {

/// Cosine-weighted directions in the divisions of a hemisphere: sin²θ is
/// uniform within a row, φ within a column (§4.12). The azimuth of each
/// column's start is tabulated once per hemisphere; the jitter within the
/// column (at most π/4 wide from 8 columns up) is a small rotation from it.
class DivisionDirections {
  public:
    DivisionDirections(const Frame& frame, int rows, int columns)
        : frame_(frame), rows_(rows), columns_(columns), small_(columns >= 8) {
        if (!small_) return;
        start_.resize(static_cast<size_t>(columns));
        for (int p = 0; p < columns; ++p) {
            auto& [c, s] = start_[static_cast<size_t>(p)];
            SinCos(2.0 * kPi * p / columns, c, s);
        }
    }

    /// The direction in division (t, p) with jitter (xi0, xi1) in [0,1)².
    Vec3 operator()(int t, int p, double xi0, double xi1) const {
        const double sin2 = (t + xi0) / rows_;
        const double sinTheta = std::sqrt(sin2);
        const double cosTheta = std::sqrt(1.0 - sin2);
        double cosPhi, sinPhi;
        if (small_) {
            double c, s;
            SinCosSmall(2.0 * kPi * xi1 / columns_, c, s);
            const auto [c0, s0] = start_[static_cast<size_t>(p)];
            cosPhi = c0 * c - s0 * s;
            sinPhi = s0 * c + c0 * s;
        } else {
            // Few columns (deeper levels, small -ad): a column is too wide for
            // SinCosSmall, but SinCos still spares std::cos and std::sin.
            SinCos(2.0 * kPi * (p + xi1) / columns_, cosPhi, sinPhi);
        }
        return frame_.ToWorld({cosPhi * sinTheta, sinPhi * sinTheta, cosTheta});
    }

  private:
    const Frame& frame_;
    int rows_, columns_;
    bool small_;  // columns narrow enough for SinCosSmall
    std::vector<std::pair<double, double>> start_;  // cos, sin of each column's start
};

/// The hemisphere frame around unit n. Radiance ≤ 4.2 used the fixed
/// getperpendicular() axis, so neighbouring records shared one division
/// layout and its aliasing; a random azimuth (as Radiance 5 does) decorrelates
/// them. The u axis is stored in the record, so nothing downstream depends on it.
Frame RandomFrame(const Vec3& n, Rng& rng) {
    const Frame fixed = Frame::Around(n);
    const Vec3& u0 = fixed.u;
    const Vec3& v0 = fixed.v;
    double cosAzimuth, sinAzimuth;
    SinCos(2.0 * kPi * rng.Uniform(), cosAzimuth, sinAzimuth);
    Frame frame;
    frame.n = n;
    frame.u = Normalize(u0 * cosAzimuth + v0 * sinAzimuth);
    frame.v = Cross(n, frame.u);
    return frame;
}

/// A usable radiance sample, or nullopt when the ray failed. Negative channels
/// are cut to zero so the result is never negative (the header's contract).
struct Traced {
    Rgb radiance;
    double inverseDistance = 0;
};
std::optional<Traced> TraceOne(AmbientTraceRef trace, const Vec3& dir) {
    const std::optional<AmbientSample> s = trace(dir);
    if (!s || !(s->distance > 0) || !IsFinite(s->radiance))
        return std::nullopt;
    Traced out;
    out.radiance = Rgb(std::max(s->radiance.r, 0.0), std::max(s->radiance.g, 0.0),
                       std::max(s->radiance.b, 0.0));
    out.inverseDistance = 1.0 / s->distance;  // 0 for an infinite miss distance
    return out;
}

/// Adds one super-sample to a division: running mean and nearest hit.
void AddSuperSample(Division& d, const Traced& sample) {
    const int n = ++d.samples;
    // mean += (x − mean)/n keeps a constant environment exactly constant.
    d.mean += (sample.radiance - d.mean) * (1.0 / n);
    // The gradient weights want the nearest surface seen in the division (as
    // Radiance 5 keeps): a division the edge of a near emitter cuts must keep
    // the emitter's distance even if its first sample missed. The first-sample
    // distance alone (still the header's radius statistic), or Radiance ≤ 4.2's
    // mean 1/d, under-weights such an edge (docs/measured-choices.md).
    d.nearestInverseDistance = std::max(d.nearestInverseDistance, sample.inverseDistance);
}

/// Ward & Heckbert's translational gradient of E (absolute, W·m⁻² per unit
/// length) from brightness differences across division boundaries, each
/// weighted by the nearer of the two divisions' nearest hits (Radiance's
/// posgradient). Row-boundary terms point along the column centre, as in the
/// paper; Radiance ≤ 4.2 used the column's start φ_j, which rotates them by
/// π/np and adds a spurious sideways component (docs/measured-choices.md).
Vec3 TranslationalGradient(const DivisionGrid& divs, const Frame& frame) {
    const int rows = divs.Rows();
    const int columns = divs.Columns();
    double xd = 0, yd = 0;
    for (int p = 0; p < columns; ++p) {
        double acrossRows = 0;     // Σ over row boundaries (θ direction)
        double acrossColumns = 0;  // Σ over the boundary with column p−1 (φ direction)
        double lastSine = 0;
        for (int t = 0; t < rows; ++t) {
            const Division& d = divs.At(t, p);
            const double b = Bright(d.mean);
            if (t > 0) {
                const Division& up = divs.At(t - 1, p);
                const double r = std::max(up.nearestInverseDistance, d.nearestInverseDistance);
                const double cos2 = 1.0 - static_cast<double>(t) / rows;  // at the boundary
                acrossRows += r * lastSine * cos2 * (b - Bright(up.mean));
            }
            const double nextSine = std::sqrt(static_cast<double>(t + 1) / rows);
            const Division& left = divs.At(t, divs.Previous(p));
            const double r = std::max(left.nearestInverseDistance, d.nearestInverseDistance);
            acrossColumns += r * (nextSine - lastSine) * (b - Bright(left.mean));
            lastSine = nextSine;
        }
        acrossRows *= 2.0 * kPi / columns;
        const double phiCentre = 2.0 * kPi * (p + 0.5) / columns;
        const double phiEdge = 2.0 * kPi * p / columns;
        xd += acrossRows * std::cos(phiCentre) - acrossColumns * std::sin(phiEdge);
        yd += acrossRows * std::sin(phiCentre) + acrossColumns * std::cos(phiEdge);
    }
    return frame.u * xd + frame.v * yd;
}

/// Ward & Heckbert's rotational gradient of E (absolute, W·m⁻² per radian):
/// rotating the normal about axis a by δ changes E by δ·(g·a). Each column
/// contributes Σ_t L·tanθ along φ + π/2 (Radiance's dirgradient), times π/(nt·np).
Vec3 RotationalGradient(const DivisionGrid& divs, const Frame& frame) {
    const int rows = divs.Rows();
    const int columns = divs.Columns();
    // Mean of tanθ over each row for cosine-distributed directions, i.e. with
    // x = sin²θ uniform in [t/nt, (t+1)/nt]: nt·[F(x)] with F(x) = asin√x −
    // √(x(1−x)), the antiderivative of √(x/(1−x)). Radiance ≤ 4.2 took tanθ at
    // the row's centre, which misses the integrable 1/√(1−x) rise toward the
    // horizon and so underestimates the gradient of a sky bright down to the
    // horizon (hemisphere_test: GradientsMatchHalfPlaneEmitter).
    std::vector<double> meanTan(static_cast<std::size_t>(rows));
    auto antiderivative = [](double x) {
        return std::asin(std::sqrt(x)) - std::sqrt(x * (1.0 - x));
    };
    for (int t = 0; t < rows; ++t) {
        const double x0 = static_cast<double>(t) / rows;
        const double x1 = t + 1 == rows ? 1.0 : static_cast<double>(t + 1) / rows;
        meanTan[static_cast<std::size_t>(t)] = rows * (antiderivative(x1) - antiderivative(x0));
    }
    double xd = 0, yd = 0;
    for (int p = 0; p < columns; ++p) {
        double mag = 0;
        for (int t = 0; t < rows; ++t)
            mag += Bright(divs.At(t, p).mean) * meanTan[static_cast<std::size_t>(t)];
        const double phi = 2.0 * kPi * (p + 0.5) / columns + 0.5 * kPi;
        xd += mag * std::cos(phi);
        yd += mag * std::sin(phi);
    }
    const double scale = kPi / (static_cast<double>(rows) * columns);
    return (frame.u * xd + frame.v * yd) * scale;
}

}  // namespace

namespace detail {

std::vector<int> AllotCheckerboard(const std::vector<double>& priority, int rows, int columns,
                                   int count, Rng& rng,
                                   FunctionRef<int(int colour, int budget, double total)> cut) {
    std::vector<int> counts(priority.size(), 0);
    const int cells = rows * columns;
    // Cells of colour 0, that of cell (0, 0): half, or one more when both
    // counts are odd.
    const int evenCells = (cells + 1) / 2;
    const int evenCount = static_cast<int>(
        std::floor(static_cast<double>(count) * evenCells / cells + rng.Uniform()));
    for (int colour = 0; colour < 2; ++colour) {
        double total = 0;
        for (int t = 0; t < rows; ++t) {
            for (int p = (t + colour) % 2; p < columns; p += 2)
                total += priority[static_cast<std::size_t>(t * columns + p)];
        }
        const double offset = rng.Uniform();
        const int budget = cut(colour, colour == 0 ? evenCount : count - evenCount, total);
        // An infinite total (radiance differences above about 1e154, whose
        // squares overflow) would make every share NaN: that colour then
        // takes no extra samples.
        if (!(total > 0) || !(total <= std::numeric_limits<double>::max()) || budget <= 0)
            continue;
        double cumulative = 0;
        for (int t = 0; t < rows; ++t) {
            for (int p = (t + colour) % 2; p < columns; p += 2) {
                const std::size_t k = static_cast<std::size_t>(t * columns + p);
                const double before = std::floor(cumulative + offset);
                cumulative += budget * priority[k] / total;
                counts[k] = static_cast<int>(std::floor(cumulative + offset) - before);
            }
        }
    }
    return counts;
}

std::vector<double> NeighbourVariance(const std::vector<double>& bright, int rows, int columns,
                                      bool wrap) {
    std::vector<double> priority(bright.size(), 0.0);
    // Across the azimuth's wrap-around an odd column count joins two cells
    // of one colour: that pair are not neighbours.
    const bool wrapJoins = wrap && columns % 2 == 0;
    for (int t = 0; t < rows; ++t) {
        for (int p = 0; p < columns; ++p) {
            double b[4];
            int n = 0;
            if (t > 0) b[n++] = bright[static_cast<std::size_t>((t - 1) * columns + p)];
            if (t + 1 < rows) b[n++] = bright[static_cast<std::size_t>((t + 1) * columns + p)];
            const int left = p > 0 ? p - 1 : columns - 1;
            if (p > 0 || wrapJoins) b[n++] = bright[static_cast<std::size_t>(t * columns + left)];
            const int right = p + 1 < columns ? p + 1 : 0;
            if (p + 1 < columns || wrapJoins)
                b[n++] = bright[static_cast<std::size_t>(t * columns + right)];
            double mean = 0;
            for (int i = 0; i < n; ++i) mean += b[i];
            mean /= n;
            double var = 0;
            for (int i = 0; i < n; ++i) var += (b[i] - mean) * (b[i] - mean);
            priority[static_cast<std::size_t>(t * columns + p)] = var / n;
        }
    }
    return priority;
}

std::vector<int> AllotClassicSuperSamples(const std::vector<double>& bright, int rows,
                                          int columns, int count, Rng& rng) {
    // Priorities from each division's neighbours only, so that a division an
    // edge crosses has neighbours on both sides of it. Not Radiance's
    // estimate, which includes the division's own sample: then a division
    // whose first sample caught a small bright patch is refined (its mean
    // pulled down to the truth) while one that missed it stays dark, and the
    // hemisphere comes out low (README, "Differences"). Nor one normalisation
    // over all divisions: a division whose first sample caught a rare bright
    // ray (the sun through a BSDF window) raised its neighbours' priorities,
    // so lowered its own share and kept that ray at full weight: biased high
    // (README, "Differences"). Hence the checkerboard.
    return AllotCheckerboard(NeighbourVariance(bright, rows, columns, true), rows, columns,
                             count, rng, [](int, int budget, double) { return budget; });
}

}  // namespace detail

Hemisphere SampleHemisphere(const Vec3& normal, const HemisphereOptions& options, Rng& rng,
                            AmbientTraceRef trace) {
    RT_DCHECK(LengthSquared(normal) > 0);
    Hemisphere h;
    h.frame = RandomFrame(Normalize(normal), rng);
    const DivisionCounts counts = HemisphereDivisions(options);
    h.rows = counts.rows;
    h.columns = counts.columns;
    const int rows = h.rows;
    const int columns = h.columns;

    DivisionGrid divs(rows, columns);
    const DivisionDirections direction(h.frame, rows, columns);
    int failed = 0;
    for (int t = 0; t < rows; ++t) {
        for (int p = 0; p < columns; ++p) {
            const double xi0 = rng.Uniform();
            const double xi1 = rng.Uniform();
            ++h.raysTraced;
            const std::optional<Traced> s =
                TraceOne(trace, direction(t, p, xi0, xi1));
            if (!s) {
                ++failed;
                continue;
            }
            Division& d = divs.At(t, p);
            d.mean = s->radiance;
            d.samples = 1;
            d.nearestInverseDistance = s->inverseDistance;
            h.inverseDistanceSum += s->inverseDistance;
            ++h.distanceCount;
        }
    }
    h.complete = failed == 0;
    h.anySample = failed < rows * columns;

    // -as·weight, but at most one extra sample per division on average: the
    // priorities are fixed before any extra sample is taken, so beyond that the
    // extra samples only pile up in the same few divisions, and a larger -ad
    // spends them better (it also refines radii and gradients). Radiance has no
    // such clamp (README, Differences).
    const double extraWanted = std::max(0.0, options.superSamples * options.weight);
    const int extra = static_cast<int>(
        std::min(extraWanted, static_cast<double>(rows) * columns) + 0.5);
    if (h.complete && extra >= kMinSuperSamples && rows >= kMinSuperSampleRows) {
        std::vector<double> bright(static_cast<std::size_t>(divs.Size()));
        for (int i = 0; i < divs.Size(); ++i)
            bright[static_cast<std::size_t>(i)] = Bright(divs[i].mean);
        const std::vector<int> extraPerDivision =
            detail::AllotClassicSuperSamples(bright, rows, columns, extra, rng);
        for (int i = 0; i < divs.Size(); ++i) {
            const int t = i / columns;
            const int p = i % columns;
            for (int k = 0; k < extraPerDivision[static_cast<std::size_t>(i)]; ++k) {
                const double xi0 = rng.Uniform();
                const double xi1 = rng.Uniform();
                ++h.raysTraced;
                const std::optional<Traced> s =
                    TraceOne(trace, direction(t, p, xi0, xi1));
                if (!s) break;  // keeps the samples it has
                AddSuperSample(divs[i], *s);
            }
        }
    }

    // Only records use them (their corral bits): not computed without the cache.
    if (h.complete && options.caching) {
        h.horizonInverseDistance.resize(static_cast<size_t>(columns));
        for (int p = 0; p < columns; ++p) {
            h.horizonInverseDistance[static_cast<size_t>(p)] =
                divs.At(rows - 1, p).nearestInverseDistance;
        }
    }

    Rgb sum;
    for (const Division& d : divs.Cells())
        sum += d.mean;
    h.value = sum * (1.0 / (static_cast<double>(rows) * columns));

    const double b = Bright(h.value);
    // Only records and a turned shading normal use the gradients: without
    // the cache (-aa 0, a hemisphere per shading point) their per-column
    // sines and cosines would otherwise be wasted.
    if (h.complete && b > kFtiny && (options.caching || options.gradients)) {
        // Relative gradients: E = π·Ē, so ∇E / E = ∇E / (π·bright(Ē)).
        const double toRelative = 1.0 / (kPi * b);
        h.posGradient = TranslationalGradient(divs, h.frame) * toRelative;
        h.dirGradient = RotationalGradient(divs, h.frame) * toRelative;
        if (!IsFinite(h.posGradient))
            h.posGradient = Vec3();
        if (!IsFinite(h.dirGradient))
            h.dirGradient = Vec3();
    }
    return h;
}

std::optional<AmbientRecord> MakeClassicRecord(const Vec3& position, const Vec3& normal,
                                               const Hemisphere& hemisphere, int level,
                                               double weight, const AmbientLimits& limits) {
    if (!hemisphere.complete || !(weight > 0) || !IsFinite(hemisphere.value))
        return std::nullopt;
    Vec3 g = IsFinite(hemisphere.posGradient) ? hemisphere.posGradient : Vec3();
    const Vec3 gDir = IsFinite(hemisphere.dirGradient) ? hemisphere.dirGradient : Vec3();

    // Harmonic mean distance; Radiance's FTINY test treats "everything at
    // FHUGE" as nothing nearby.
    double radius = limits.maxRadius;
    if (hemisphere.distanceCount > 0 && hemisphere.inverseDistanceSum > kFtiny)
        radius = hemisphere.distanceCount / hemisphere.inverseDistanceSum;
    const double g2 = LengthSquared(g);
    // Where E changes fast the record must not reach further than 1/|g|.
    if (g2 * radius * radius > 1.0)
        radius = 1.0 / std::sqrt(g2);
    if (radius < limits.minRadius) {
        radius = limits.minRadius;
        // ...and at the minimum radius the gradient is trusted only up to |g|·R = 1.
        if (g2 * radius * radius > 1.0)
            g = g * (1.0 / (radius * std::sqrt(g2)));
    }
    // Weak records (deeper bounces) may be used further away (Radiance ≤ 4.2).
    radius /= std::sqrt(weight);
    radius = std::min(std::max(radius, limits.minRadius), limits.maxRadius);
    if (!(radius > 0) || !std::isfinite(radius))
        return std::nullopt;
    // The gradient is trusted only up to |g|·R = 1 for the radius actually
    // stored (Radiance 5 caps it the same way, after the weight): Radiance ≤
    // 4.2 capped it before dividing by sqrt(weight), so a deeper record could
    // extrapolate further than its gradient is good for (README,
    // "Differences"; docs/measured-choices.md).
    if (LengthSquared(g) * radius * radius > 1.0)
        g = g * (1.0 / (radius * std::sqrt(LengthSquared(g))));

    AmbientRecord rec;
    rec.position = position;
    rec.normal = normal;
    rec.uAxis = hemisphere.frame.u;
    const Vec3 v = rec.VAxis();
    rec.value = hemisphere.value;
    rec.radius[0] = rec.radius[1] = radius;
    rec.posGradient[0] = Dot(g, rec.uAxis);
    rec.posGradient[1] = Dot(g, v);
    rec.dirGradient[0] = Dot(gDir, rec.uAxis);
    rec.dirGradient[1] = Dot(gDir, v);
    rec.level = level;
    rec.weight = weight;
    rec.corral = 0;
    return rec;
}

}  // namespace rt
