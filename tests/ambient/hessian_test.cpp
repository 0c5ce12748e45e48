// SPDX-License-Identifier: MIT
//
// Physics tests of Radiance 5's hemisphere and records (ambient/hessian.cpp):
// the concentric map (bijection, area, cosine directions by chi²), the cell
// layout and collision rule, the form factor edge terms against finite
// differences of a triangle's exact form factor, analytic environments
// (uniform, parallel and tilted planes, a half-plane, a rectangle, a wall)
// against the analytic irradiance and its finite differences, the radius
// limits and their order, super-sampling, and failure cases.
#include "ambient/hessian.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <limits>
#include <random>
#include <optional>
#include <utility>
#include <vector>

#include "ambient/leak.h"
#include "ambient/ambient_options.h"
#include "core/conventions.h"
#include "tests/ambient/hemisphere_test_scenes.h"

namespace rt {
namespace {

using testing::Chi2Quantile, testing::ConstantEnvironment, testing::FrameAround,
    testing::HalfPlaneCeiling, testing::OffsetRectangle, testing::Options,
    testing::RectangleEmitter, testing::Tilt;

const Vec3 kUp(0, 0, 1);
const Vec3 kTiltedNormal = Normalize(Vec3(0.3, -0.5, 0.81));
/// Radiance's far limit for a scene cube of size 4.
const double kFar = HessianFarDistance(4.0);

AmbientLimits Limits(double minRadius, double maxRadius) {
    AmbientLimits l;
    l.minRadius = minRadius;
    l.maxRadius = maxRadius;
    return l;
}

std::optional<AmbientSample> Sample(double radiance, double distance) {
    return AmbientSample{Rgb::Grey(radiance), distance};
}

/// Inverse of the concentric map (without Radiance's 1 − 1e-13 radius scale):
/// the square point of a disc point.
std::pair<double, double> DiscToSquare(double x, double y) {
    const double r = std::hypot(x, y);
    double phi = std::atan2(y, x);
    if (phi < -0.25 * kPi)
        phi += 2 * kPi;
    double a, b;
    if (phi < 0.25 * kPi) {
        a = r;
        b = a * phi * 4 / kPi;
    } else if (phi < 0.75 * kPi) {
        b = r;
        a = b * (2 - phi * 4 / kPi);
    } else if (phi < 1.25 * kPi) {
        a = -r;
        b = a * (phi * 4 / kPi - 4);
    } else {
        b = -r;
        a = b * (6 - phi * 4 / kPi);
    }
    return {0.5 * (a + 1), 0.5 * (b + 1)};
}

constexpr double kRadiusScale = 0.9999999999999;

/// The cell (i, j) whose square a unit direction maps back to, in `h`'s frame.
std::pair<int, int> CellOf(const HessianHemisphere& h, const Vec3& dir) {
    const Vec3 l = h.frame.ToLocal(dir);
    const auto [x, y] = DiscToSquare(l.x / kRadiusScale, l.y / kRadiusScale);
    const int j = std::clamp(static_cast<int>(std::floor(x * h.ns)), 0, h.ns - 1);
    const int i = std::clamp(static_cast<int>(std::floor(y * h.ns)), 0, h.ns - 1);
    return {i, j};
}

double Chi2(const std::vector<double>& counts, const std::vector<double>& expected) {
    double chi2 = 0;
    for (std::size_t k = 0; k < counts.size(); ++k)
        chi2 += (counts[k] - expected[k]) * (counts[k] - expected[k]) / expected[k];
    return chi2;
}

/// Chi² of `points` in the unit disc against the uniform density, over 8
/// rings of equal area × 16 sectors (offset so as not to align with the
/// concentric map's region boundaries at odd multiples of π/4).
double DiscUniformityChi2(const std::vector<DiscPoint>& points) {
    constexpr int kRings = 8, kSectors = 16;
    std::vector<double> counts(kRings * kSectors, 0.0);
    for (const DiscPoint& p : points) {
        const int ring = std::min(kRings - 1, static_cast<int>((p.x * p.x + p.y * p.y) * kRings));
        double phi = std::atan2(p.y, p.x) + 0.3;
        phi -= 2 * kPi * std::floor(phi / (2 * kPi));
        const int sector = std::min(kSectors - 1, static_cast<int>(phi / (2 * kPi) * kSectors));
        ++counts[static_cast<std::size_t>(ring * kSectors + sector)];
    }
    const std::vector<double> expected(counts.size(),
                                       static_cast<double>(points.size()) / counts.size());
    return Chi2(counts, expected);
}

/// Stratified jittered points: `n` × `n` strata, `passes` points in each.
std::vector<std::pair<double, double>> StratifiedSquare(int n, int passes, Rng& rng) {
    std::vector<std::pair<double, double>> out;
    for (int pass = 0; pass < passes; ++pass) {
        for (int i = 0; i < n; ++i) {
            for (int j = 0; j < n; ++j)
                out.emplace_back((j + rng.Uniform()) / n, (i + rng.Uniform()) / n);
        }
    }
    return out;
}

// ---------------------------------------------------------------------------
// The concentric map.

// Both ways round: square → disc → square and disc → square → disc are the
// identity, so the map is one-to-one and onto; every image lies strictly
// inside the unit disc (the 1 − 1e-13 scale keeps directions off the horizon).
TEST(ConcentricMap, IsABijectionOfSquareAndDisc) {
    Rng rng(17);
    double worstSquare = 0, worstDisc = 0;
    for (int k = 0; k < 100000; ++k) {
        const double x = rng.Uniform(), y = rng.Uniform();
        const DiscPoint p = SquareToDisc(x, y);
        ASSERT_LT(p.x * p.x + p.y * p.y, 1.0);
        const auto [bx, by] = DiscToSquare(p.x / kRadiusScale, p.y / kRadiusScale);
        worstSquare = std::max({worstSquare, std::fabs(bx - x), std::fabs(by - y)});

        const double r = std::sqrt(rng.Uniform()), phi = 2 * kPi * rng.Uniform();
        const auto [sx, sy] = DiscToSquare(r * std::cos(phi), r * std::sin(phi));
        ASSERT_GE(sx, -1e-12);
        ASSERT_LE(sx, 1 + 1e-12);
        ASSERT_GE(sy, -1e-12);
        ASSERT_LE(sy, 1 + 1e-12);
        const DiscPoint q = SquareToDisc(sx, sy);
        worstDisc = std::max({worstDisc, std::fabs(q.x / kRadiusScale - r * std::cos(phi)),
                              std::fabs(q.y / kRadiusScale - r * std::sin(phi))});
    }
    EXPECT_LT(worstSquare, 1e-12);
    EXPECT_LT(worstDisc, 1e-12);
    // The square's centre and corners.
    const DiscPoint c = SquareToDisc(0.5, 0.5);
    EXPECT_EQ(c.x, 0.0);
    EXPECT_EQ(c.y, 0.0);
    const DiscPoint corner = SquareToDisc(1.0, 1.0);
    EXPECT_NEAR(corner.x, std::sqrt(0.5), 1e-12);
    EXPECT_NEAR(corner.y, std::sqrt(0.5), 1e-12);
}

// The Hessian's edge terms take the angle between neighbouring hit points
// from a series below 14°: within two ulps of std::atan over its whole range.
TEST(HessianEdge, AtanSmallMatchesTheLibrary) {
    double worst = 0;
    for (int k = -100000; k <= 100000; ++k) {
        const double x = 0.25 * k / 100000.0;
        if (x == 0) continue;
        worst = std::max(worst, std::fabs(detail::AtanSmall(x) - std::atan(x)) / std::fabs(std::atan(x)));
    }
    EXPECT_EQ(detail::AtanSmall(0.0), 0.0);
    EXPECT_LT(worst, 4.5e-16);
}

// The angle between two hit points over the sine's length, for every angle
// (series below 14°, series after a shift up to 56°, the library beyond):
// within three ulps of std::atan2, and continuous where the methods meet.
TEST(HessianEdge, AngleOverSineMatchesTheLibrary) {
    double worst = 0;
    for (int k = 1; k < 200000; ++k) {
        const double angle = kPi * k / 200000.0;
        for (const double scale : {1.0, 3.7e-4, 2.9e3}) {
            const double r01 = scale * std::cos(angle);
            const double rc = scale * std::sin(angle);
            const double got = detail::AngleOverSine(r01, rc * rc);
            const double want = std::atan2(rc, r01) / rc;
            worst = std::max(worst, std::fabs(got - want) / want);
        }
    }
    EXPECT_LT(worst, 6e-16);
}

// SquareToDisc evaluates sin and cos by series on a quarter turn: it must agree
// with Shirley & Chiu's formula through std::cos/std::sin to within the
// rounding of that formula's own angle (about 1e-15 at φ near 2π).
TEST(ConcentricMap, MatchesTheTrigonometricFormula) {
    Rng rng(29);
    double worst = 0;
    for (int k = 0; k < 200000; ++k) {
        const double x = rng.Uniform(), y = rng.Uniform();
        const double a = 2 * x - 1, b = 2 * y - 1;
        double r, phi;
        if (a > -b) {
            if (a > b) { r = a; phi = 0.25 * kPi * (b / a); }
            else { r = b; phi = 0.25 * kPi * (2 - a / b); }
        } else {
            if (a < b) { r = -a; phi = 0.25 * kPi * (4 + b / a); }
            else { r = -b; phi = b != 0 ? 0.25 * kPi * (6 - a / b) : 0; }
        }
        r *= kRadiusScale;
        const DiscPoint p = SquareToDisc(x, y);
        worst = std::max({worst, std::fabs(p.x - r * std::cos(phi)), std::fabs(p.y - r * std::sin(phi))});
    }
    EXPECT_LT(worst, 3e-15);
}

// Area preservation: stratified points in the square land uniformly on the
// disc. Stratification only lowers chi² below the multinomial value, but a map
// that distorts area moves whole strata between bins: the polar map
// (r = x, φ = 2πy), which is one-to-one too, fails the same test by far.
TEST(ConcentricMap, PreservesAreaChi2) {
    Rng rng(3);
    const auto square = StratifiedSquare(256, 4, rng);
    std::vector<DiscPoint> concentric, polar;
    for (const auto& [x, y] : square) {
        concentric.push_back(SquareToDisc(x, y));
        polar.push_back({x * std::cos(2 * kPi * y), x * std::sin(2 * kPi * y)});
    }
    const double limit = Chi2Quantile(8 * 16 - 1, 3.09);
    const double chi2 = DiscUniformityChi2(concentric);
    const double chi2Polar = DiscUniformityChi2(polar);
    std::cout << "disc chi2 concentric " << chi2 << " polar " << chi2Polar << " (limit " << limit
              << ")\n";
    EXPECT_LT(chi2, limit);
    EXPECT_GT(chi2Polar, 100 * limit);
}

// The sampled directions, pooled over many hemispheres and measured in a fixed
// frame (so the random frame is part of the test), follow the cosine pdf: cosθ
// has CDF cos²θ, φ is uniform and the joint histogram is their product.
// Neither binning lines up with the 8 × 8 cells.
TEST(HessianHemisphere, DirectionsFollowCosineDistributionChi2) {
    constexpr int kThetaBins = 10, kPhiBins = 12;
    const Frame fixed = FrameAround(kTiltedNormal);
    std::vector<double> counts(kThetaBins * kPhiBins, 0.0);
    long total = 0;
    const AmbientTraceFn trace = [&](const Vec3& d) {
        const auto [ti, pi] = testing::BinOf(fixed, d, kThetaBins, kPhiBins);
        ++counts[static_cast<std::size_t>(ti * kPhiBins + pi)];
        ++total;
        return Sample(1, 1);
    };
    Rng rng(20240607);
    for (int i = 0; i < 2000; ++i) {
        const HessianHemisphere h =
            SampleHessianHemisphere({}, kTiltedNormal, Options(64, 0), kFar, rng, trace);
        ASSERT_EQ(h.ns, 8);
    }
    ASSERT_EQ(total, 128000);
    std::vector<double> expected;
    for (int i = 0; i < kThetaBins; ++i) {
        const double lo = static_cast<double>(i) / kThetaBins, hi = (i + 1.0) / kThetaBins;
        for (int j = 0; j < kPhiBins; ++j)
            expected.push_back(total * (hi * hi - lo * lo) / kPhiBins);
    }
    const double chi2 = Chi2(counts, expected);
    const double limit = Chi2Quantile(kThetaBins * kPhiBins - 1, 3.09);
    std::cout << "cosine chi2 " << chi2 << " (limit " << limit << ")\n";
    EXPECT_LT(chi2, limit);
}

// ---------------------------------------------------------------------------
// Layout, frame and the collision rule.

TEST(HessianHemisphere, DivisionsFollowRadiance) {
    EXPECT_EQ(HessianDivisions(Options(1024, 0)), 32);
    EXPECT_EQ(HessianDivisions(Options(1024, 0, 0.5)), 23);  // sqrt(512) = 22.6
    EXPECT_EQ(HessianDivisions(Options(1024, 0, 0.25)), 16);
    EXPECT_EQ(HessianDivisions(Options(1024, 0, 0.125)), 11);  // sqrt(128) = 11.3
    EXPECT_EQ(HessianDivisions(Options(16, 0)), 7);            // MINADIV with the cache
    EXPECT_EQ(HessianDivisions(Options(16, 0, 1, false)), 4);  // ...not without
    EXPECT_EQ(HessianDivisions(Options(0, 0, 1, false)), 1);
    EXPECT_EQ(HessianDivisions(Options(1024, 0, std::nan(""))), 7);
    EXPECT_EQ(HessianDivisions(Options(std::numeric_limits<int>::max(), 0)), 2048);
    EXPECT_LE(2048 * 2048, kMaxAmbientDivisions);
}

// Each cell's first sample lies in that cell's square, read back through the
// inverse map in the hemisphere's frame; the frame is right-handed and
// orthonormal with v = n × u; Ē is the mean over the cells.
TEST(HessianHemisphere, OneSamplePerCellInItsSquare) {
    Rng rng(8);
    const double distance = 2.5;
    const HessianHemisphere h =
        SampleHessianHemisphere(Vec3(1, 2, 3), kTiltedNormal, Options(400, 0), kFar, rng,
                                ConstantEnvironment(Rgb(0.2, 0.4, 0.6), distance));
    ASSERT_TRUE(h.complete);
    ASSERT_EQ(h.ns, 20);
    EXPECT_EQ(h.raysTraced, 400);
    EXPECT_EQ(h.superSamples, 0);
    EXPECT_EQ(h.point, Vec3(1, 2, 3));
    EXPECT_NEAR(Dot(h.frame.n, kTiltedNormal), 1.0, 1e-15);
    EXPECT_NEAR(Length(h.frame.u), 1.0, 1e-15);
    EXPECT_NEAR(Dot(h.frame.u, h.frame.n), 0.0, 1e-15);
    EXPECT_LT(Length(h.frame.v - Cross(h.frame.n, h.frame.u)), 1e-15);
    for (int i = 0; i < h.ns; ++i) {
        for (int j = 0; j < h.ns; ++j) {
            const HessianCell& c = h.At(i, j);
            ASSERT_EQ(c.samples, 1);
            EXPECT_NEAR(Length(c.offset), distance, 1e-12);
            EXPECT_EQ(c.inverseDistance, 1 / distance);
            EXPECT_GT(Dot(c.offset, h.frame.n), 0.0);
            EXPECT_EQ(CellOf(h, c.offset / distance), std::make_pair(i, j));
        }
    }
}

// Neighbouring cells' first samples are never within π/(4ns) of each other
// (Radiance's ambcollision), which keeps the triangles between them from
// degenerating; without the re-draws, some pairs come closer at ns = 8.
TEST(HessianHemisphere, NeighbouringFirstSamplesAreApart) {
    double closest = 1e300;
    for (std::uint64_t seed = 0; seed < 40; ++seed) {
        Rng rng(seed);
        const HessianHemisphere h = SampleHessianHemisphere(
            {}, kTiltedNormal, Options(64, 0), kFar, rng, ConstantEnvironment(Rgb::Grey(1), 1));
        for (int i = 0; i < h.ns; ++i) {
            for (int j = 0; j < h.ns; ++j) {
                for (int ii = i; ii <= std::min(h.ns - 1, i + 1); ++ii) {
                    for (int jj = std::max(0, j - 1); jj <= std::min(h.ns - 1, j + 1); ++jj) {
                        if (ii == i && jj <= j)
                            continue;
                        const Vec3 a = h.At(i, j).offset, b = h.At(ii, jj).offset;
                        const double angle = std::atan2(Length(Cross(a, b)), Dot(a, b));
                        closest = std::min(closest, angle / (kPi / (4 * h.ns)));
                    }
                }
            }
        }
    }
    std::cout << "closest neighbours: " << closest << " × π/(4ns)\n";
    // The rule compares cosines against 1 − θ²/2, which lets pairs come
    // slightly (< 0.1%) closer than π/(4ns).
    EXPECT_GT(closest, 0.999);
}

TEST(HessianHemisphere, SameSeedGivesSameResult) {
    HalfPlaneCeiling scene;
    scene.worldFromLocal = FrameAround(kTiltedNormal);
    Rng a(42), b(42);
    const HessianHemisphere ha =
        SampleHessianHemisphere({}, kTiltedNormal, Options(1024, 512), kFar, a, scene.At({}));
    const HessianHemisphere hb =
        SampleHessianHemisphere({}, kTiltedNormal, Options(1024, 512), kFar, b, scene.At({}));
    EXPECT_EQ(ha.value, hb.value);
    EXPECT_EQ(ha.raysTraced, hb.raysTraced);
    EXPECT_EQ(MakeHessianRecord(ha, 0, 1, 0.1, Limits(0.01, 1)),
              MakeHessianRecord(hb, 0, 1, 0.1, Limits(0.01, 1)));
}

// ---------------------------------------------------------------------------
// The form factor edge terms (§4.7 step 2) against a triangle's exact form
// factor F = (1/2π)·Σ angle(r0, r1)·n·unit(r0 × r1).

double TriangleFormFactor(const std::array<Vec3, 3>& p, const Vec3& point, const Vec3& n) {
    double f = 0;
    for (int k = 0; k < 3; ++k) {
        const Vec3 a = p[k] - point, b = p[(k + 1) % 3] - point;
        const Vec3 c = Cross(a, b);
        f += std::atan2(Length(c), Dot(a, b)) * Dot(n, c) / Length(c);
    }
    return f / (2 * kPi);
}

// The gradient terms sum to the gradient of F with respect to the point; the
// Hessian terms to the *negated* Hessian of F. That sign is Radiance's (its
// comp_hessian() and the notes' formula both carry it); it does not change the
// radii, which use |λ|, only which eigenvector the frame rotation picks, so it
// is kept. Central differences, step 1e-4 on triangles about 1 away:
// truncation error near 1e-8.
TEST(HessianEdges, SumToTheFormFactorDerivativesOfATriangle) {
    Rng rng(5);
    for (int trial = 0; trial < 20; ++trial) {
        const Vec3 n = Normalize(Vec3(rng.Uniform() - 0.5, rng.Uniform() - 0.5, 1.0));
        const Frame f = FrameAround(n);
        // A counter-clockwise triangle (seen from +n) wholly above the plane.
        std::array<Vec3, 3> p;
        for (int k = 0; k < 3; ++k) {
            const double phi = 2 * kPi * (k + 0.8 * rng.Uniform()) / 3;
            const double r = 0.2 + rng.Uniform(), height = 0.3 + rng.Uniform();
            p[k] = f.ToWorld({r * std::cos(phi), r * std::sin(phi), height});
        }
        Vec3 gradient;
        Matrix3 hessian;
        for (int k = 0; k < 3; ++k) {
            const detail::FormFactorEdge e = detail::FormFactorEdgeTerms(p[k], p[(k + 1) % 3], n);
            gradient += e.gradient;
            for (int a = 0; a < 3; ++a) {
                for (int b = 0; b < 3; ++b)
                    hessian.m[a][b] += e.hessian.m[a][b];
            }
        }
        ASSERT_GT(TriangleFormFactor(p, {}, n), 0.0);
        const double d = 1e-4;
        double scale = 0;
        Vec3 fdGradient;
        Matrix3 fdHessian;
        for (int a = 0; a < 3; ++a) {
            Vec3 ea;
            ea[a] = d;
            fdGradient[a] =
                (TriangleFormFactor(p, ea, n) - TriangleFormFactor(p, -ea, n)) / (2 * d);
            for (int b = 0; b < 3; ++b) {
                Vec3 eb;
                eb[b] = d;
                fdHessian.m[a][b] =
                    (TriangleFormFactor(p, ea + eb, n) - TriangleFormFactor(p, ea - eb, n) -
                     TriangleFormFactor(p, eb - ea, n) + TriangleFormFactor(p, -ea - eb, n)) /
                    (4 * d * d);
                scale = std::max(scale, std::fabs(fdHessian.m[a][b]));
            }
        }
        EXPECT_LT(Length(gradient - fdGradient), 1e-7 * Length(fdGradient)) << trial;
        for (int a = 0; a < 3; ++a) {
            for (int b = 0; b < 3; ++b)
                EXPECT_NEAR(hessian.m[a][b], -fdHessian.m[a][b], 1e-6 * scale) << trial;
        }
    }
}

// ---------------------------------------------------------------------------
// Analytic environments.

struct Tangent2 {
    double xx = 0, xy = 0, yy = 0;
};
Tangent2 Project(const Matrix3& h, const Vec3& x, const Vec3& y) {
    return {h.Form(x, x), h.Form(x, y), h.Form(y, y)};
}

// Every ray returns the same radiance from far away (a miss, stored at the
// far limit): Ē is that radiance (to rounding), the Hessian and translational
// gradient vanish (the only geometry is the far boundary of the triangulated
// grid), so both radii are the maximum and the gradient 0. Radiance's
// rotational gradient is 0 in expectation only: it weights each sample by its
// own tanθ, which the concentric map lets reach 2e6 next to the horizon, so
// single hemispheres scatter widely (and, interpolated across a curved
// surface's normals, made the sphere furnace up to 1.2e-3 off). A uniform
// hemisphere's records get none: exactly 0 for each of 200 hemispheres.
TEST(HessianRecord, UniformEnvironmentHasMaximumRadiiAndNoGradient) {
    const Rgb sky(0.3, 0.5, 0.7);
    const AmbientLimits limits = Limits(0.01, 0.8);
    constexpr int kRuns = 200;
    for (int run = 0; run < kRuns; ++run) {
        Rng rng(11, static_cast<std::uint64_t>(run));
        const HessianHemisphere h =
            SampleHessianHemisphere(Vec3(1, 1, 0), kTiltedNormal, Options(1024, 512), kFar, rng,
                                    ConstantEnvironment(sky, kFhuge));
        ASSERT_TRUE(h.complete);
        // Exact up to the rounding of a mean over 1024 cells.
        for (int c = 0; c < 3; ++c)
            ASSERT_NEAR(h.value[c], sky[c], 1e-13 * sky[c]) << c;
        EXPECT_EQ(h.superSamples, 0);  // nothing differs
        for (const HessianCell& c : h.cells)
            ASSERT_NEAR(Length(c.offset), kFar, 1e-12 * kFar);
        const HessianEstimate est = EstimateHessian(h);
        EXPECT_LT(Length(est.gradient - kTiltedNormal * Dot(est.gradient, kTiltedNormal)),
                  1e-4 / limits.maxRadius);
        const auto rec = MakeHessianRecord(h, 0, 1.0, 0.1, limits);
        ASSERT_TRUE(rec.has_value());
        EXPECT_EQ(rec->radius[0], limits.maxRadius);
        EXPECT_EQ(rec->radius[1], limits.maxRadius);
        EXPECT_LT(std::hypot(rec->posGradient[0], rec->posGradient[1]) * limits.maxRadius, 1e-4);
        EXPECT_EQ(rec->corral, 0u);
        EXPECT_EQ(rec->value, h.value);
        EXPECT_EQ(rec->dirGradient[0], 0.0);
        EXPECT_EQ(rec->dirGradient[1], 0.0);
    }
}

/// An infinite emitting plane n_p·x = height (height > 0 from the origin) of
/// radiance `radiance`; everything else a black miss.
struct TiltedPlane {
    Vec3 planeNormal;  // unit, pointing from the receiver toward the plane
    double height = 1;
    double radiance = 1;

    AmbientTraceFn At(const Vec3& point) const {
        const TiltedPlane s = *this;
        return [s, point](const Vec3& d) {
            const double c = Dot(d, s.planeNormal);
            if (c > 0)
                return Sample(s.radiance, (s.height - Dot(point, s.planeNormal)) / c);
            return Sample(0, kFhuge);
        };
    }
    /// Irradiance for unit normal n: the plane fills the directions with
    /// ω·n_p > 0, whatever its distance, so E = πL·(1 + n·n_p)/2.
    double Irradiance(const Vec3& n) const {
        return kPi * radiance * 0.5 * (1 + Dot(n, planeNormal));
    }
};

// A plane parallel to the receiver fills the hemisphere: Ē = L exactly, and
// the irradiance does not depend on where the receiver is, so the gradient and
// the Hessian are 0. The triangulated grid stops a fraction of a cell short of
// the horizon, leaving a ring the estimate misses; it must stay below 1% of
// the plane's natural scale (|g|·h, and 2% for |H|·h²) at 32 × 32 cells, and
// the curvature must shrink with more cells.
TEST(HessianRecord, ParallelPlaneHasNoGradientOrCurvature) {
    TiltedPlane plane;
    plane.planeNormal = kTiltedNormal;
    plane.height = 0.5;
    plane.radiance = 2;
    double previous = 1e300;
    for (int divisions : {1024, 16384}) {
        Rng rng(4);
        const HessianHemisphere h = SampleHessianHemisphere(
            {}, kTiltedNormal, Options(divisions, 512), kFar, rng, plane.At({}));
        EXPECT_EQ(h.value, Rgb::Grey(2));
        const HessianEstimate est = EstimateHessian(h);
        const Tangent2 t = Project(est.hessian, h.frame.u, h.frame.v);
        const double curvature = std::max({std::fabs(t.xx), std::fabs(t.xy), std::fabs(t.yy)});
        const double tangentGradient =
            std::hypot(Dot(est.gradient, h.frame.u), Dot(est.gradient, h.frame.v));
        std::cout << "parallel plane ns " << h.ns << ": |g|·h " << tangentGradient * plane.height
                  << " |H|·h² " << curvature * plane.height * plane.height << "\n";
        EXPECT_LT(tangentGradient * plane.height, 0.01);
        EXPECT_LT(curvature * plane.height * plane.height, 0.02);
        EXPECT_LT(curvature, previous);
        previous = curvature;
    }
}

// A tilted infinite plane (45° from the normal here) covers a half-space of
// directions: E = πL(1 + cos α)/2 wherever the receiver is, so again no
// translational gradient or curvature, but rotating the normal changes E. The
// rotational gradient's mean over 64 hemispheres (each 64 × 64) must match
// 0.99 × the central difference (δ = 1e-4 rad) of the analytic E within 4
// standard errors plus 1%; Ē within the stratification noise (0.3%).
TEST(HessianRecord, TiltedPlaneMatchesAnalyticIrradianceAndRotation) {
    const Frame f = FrameAround(kTiltedNormal);
    TiltedPlane plane;
    plane.planeNormal = Tilt(f.n, Normalize(f.u * 0.6 + f.v * 0.8), 0.25 * kPi);
    plane.height = 0.7;
    plane.radiance = 3;
    const double e0 = plane.Irradiance(f.n);
    const double d = 1e-4;
    // Relative change per radian of turning the normal about f.u and f.v.
    double reference[2];
    for (int k = 0; k < 2; ++k) {
        const Vec3 axis = k == 0 ? f.u : f.v;
        const Vec3 toward = Cross(axis, f.n);
        reference[k] =
            (plane.Irradiance(Tilt(f.n, toward, d)) - plane.Irradiance(Tilt(f.n, toward, -d))) /
            (2 * d) / e0;
    }
    constexpr int kRuns = 64;
    double sum[2] = {0, 0}, sumSq[2] = {0, 0}, value = 0, worstCurvature = 0, worstGradient = 0;
    for (int run = 0; run < kRuns; ++run) {
        Rng rng(21, static_cast<std::uint64_t>(run));
        const HessianHemisphere h =
            SampleHessianHemisphere({}, f.n, Options(4096, 0), kFar, rng, plane.At({}));
        value += kPi * Bright(h.value) / kRuns;
        const auto g = HessianRotationalGradient(h, f.u, f.v);
        ASSERT_TRUE(g.has_value());
        for (int k = 0; k < 2; ++k) {
            sum[k] += (*g)[k];
            sumSq[k] += (*g)[k] * (*g)[k];
        }
        const HessianEstimate est = EstimateHessian(h);
        const Tangent2 t = Project(est.hessian, f.u, f.v);
        worstCurvature =
            std::max({worstCurvature, std::fabs(t.xx), std::fabs(t.xy), std::fabs(t.yy)});
        worstGradient =
            std::max(worstGradient, std::hypot(Dot(est.gradient, f.u), Dot(est.gradient, f.v)));
    }
    std::cout << "tilted plane: E rel err " << value / e0 - 1 << ", |g|·h "
              << worstGradient * plane.height << ", |H|·h² "
              << worstCurvature * plane.height * plane.height << "\n";
    EXPECT_NEAR(value, e0, 3e-3 * e0);
    EXPECT_LT(worstGradient * plane.height, 0.01);
    EXPECT_LT(worstCurvature * plane.height * plane.height, 0.05);
    for (int k = 0; k < 2; ++k) {
        const double mean = sum[k] / kRuns;
        const double se = std::sqrt((sumSq[k] / kRuns - mean * mean) / kRuns);
        const double expected = 0.99 * reference[k];
        std::cout << "tilted plane: gdir[" << k << "] " << mean << " ± " << se << " expect "
                  << expected << "\n";
        EXPECT_NEAR(mean, expected, 4 * se + 0.01 * std::hypot(reference[0], reference[1]));
    }
}

/// Relative gradient (local x, y, z) and relative tangent Hessian (local xx,
/// xy, yy) of `irradiance(localPoint)` by central differences with step d.
template <typename F>
std::pair<Vec3, Tangent2> RelativeDerivatives(F irradiance, const Vec3& p, double d) {
    const Vec3 ex(d, 0, 0), ey(0, d, 0);
    const double e0 = irradiance(p);
    const Vec3 ez(0, 0, d);
    Vec3 g((irradiance(p + ex) - irradiance(p - ex)) / (2 * d) / e0,
           (irradiance(p + ey) - irradiance(p - ey)) / (2 * d) / e0,
           (irradiance(p + ez) - irradiance(p - ez)) / (2 * d) / e0);
    Tangent2 h;
    h.xx = (irradiance(p + ex) - 2 * e0 + irradiance(p - ex)) / (d * d) / e0;
    h.yy = (irradiance(p + ey) - 2 * e0 + irradiance(p - ey)) / (d * d) / e0;
    h.xy = (irradiance(p + ex + ey) - irradiance(p + ex - ey) - irradiance(p - ex + ey) +
            irradiance(p - ex - ey)) /
           (4 * d * d) / e0;
    return {g, h};
}

/// Mean translational gradient (local frame) and tangent Hessian (local axes)
/// of the estimate over `runs` hemispheres, divided by Radiance's 0.99.
struct MeanEstimate {
    Vec3 gradient;
    Tangent2 hessian;
    double value = 0;  // mean πĒ
};
MeanEstimate AverageEstimate(const Frame& worldFromLocal, const AmbientTraceFn& trace,
                             int divisions, int superSamples, int runs, std::uint64_t seed) {
    MeanEstimate m;
    const Vec3 x = worldFromLocal.u, y = worldFromLocal.v;
    for (int run = 0; run < runs; ++run) {
        Rng rng(seed, static_cast<std::uint64_t>(run));
        const HessianHemisphere h = SampleHessianHemisphere(
            {}, worldFromLocal.n, Options(divisions, superSamples), kFar, rng, trace);
        EXPECT_TRUE(h.complete);
        const HessianEstimate est = EstimateHessian(h);
        const double s = 1.0 / (0.99 * runs);
        m.gradient += worldFromLocal.ToLocal(est.gradient) * s;
        const Tangent2 t = Project(est.hessian, x, y);
        m.hessian.xx += t.xx * s;
        m.hessian.xy += t.xy * s;
        m.hessian.yy += t.yy * s;
        m.value += kPi * Bright(h.value) / runs;
    }
    return m;
}

double HessianError(const Tangent2& estimate, const Tangent2& negatedReference) {
    return std::max({std::fabs(estimate.xx + negatedReference.xx),
                     std::fabs(estimate.xy + negatedReference.xy),
                     std::fabs(estimate.yy + negatedReference.yy)});
}
double Largest(const Tangent2& t) {
    return std::max({std::fabs(t.xx), std::fabs(t.xy), std::fabs(t.yy)});
}

// A rectangle emitter off to one side (both gradient components, every
// Hessian entry non-zero). References: central differences of the exact
// irradiance (Lambert's polygon formula) for moves of the receiver and turns
// of its normal. The triangulated grid gives each triangle its farthest
// vertex's value, so the emitter it sees is shrunk by about a cell along its
// edges: the translational estimates converge as 1/ns, while the rotational
// one, from the samples alone, is unbiased. Without super-sampling, averaged over
// 8 hemispheres of 256 × 256: gradient within 4% of |g|, Hessian within 4% of
// its largest entry, with Radiance's sign; the error must be at least halved
// from 64 × 64; rotational gradient within 1%.
TEST(HessianRecord, RectangleEmitterMatchesFiniteDifferences) {
    const RectangleEmitter scene = OffsetRectangle(FrameAround(kTiltedNormal));
    const Vec3 p(0.05, -0.1, 0);
    const auto [gRef, hRef] =
        RelativeDerivatives([&](const Vec3& q) { return scene.Irradiance(q, kUp); }, p, 1e-3);
    const double e0 = scene.Irradiance(p, kUp);
    double dirRef[2];
    for (int k = 0; k < 2; ++k) {
        Vec3 axis;
        axis[k] = 1;
        const Vec3 toward = Cross(axis, kUp);
        dirRef[k] = (scene.Irradiance(p, Tilt(kUp, toward, 1e-4)) -
                     scene.Irradiance(p, Tilt(kUp, toward, -1e-4))) /
                    2e-4 / e0;
    }
    const MeanEstimate coarse = AverageEstimate(scene.worldFromLocal, scene.At(p), 4096, 0, 8, 31);
    const MeanEstimate fine = AverageEstimate(scene.worldFromLocal, scene.At(p), 65536, 0, 8, 31);
    // The record keeps the tangent components; the normal one (moving off
    // the surface) is checked too, the estimator being three-dimensional.
    const Vec3 tangentRef(gRef.x, gRef.y, 0);
    auto tangent = [](const Vec3& g) { return Vec3(g.x, g.y, 0); };
    const double coarseG = Length(tangent(coarse.gradient) - tangentRef);
    const double fineG = Length(tangent(fine.gradient) - tangentRef);
    const double coarseH = HessianError(coarse.hessian, hRef);
    const double fineH = HessianError(fine.hessian, hRef);
    std::cout << "rectangle: g ref " << gRef << " ns 64 " << coarse.gradient << " ns 256 "
              << fine.gradient << "\n  H ref " << hRef.xx << " " << hRef.xy << " " << hRef.yy
              << "; ns 256 " << fine.hessian.xx << " " << fine.hessian.xy << " " << fine.hessian.yy
              << "; errors ns 64/256: g " << coarseG / Length(tangentRef) << " / "
              << fineG / Length(tangentRef) << ", H " << coarseH / Largest(hRef) << " / "
              << fineH / Largest(hRef) << "\n";
    EXPECT_NEAR(fine.value, e0, 2e-3 * e0);
    EXPECT_LT(fineG, 0.04 * Length(tangentRef));
    EXPECT_NEAR(fine.gradient.z, gRef.z, 0.04 * Length(gRef));
    EXPECT_LT(fineH, 0.04 * Largest(hRef));
    EXPECT_LT(fineG, 0.5 * coarseG);
    EXPECT_LT(fineH, 0.5 * coarseH);

    // The rotational gradient needs no triangles: 8 hemispheres of 32 × 32.
    double dir[2] = {0, 0};
    const Frame& w = scene.worldFromLocal;
    for (int run = 0; run < 8; ++run) {
        Rng rng(5, static_cast<std::uint64_t>(run));
        const HessianHemisphere h =
            SampleHessianHemisphere({}, w.n, Options(1024, 0), kFar, rng, scene.At(p));
        const auto g = HessianRotationalGradient(h, w.u, w.v);
        ASSERT_TRUE(g.has_value());
        dir[0] += (*g)[0] / (0.99 * 8);
        dir[1] += (*g)[1] / (0.99 * 8);
    }
    std::cout << "rectangle: gdir " << dir[0] << " " << dir[1] << " ref " << dirRef[0] << " "
              << dirRef[1] << "\n";
    const double dirScale = std::hypot(dirRef[0], dirRef[1]);
    EXPECT_NEAR(dir[0], dirRef[0], 0.01 * dirScale);
    EXPECT_NEAR(dir[1], dirRef[1], 0.01 * dirScale);
}

// The half-plane emitter z = h, x > 0 of hemisphere_test.cpp: E = πL/2·(1 +
// x/√(x²+h²)) on the floor, so the gradient is along x only and the Hessian
// has only an xx entry, non-zero off the edge (x = 0.4h here, where it is
// negative). Same tolerances as for the rectangle; the estimated yy and xy
// entries must stay within 4% of |xx|.
TEST(HessianRecord, HalfPlaneEdgeMatchesFiniteDifferences) {
    HalfPlaneCeiling scene;
    scene.worldFromLocal = FrameAround(kUp);
    scene.height = 1;
    scene.radiance = 3;
    const double x = 0.4;
    const auto [gRef, hRef] = RelativeDerivatives(
        [&](const Vec3& q) { return scene.Irradiance(q.x); }, Vec3(x, 0, 0), 1e-3);
    EXPECT_NEAR(gRef.x, scene.RelativeGradientX(x), 1e-6);
    const MeanEstimate m =
        AverageEstimate(scene.worldFromLocal, scene.At(Vec3(x, 0, 0)), 65536, 0, 8, 77);
    std::cout << "half-plane: g " << m.gradient << " ref " << gRef << "; H " << m.hessian.xx << " "
              << m.hessian.xy << " " << m.hessian.yy << " ref(negated) " << -hRef.xx << "\n";
    EXPECT_NEAR(m.value, scene.Irradiance(x), 2e-3 * scene.Irradiance(x));
    EXPECT_LT(std::hypot(m.gradient.x - gRef.x, m.gradient.y), 0.04 * gRef.x);
    EXPECT_LT(HessianError(m.hessian, hRef), 0.04 * std::fabs(hRef.xx));
}

// ---------------------------------------------------------------------------
// A wall beside the receiver.

/// A black block x > distance, z < height (local frame, floor at z = 0) under
/// a sky of radiance 1 that is a miss.
AmbientTraceFn WallScene(const Frame& worldFromLocal, double distance, double height) {
    return [=](const Vec3& dWorld) {
        const Vec3 d = worldFromLocal.ToLocal(dWorld);
        if (d.x > 0) {
            const double t = distance / d.x;
            if (t * d.z < height)
                return Sample(0, t);
        }
        return Sample(1, kFhuge);
    };
}

// Irradiance changes fastest toward the wall, so the record is shortest that
// way: its ellipse reaches less far along the wall normal than along the
// wall, and u (the axis of radius[0] < radius[1]) mostly lies along the
// normal. Not always: the wall's Hessian has eigenvalues of both signs, and
// Radiance turns the frame toward an eigenvector solved with |λ| in place of
// λ, which for some random starting frames turns the ellipse well away
// (hessian_radiance_test.cpp finds the same fractions in real Radiance's
// records). So over 40 records: at least 85% shorter toward the wall, at
// least 60% with u within 20° of the normal. With the
// ellipse reaching the wall (level-2 records, weight 1/4, at -aa 0.2) corral
// bits are set, all in sectors whose centre faces the wall, including the one
// straight at it.
TEST(HessianRecord, WallShortensTheRecordTowardItAndSetsCorralBits) {
    const Frame w = FrameAround(kTiltedNormal);
    const double distance = 0.05, height = 0.1;
    const AmbientLimits limits = Limits(0.01, 2);
    constexpr int kRecords = 40;
    int shorter = 0, aligned = 0, withCorral = 0;
    for (int seed = 0; seed < kRecords; ++seed) {
        Rng rng(static_cast<std::uint64_t>(seed));
        const HessianHemisphere h = SampleHessianHemisphere({}, w.n, Options(1024, 512, 0.25), kFar,
                                                            rng, WallScene(w, distance, height));
        const auto rec = MakeHessianRecord(h, 2, 0.25, 0.2, limits);
        ASSERT_TRUE(rec.has_value());
        const Vec3 v = rec->VAxis();
        // Distance from the centre to the ellipse along the wall normal and along the wall.
        auto reach = [&](const Vec3& d) {
            return 1 / std::hypot(Dot(d, rec->uAxis) / rec->radius[0], Dot(d, v) / rec->radius[1]);
        };
        shorter += reach(w.u) < reach(w.v) ? 1 : 0;
        aligned += std::fabs(Dot(rec->uAxis, w.u)) > std::cos(20 * kPi / 180) ? 1 : 0;
        if (rec->corral == 0)
            continue;
        ++withCorral;
        for (int k = 0; k < 32; ++k) {
            if ((rec->corral >> k) & 1u) {
                const double phi = (k + 0.5) * kPi / 16;
                const Vec3 centre = rec->uAxis * std::cos(phi) + v * std::sin(phi);
                EXPECT_GT(Dot(centre, w.u), 0.0) << "sector " << k << " of record " << seed;
            }
        }
        EXPECT_TRUE(CorralCovers(*rec, rec->position + w.u));  // straight at the wall
        EXPECT_FALSE(CorralCovers(*rec, rec->position - w.u));
    }
    std::cout << "wall: shorter toward it " << shorter << ", u along its normal " << aligned
              << ", corral bits " << withCorral << " of " << kRecords << "\n";
    EXPECT_GE(shorter, kRecords * 85 / 100);
    EXPECT_GE(aligned, kRecords * 60 / 100);
    EXPECT_GE(withCorral, kRecords * 80 / 100);
}

// Without the corral's reach (weight 1 at -aa 0.1 the ellipse stops short of
// the wall) there are no bits, and none ever without occluders nearby.
TEST(HessianRecord, NoCorralWhereNothingIsInsideTheEllipse) {
    const Frame w = FrameAround(kUp);
    Rng rng(3);
    const HessianHemisphere near =
        SampleHessianHemisphere({}, w.n, Options(1024, 0), kFar, rng, WallScene(w, 0.05, 0.1));
    const auto rec = MakeHessianRecord(near, 0, 1.0, 0.1, Limits(0.01, 2));
    ASSERT_TRUE(rec.has_value());
    EXPECT_LT(rec->radius[0] * 0.1, 0.05);
    EXPECT_EQ(rec->corral, 0u);
    const HessianHemisphere open = SampleHessianHemisphere(
        {}, w.n, Options(1024, 0), kFar, rng, ConstantEnvironment(Rgb::Grey(1), kFhuge));
    EXPECT_EQ(CorralBits(open, open.frame.u, 100, 200), 0u);
}

// A black environment has nothing to normalise by: Radiance falls back on a
// purely geometric Hessian (every Y = 1), with no gradients and no corral.
// The radii still see the geometry: a low black ceiling (everything at
// distance 0.05/cosθ) gives a much smaller record than the same ceiling far
// away.
TEST(HessianRecord, BlackEnvironmentGivesGeometricRecord) {
    const AmbientLimits limits = Limits(0.001, 100);
    double radius[2];
    for (int k = 0; k < 2; ++k) {
        const double h = k == 0 ? 0.05 : 50;
        Rng rng(9);
        const HessianHemisphere hem =
            SampleHessianHemisphere({}, kUp, Options(1024, 512), kFar, rng,
                                    [h](const Vec3& d) { return Sample(0, h / d.z); });
        ASSERT_TRUE(hem.complete);
        EXPECT_FALSE(EstimateHessian(hem).radiometric);
        const auto rec = MakeHessianRecord(hem, 0, 1.0, 0.1, limits);
        ASSERT_TRUE(rec.has_value());
        EXPECT_EQ(rec->value, Rgb());
        EXPECT_EQ(rec->posGradient[0], 0.0);
        EXPECT_EQ(rec->posGradient[1], 0.0);
        EXPECT_EQ(rec->dirGradient[0], 0.0);
        EXPECT_EQ(rec->dirGradient[1], 0.0);
        EXPECT_EQ(rec->corral, 0u);
        EXPECT_FALSE(HessianRotationalGradient(hem, hem.frame.u, hem.frame.v).has_value());
        radius[k] = rec->radius[0];
    }
    std::cout << "black ceiling radius: at 0.05 " << radius[0] << ", at 50 " << radius[1] << "\n";
    EXPECT_LT(radius[0], 0.2 * radius[1]);
}

// ---------------------------------------------------------------------------
// Eigen-analysis and limits.

/// The Hessian with eigenvalue `a` along unit tangent `x` and `b` along n × x.
Matrix3 TangentHessian(const Frame& f, const Vec3& x, double a, double b) {
    const Vec3 y = Cross(f.n, x);
    Matrix3 m;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j)
            m.m[i][j] = a * x[i] * x[j] + b * y[i] * y[j];
    }
    return m;
}

// r = (4/|λ|)^¼ with radius[0] for the larger |λ|; v turns to the smaller
// curvature's eigenvector when that eigenvalue is positive; v = n × u.
TEST(HessianEllipse, RadiiAndAxesFromEigenvalues) {
    const Frame f = FrameAround(kTiltedNormal);
    const Vec3 x = Normalize(f.u * std::cos(0.7) + f.v * std::sin(0.7));
    const HessianEllipse e = EllipseFromHessian(TangentHessian(f, x, 16.0, 0.25), f, 100);
    EXPECT_NEAR(e.radius[0], std::sqrt(0.5), 1e-12);  // (4/16)^¼
    EXPECT_NEAR(e.radius[1], 2.0, 1e-12);             // (4/0.25)^¼
    EXPECT_NEAR(std::fabs(Dot(e.u, x)), 1.0, 1e-12);
    EXPECT_NEAR(std::fabs(Dot(e.v, Cross(f.n, x))), 1.0, 1e-12);
    EXPECT_LT(Length(e.v - Cross(f.n, e.u)), 1e-12);
    // Radiance's sign (see HessianEdges): a concave irradiance, both λ < 0,
    // gives the same radii.
    const HessianEllipse neg = EllipseFromHessian(TangentHessian(f, x, -16.0, -0.25), f, 100);
    EXPECT_NEAR(neg.radius[0], std::sqrt(0.5), 1e-12);
    EXPECT_NEAR(neg.radius[1], 2.0, 1e-12);
    // Only the normal component: nothing in the tangent plane.
    Matrix3 normalOnly;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j)
            normalOnly.m[i][j] = 5 * f.n[i] * f.n[j];
    }
    const HessianEllipse flat = EllipseFromHessian(normalOnly, f, 7);
    EXPECT_EQ(flat.radius[0], 7);
    EXPECT_EQ(flat.radius[1], 7);
}

// Radiance's quirks, kept: (1) with an off-diagonal term at most 1e-6 the
// frame is not turned, so radius[0] (the larger curvature's) can end up along
// u although the larger curvature is along v; (2) the turn solves for the
// eigenvector with |λ|, which for a negative smaller eigenvalue is not an
// eigenvector; (3) a near-zero eigenvalue gives maxRadius for both.
TEST(HessianEllipse, KeepsRadianceQuirks) {
    const Frame f = FrameAround(kUp);
    // Eigenvectors 1e-8 rad off the frame: the off-diagonal term is 3.75e-8.
    const Vec3 nearlyU = Normalize(f.u + f.v * 1e-8);
    const HessianEllipse noTurn = EllipseFromHessian(TangentHessian(f, nearlyU, 0.25, 4.0), f, 100);
    EXPECT_NEAR(noTurn.radius[0], 1.0, 1e-12);
    EXPECT_EQ(noTurn.u, f.u);  // curvature 4 is along v, yet radius 1 is along u

    const Vec3 x = Normalize(f.u + f.v * 0.5);
    const Matrix3 m = TangentHessian(f, x, 4.0, -0.25);  // smaller |λ| negative
    const HessianEllipse e = EllipseFromHessian(m, f, 100);
    const double h00 = m.Form(f.u, f.u), h01 = m.Form(f.u, f.v);
    const double s = (0.25 - h00) / h01;  // |λ| in place of λ
    const Vec3 expectV = Normalize(f.u + f.v * s);
    EXPECT_LT(Length(e.v - expectV), 1e-12);
    EXPECT_GT(std::fabs(Dot(e.v, x)), 0.05);  // not the true eigenvector n × x

    const HessianEllipse tiny = EllipseFromHessian(TangentHessian(f, x, 4.0, 1e-13), f, 3);
    EXPECT_EQ(tiny.radius[0], 3);
    EXPECT_EQ(tiny.radius[1], 3);
}

// §4.7 step 6 in Radiance's order; each case distinguishes the order from
// another plausible one.
TEST(HessianLimits, RadiiInRadianceOrder) {
    const AmbientLimits l = Limits(0.1, 1.0);
    auto limit = [&](double r0, double r1, const double* g, double weight,
                     const AmbientLimits& lim) {
        double r[2] = {r0, r1};
        LimitHessianRadii(r, g, weight, lim);
        return std::make_pair(r[0], r[1]);
    };
    // Gradient caps per axis, then r0 <= r1 restored.
    const double g1[2] = {2.0, 0.25};
    EXPECT_EQ(limit(0.4, 0.8, g1, 1, l), std::make_pair(0.4, 0.8));
    const double g2[2] = {0.5, 2.0};
    EXPECT_EQ(limit(0.8, 0.9, g2, 1, l), std::make_pair(0.5, 0.5));
    // Gradients are ignored without a gradient (the geometric fallback).
    EXPECT_EQ(limit(0.8, 0.9, nullptr, 1, l), std::make_pair(0.8, 0.9));
    // The gradient cap comes before the minimum: 1/|g| = 0.01 is raised to 0.1.
    const double g3[2] = {100.0, 0.0};
    EXPECT_EQ(limit(0.5, 0.6, g3, 1, l), std::make_pair(0.1, 0.2));
    // Minimum, then 1/sqrt(weight): 0.05 → 0.1 → 0.2 (not 0.1 after the weight).
    EXPECT_EQ(limit(0.05, 0.05, nullptr, 0.25, l), std::make_pair(0.2, 0.2));
    // r1 below the minimum too.
    EXPECT_EQ(limit(0.02, 0.05, nullptr, 1, l), std::make_pair(0.1, 0.1));
    // 2:1 after the weight, maximum last: (0.3, 0.9)/0.5 = (0.6, 1.8) → 2:1
    // (0.6, 1.2) → max (0.6, 1.0).
    EXPECT_EQ(limit(0.3, 0.9, nullptr, 0.25, l), std::make_pair(0.6, 1.0));
    // The maximum clips both.
    EXPECT_EQ(limit(1.5, 2.0, nullptr, 1, l), std::make_pair(1.0, 1.0));
    // The anisotropy cap of 2:1 on its own.
    const auto [a, b] = limit(0.2, 0.9, nullptr, 1, l);
    EXPECT_DOUBLE_EQ(a, 0.2);
    EXPECT_DOUBLE_EQ(b, 0.4);
}

TEST(HessianLimits, GradientChangeAcrossTheEllipseIsAtMostOne) {
    double g[2] = {3.0, 4.0};
    const double small[2] = {0.2, 0.1};
    CapHessianGradient(g, small);  // (0.6² + 0.4²) < 1: untouched
    EXPECT_EQ(g[0], 3.0);
    EXPECT_EQ(g[1], 4.0);
    const double large[2] = {0.4, 0.2};
    CapHessianGradient(g, large);
    EXPECT_NEAR(std::hypot(g[0] * large[0], g[1] * large[1]), 1.0, 1e-15);
    EXPECT_NEAR(g[0] / g[1], 0.75, 1e-15);  // direction kept
}

// Whole records keep the invariants the limits promise, in scenes that push
// on each limit.
TEST(HessianRecord, RecordsKeepTheirInvariants) {
    const Frame w = FrameAround(kTiltedNormal);
    const AmbientLimits limits = Limits(0.02, 0.5);
    HalfPlaneCeiling half;
    half.worldFromLocal = w;
    half.height = 0.3;
    const std::vector<AmbientTraceFn> scenes = {WallScene(w, 0.05, 0.1), WallScene(w, 0.5, 1.0),
                                                half.At(Vec3(0.05, 0, 0)),
                                                ConstantEnvironment(Rgb::Grey(1), 0.01)};
    for (std::size_t s = 0; s < scenes.size(); ++s) {
        for (int level = 0; level < 3; ++level) {
            const double weight = std::pow(0.5, level);
            Rng rng(s, static_cast<std::uint64_t>(level));
            const HessianHemisphere h = SampleHessianHemisphere(
                Vec3(1, 2, 3), w.n, Options(1024, 512, weight), kFar, rng, scenes[s]);
            const auto rec = MakeHessianRecord(h, level, weight, 0.1, limits);
            ASSERT_TRUE(rec.has_value());
            EXPECT_EQ(rec->position, Vec3(1, 2, 3));
            EXPECT_EQ(rec->normal, w.n);
            EXPECT_EQ(rec->level, level);
            EXPECT_EQ(rec->weight, weight);
            EXPECT_NEAR(Length(rec->uAxis), 1.0, 1e-12);
            EXPECT_NEAR(Dot(rec->uAxis, rec->normal), 0.0, 1e-12);
            EXPECT_LE(rec->radius[0], rec->radius[1]);
            EXPECT_LE(rec->radius[1], 2 * rec->radius[0] * (1 + 1e-15));
            EXPECT_LE(rec->radius[1], limits.maxRadius);
            EXPECT_GE(rec->radius[0], std::min(limits.maxRadius, limits.minRadius));
            EXPECT_LE(std::hypot(rec->posGradient[0] * rec->radius[0],
                                 rec->posGradient[1] * rec->radius[1]),
                      1 + 1e-12);
        }
    }
}

// ---------------------------------------------------------------------------
// Super-sampling.

/// Bright on one side of a plane through the normal, black on the other.
AmbientTraceFn EdgeScene(const Vec3& edgeNormal) {
    return [=](const Vec3& d) { return Sample(Dot(d, edgeNormal) > 0 ? 1.0 : 0.0, 1.0); };
}

// The extra samples go where neighbouring cells differ: with a sharp edge
// through the normal, to cells within a cell or two of it. Never more than
// asked for; and nearly all of them are used.
TEST(HessianSuperSampling, GoesToHighContrastCellsAndNeverExceedsTheRequest) {
    const Frame w = FrameAround(kTiltedNormal);
    const Vec3 edgeNormal = Normalize(w.u + w.v * 0.4);
    for (std::uint64_t seed = 0; seed < 5; ++seed) {
        std::vector<Vec3> dirs;
        const auto scene = EdgeScene(edgeNormal);
        const AmbientTraceFn trace = [&](const Vec3& d) {
            dirs.push_back(d);
            return scene(d);
        };
        Rng rng(seed);
        const HessianHemisphere h =
            SampleHessianHemisphere({}, w.n, Options(1024, 512), kFar, rng, trace);
        ASSERT_TRUE(h.complete);
        const int first = h.ns * h.ns;
        EXPECT_EQ(h.raysTraced, first + h.superSamples);
        EXPECT_LE(h.superSamples, 512);
        EXPECT_GE(h.superSamples, 480);
        // Cells next to the edge: some cell within one step across it has the
        // other value.
        auto nearEdge = [&](int i, int j) {
            const double self = Bright(h.At(i, j).radiance);
            for (int ii = std::max(0, i - 1); ii <= std::min(h.ns - 1, i + 1); ++ii) {
                for (int jj = std::max(0, j - 1); jj <= std::min(h.ns - 1, j + 1); ++jj) {
                    if (Bright(h.At(ii, jj).radiance) != self)
                        return true;
                }
            }
            return false;
        };
        int nearCells = 0;
        for (int i = 0; i < h.ns; ++i) {
            for (int j = 0; j < h.ns; ++j)
                nearCells += nearEdge(i, j) ? 1 : 0;
        }
        int nearSupers = 0;
        for (std::size_t k = static_cast<std::size_t>(first); k < dirs.size(); ++k) {
            const auto [i, j] = CellOf(h, dirs[k]);
            nearSupers += nearEdge(i, j) ? 1 : 0;
        }
        const double cellFraction = static_cast<double>(nearCells) / first;
        const double superFraction = static_cast<double>(nearSupers) / h.superSamples;
        std::cout << "super-samples near the edge " << superFraction << " (cells there "
                  << cellFraction << ")\n";
        EXPECT_LT(cellFraction, 0.2);
        EXPECT_GT(superFraction, 0.98);
    }
}

// The priorities leave each cell's own sample out: one bright cell among black
// ones has priority 0 itself, and each of its four neighbours the variance of
// its own neighbours' brightness, of which that bright cell is one.
TEST(HessianSuperSampling, PrioritiesLeaveTheCellsOwnSampleOut) {
    HessianHemisphere h;
    h.ns = 5;
    h.complete = true;
    h.cells.assign(25, HessianCell{});
    h.cells[2 * 5 + 2].radiance = Rgb::Grey(1);
    const std::vector<double> e = detail::NeighbourContrast(h);
    auto at = [&](int i, int j) { return e[static_cast<std::size_t>(i * 5 + j)]; };
    EXPECT_EQ(at(2, 2), 0.0);
    // Four neighbours, one of them 1: mean 1/4, variance (3·(1/4)² + (3/4)²)/4.
    const double variance = (3 * 0.0625 + 0.5625) / 4;
    for (const auto& [i, j] : {std::pair{1, 2}, {3, 2}, {2, 1}, {2, 3}})
        EXPECT_DOUBLE_EQ(at(i, j), variance) << i << " " << j;
    EXPECT_EQ(at(1, 1), 0.0);  // diagonal: not a neighbour
    EXPECT_EQ(at(0, 0), 0.0);
    // A bright border cell: its three neighbours' variance.
    for (HessianCell& c : h.cells) c.radiance = Rgb();
    h.cells[0 * 5 + 2].radiance = Rgb::Grey(1);
    const std::vector<double> border = detail::NeighbourContrast(h);
    EXPECT_EQ(border[2], 0.0);
    EXPECT_DOUBLE_EQ(border[1], (2 * 1.0 / 9 + 4.0 / 9) / 3);  // neighbours 0, 1, 0 (of 3)
}

// How many extra samples a cell gets does not depend on its own sample (nor
// on any cell of its colour), so its mean stays unbiased: changing one cell's
// value changes only the other colour's counts, and the total stays exact.
TEST(HessianSuperSampling, ACellsShareDoesNotDependOnItsOwnSample) {
    HessianHemisphere h;
    h.ns = 9;
    h.complete = true;
    h.cells.assign(81, HessianCell{});
    std::mt19937_64 gen(5);
    std::uniform_real_distribution<double> u(0, 1);
    for (HessianCell& c : h.cells) c.radiance = Rgb::Grey(u(gen) < 0.2 ? 10.0 : 0.1);
    // Also with the budget cut by the contrast of the other colour (deeper
    // records, SuperSamplesForContrast): a target of 0.25 keeps it below the cap.
    HemisphereOptions deeper;
    deeper.contrastTarget = 0.25;
    for (const HemisphereOptions& options : {HemisphereOptions{}, deeper})
    for (int cell : {40, 41, 0, 9}) {
        Rng a(7), b(7);
        const std::vector<int> before = detail::AllotSuperSamples(h, 60, a, options);
        HessianHemisphere changed = h;
        changed.cells[static_cast<std::size_t>(cell)].radiance = Rgb::Grey(50);
        const std::vector<int> after = detail::AllotSuperSamples(changed, 60, b, options);
        int total = 0, moved = 0, totalBefore = 0;
        for (int k = 0; k < 81; ++k) {
            total += after[static_cast<std::size_t>(k)];
            totalBefore += before[static_cast<std::size_t>(k)];
            const bool sameColour = (k / 9 + k % 9) % 2 == (cell / 9 + cell % 9) % 2;
            if (sameColour) {
                EXPECT_EQ(after[static_cast<std::size_t>(k)], before[static_cast<std::size_t>(k)])
                    << "cell " << k << " after changing " << cell;
            } else {
                moved += after[static_cast<std::size_t>(k)] != before[static_cast<std::size_t>(k)];
            }
        }
        if (options.contrastTarget > 0) {
            EXPECT_LT(totalBefore, 60);  // the cut applies
            EXPECT_GT(totalBefore, 0);
        } else {
            EXPECT_EQ(total, 60);
        }
        EXPECT_GT(moved, 0) << cell;  // the neighbours' shares did change
    }
}

// A request is never exceeded, and is cut to one extra sample per cell on
// average (the priorities are fixed before sampling), with contrast
// everywhere (a checkerboard of directions).
TEST(HessianSuperSampling, NeverMoreThanRequested) {
    const AmbientTraceFn checker = [](const Vec3& d) {
        const int k = static_cast<int>(std::floor(d.x * 9) + std::floor(d.y * 9));
        return Sample(k % 2 == 0 ? 1.0 : 0.1, 1.0);
    };
    for (int request : {9, 100, 5000}) {
        Rng rng(static_cast<std::uint64_t>(request));
        const HessianHemisphere h =
            SampleHessianHemisphere({}, kUp, Options(256, request), kFar, rng, checker);
        EXPECT_LE(h.superSamples, std::min(request, 256));
        EXPECT_GE(h.superSamples, std::min(request, 256) * 9 / 10);
        EXPECT_EQ(h.raysTraced, 256 + h.superSamples);
    }
}

// Where two neighbouring cells are both black, Radiance's estimate divides
// 0 by 0 and the NaN stops all super-sampling; here the edge between light
// and dark still gets the samples.
TEST(HessianSuperSampling, BlackNeighboursDoNotDisableIt) {
    Rng rng(1);
    const HessianHemisphere h = SampleHessianHemisphere({}, kUp, Options(1024, 512), kFar, rng,
                                                        EdgeScene(Normalize(Vec3(1, 0.3, 0))));
    EXPECT_GT(h.superSamples, 480);
    EXPECT_TRUE(std::isfinite(h.value.g));
}

// Radiance's thresholds: more than 8 extra samples, more than 7 × 7 cells.
TEST(HessianSuperSampling, NeedsMoreThanEightSamplesAndFortyNineCells) {
    const auto scene = EdgeScene(Normalize(Vec3(1, 0.3, 0)));
    auto supers = [&](const HemisphereOptions& o) {
        Rng rng(2);
        return SampleHessianHemisphere({}, kUp, o, kFar, rng, scene).superSamples;
    };
    EXPECT_EQ(supers(Options(49, 512)), 0);        // 7 × 7
    EXPECT_GT(supers(Options(64, 512)), 0);        // 8 × 8
    EXPECT_EQ(supers(Options(1024, 16, 0.5)), 0);  // (int)(8 + 0.5) = 8
    EXPECT_GT(supers(Options(1024, 18, 0.5)), 0);  // 9
}

// Each cell keeps its first sample's hit point, the mean radiance of all its
// samples and the nearest distance any of them saw (Radiance's AMBSAMP), with
// the distances varying within cells and contrast enough to super-sample.
TEST(HessianSuperSampling, UpdatesMeanAndNearestDistanceButNotTheHitPoint) {
    struct Seen {
        Vec3 dir;
        double radiance, distance;
    };
    std::vector<Seen> seen;
    const AmbientTraceFn trace = [&](const Vec3& d) {
        const double radiance = d.x > 0.2 ? 2.0 : 0.5;
        const double distance = 1.0 + 0.5 * std::sin(40 * d.y) + (d.x > 0.2 ? 0.0 : 3.0);
        seen.push_back({d, radiance, distance});
        return Sample(radiance, distance);
    };
    Rng rng(12);
    const HessianHemisphere h =
        SampleHessianHemisphere({}, kUp, Options(256, 400), kFar, rng, trace);
    ASSERT_GT(h.superSamples, 230);  // at most one per cell on average: 256
    const int ns = h.ns;
    std::vector<std::vector<Seen>> byCell(static_cast<std::size_t>(ns * ns));
    for (const Seen& s : seen) {
        const auto [i, j] = CellOf(h, s.dir);
        byCell[static_cast<std::size_t>(i * ns + j)].push_back(s);
    }
    int refined = 0;
    for (int i = 0; i < ns; ++i) {
        for (int j = 0; j < ns; ++j) {
            const std::vector<Seen>& samples = byCell[static_cast<std::size_t>(i * ns + j)];
            const HessianCell& c = h.At(i, j);
            ASSERT_EQ(static_cast<int>(samples.size()), c.samples);
            double sum = 0, nearest = 0;
            for (const Seen& s : samples) {
                sum += s.radiance;
                nearest = std::max(nearest, 1 / s.distance);
            }
            EXPECT_NEAR(c.radiance.g, sum / c.samples, 1e-14);
            EXPECT_EQ(c.inverseDistance, nearest);
            EXPECT_LT(Length(c.offset - samples.front().dir * samples.front().distance), 1e-12);
            refined += c.samples > 1 ? 1 : 0;
        }
    }
    EXPECT_GT(refined, 10);
}

// ---------------------------------------------------------------------------
// Failures.

// One failed cell: the value still counts the others (the failed one as 0),
// but there is no record, no super-sampling and no rotational gradient.
TEST(HessianRecord, IncompleteHemisphereGivesNoRecord) {
    int calls = 0;
    const AmbientTraceFn trace = [&](const Vec3&) {
        return ++calls == 100 ? std::nullopt : Sample(1.0, 1.0);
    };
    Rng rng(6);
    const HessianHemisphere h =
        SampleHessianHemisphere({}, kUp, Options(1024, 512), kFar, rng, trace);
    EXPECT_FALSE(h.complete);
    EXPECT_TRUE(h.anySample);
    EXPECT_EQ(h.superSamples, 0);
    EXPECT_EQ(h.raysTraced, 1024);
    EXPECT_DOUBLE_EQ(h.value.g, 1023.0 / 1024.0);
    EXPECT_FALSE(MakeHessianRecord(h, 0, 1, 0.1, Limits(0.01, 1)).has_value());
    EXPECT_FALSE(HessianRotationalGradient(h, h.frame.u, h.frame.v).has_value());

    const HessianHemisphere none = SampleHessianHemisphere(
        {}, kUp, Options(64, 0), kFar, rng, [](const Vec3&) { return std::nullopt; });
    EXPECT_FALSE(none.anySample);
    EXPECT_FALSE(MakeHessianRecord(none, 0, 1, 0.1, Limits(0.01, 1)).has_value());
}

// Without the cache ns may fall below 7: such hemispheres give a value only.
TEST(HessianRecord, FewerThanSevenDivisionsGiveNoRecord) {
    const auto sky = ConstantEnvironment(Rgb::Grey(1), 1.0);
    Rng rng(7);
    const HessianHemisphere six =
        SampleHessianHemisphere({}, kUp, Options(36, 0, 1, false), kFar, rng, sky);
    ASSERT_EQ(six.ns, 6);
    EXPECT_TRUE(six.complete);
    EXPECT_FALSE(MakeHessianRecord(six, 0, 1, 0.1, Limits(0.01, 1)).has_value());
    EXPECT_FALSE(HessianRotationalGradient(six, six.frame.u, six.frame.v).has_value());
    const HessianHemisphere seven =
        SampleHessianHemisphere({}, kUp, Options(49, 0, 1, false), kFar, rng, sky);
    ASSERT_EQ(seven.ns, 7);
    EXPECT_TRUE(MakeHessianRecord(seven, 0, 1, 0.1, Limits(0.01, 1)).has_value());
    EXPECT_FALSE(MakeHessianRecord(seven, 0, 0.0, 0.1, Limits(0.01, 1)).has_value());
}

// Bad samples never leak into the result: NaN or negative radiance, NaN or
// non-positive distances fail the cell or are cut to zero.
TEST(HessianHemisphere, BadSamplesNeverProduceNanOrNegativeValues) {
    int calls = 0;
    const AmbientTraceFn trace = [&](const Vec3&) -> std::optional<AmbientSample> {
        switch (++calls % 5) {
            case 0:
                return AmbientSample{Rgb(-1, 2, 3), 1.0};
            case 1:
                return AmbientSample{Rgb(std::nan(""), 1, 1), 1.0};
            case 2:
                return AmbientSample{Rgb(1, 1, 1), std::nan("")};
            case 3:
                return AmbientSample{Rgb(1, 1, 1), 0.0};
            default:
                return AmbientSample{Rgb(1, 1, 1), std::numeric_limits<double>::infinity()};
        }
    };
    Rng rng(2);
    const HessianHemisphere h = SampleHessianHemisphere({}, kUp, Options(256, 0), kFar, rng, trace);
    EXPECT_FALSE(h.complete);
    EXPECT_TRUE(IsFinite(h.value));
    EXPECT_GE(h.value.r, 0.0);
    for (const HessianCell& c : h.cells) {
        EXPECT_TRUE(IsFinite(c.radiance));
        EXPECT_TRUE(IsFinite(c.offset));
        EXPECT_GE(c.radiance.r, 0.0);
    }
}

}  // namespace
}  // namespace rt
