// SPDX-License-Identifier: MIT
//
// Analytic environments for the hemisphere sampler tests: each is a trace
// callback (radiance and hit distance along a direction from a query point)
// plus its exact irradiance, so tests can compare Ē and the Ward & Heckbert
// gradients with closed forms. Scenes are described in a local frame with the
// receiving floor at z = 0 and mapped to the world by `worldFromLocal`, so the
// same scene can be tested around any normal.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "ambient/hemisphere.h"
#include "core/conventions.h"
#include "core/vecmath.h"

namespace rt::testing {

/// Frame with n along unit `n` (and the deterministic Perpendicular() u).
/// Hemisphere options with the given counts (weight 1 and the cache by default).
inline HemisphereOptions Options(int divisions, int superSamples, double weight = 1.0,
                                 bool caching = true) {
    HemisphereOptions o;
    o.divisions = divisions;
    o.superSamples = superSamples;
    o.weight = weight;
    o.caching = caching;
    return o;
}

/// Bin of unit direction `d` on the hemisphere around `frame.n` for the
/// samplers' chi² tests: `thetaBins` equal steps of cos θ and `phiBins` equal
/// steps of azimuth from frame.u.
struct DirectionBin {
    int theta = 0, phi = 0;
};
inline DirectionBin BinOf(const Frame& frame, const Vec3& d, int thetaBins, int phiBins) {
    const Vec3 l = frame.ToLocal(d);
    DirectionBin b;
    b.theta = std::min(thetaBins - 1, static_cast<int>(l.z * thetaBins));
    double phi = std::atan2(l.y, l.x);
    if (phi < 0) phi += 2 * kPi;
    b.phi = std::min(phiBins - 1, static_cast<int>(phi / (2 * kPi) * phiBins));
    return b;
}

inline Frame FrameAround(const Vec3& n) {
    Frame f;
    f.n = n;
    f.u = Perpendicular(n);
    f.v = Cross(n, f.u);
    return f;
}

/// Rotates unit n by `angle` radians toward unit tangent w.
inline Vec3 Tilt(const Vec3& n, const Vec3& w, double angle) {
    return n * std::cos(angle) + w * std::sin(angle);
}

inline AmbientTraceFn ConstantEnvironment(const Rgb& radiance, double distance) {
    return [=](const Vec3&) {
        return std::optional<AmbientSample>(AmbientSample{radiance, distance});
    };
}

/// Radiance L inside the cone of half-angle `alpha` around unit `axis`, 0
/// outside; everything at distance 1.
inline AmbientTraceFn CapEnvironment(const Vec3& axis, double alpha, double radiance) {
    const double cosAlpha = std::cos(alpha);
    return [=](const Vec3& d) {
        const double l = Dot(d, axis) > cosAlpha ? radiance : 0.0;
        return std::optional<AmbientSample>(AmbientSample{Rgb::Grey(l), 1.0});
    };
}

/// Ē of a cap whose axis makes angle beta with the normal and which lies
/// wholly above the horizon (beta + alpha <= π/2): projected solid angle
/// π·sin²α·cosβ divided by π.
inline double CapMeanRadiance(double alpha, double beta, double radiance) {
    return radiance * std::sin(alpha) * std::sin(alpha) * std::cos(beta);
}

/// Emitting half-plane z = height, x > 0 (local frame), radiance L; the rest
/// of the sky is a miss at kFhuge. The query point is `localPoint`.
struct HalfPlaneCeiling {
    Frame worldFromLocal;
    double height = 1;
    double radiance = 1;

    AmbientTraceFn At(const Vec3& localPoint) const {
        const HalfPlaneCeiling s = *this;
        return [s, localPoint](const Vec3& dWorld) {
            const Vec3 d = s.worldFromLocal.ToLocal(dWorld);
            if (d.z > 0) {
                const double t = (s.height - localPoint.z) / d.z;
                if (localPoint.x + t * d.x > 0)
                    return std::optional<AmbientSample>(AmbientSample{Rgb::Grey(s.radiance), t});
            }
            return std::optional<AmbientSample>(AmbientSample{Rgb(), kFhuge});
        };
    }
    /// Irradiance on the floor (normal +z) at local x: πL/2·(1 + x/√(x²+h²)).
    double Irradiance(double x) const {
        return kPi * radiance * 0.5 * (1.0 + x / std::sqrt(x * x + height * height));
    }
    /// ∂E/∂x ÷ E on the floor.
    double RelativeGradientX(double x) const {
        const double h2 = height * height;
        const double dE = kPi * radiance * 0.5 * h2 / std::pow(x * x + h2, 1.5);
        return dE / Irradiance(x);
    }
    /// Relative rotational gradient on the floor at local x: ∫d dω over the
    /// lit region is π/2·(m + z) with m the unit normal of the plane through
    /// the point and the edge, so g = z × Φ / (z·Φ) = m_x/(1 + m_z) along +y.
    double RelativeRotationalGradientY(double x) const {
        const double len = std::sqrt(x * x + height * height);
        return (height / len) / (1.0 + x / len);
    }
};

/// Emitting rectangle [x0,x1]×[y0,y1] at z = height (local frame), radiance L,
/// the rest a miss at kFhuge. Exact irradiance for any receiver normal that
/// sees the whole rectangle, from Lambert's polygon formula.
struct RectangleEmitter {
    Frame worldFromLocal;
    double x0 = 0, x1 = 1, y0 = 0, y1 = 1, height = 1;
    double radiance = 1;

    AmbientTraceFn At(const Vec3& localPoint) const {
        const RectangleEmitter s = *this;
        return [s, localPoint](const Vec3& dWorld) {
            const Vec3 d = s.worldFromLocal.ToLocal(dWorld);
            if (d.z > 0) {
                const double t = (s.height - localPoint.z) / d.z;
                const Vec3 hit = localPoint + d * t;
                if (hit.x > s.x0 && hit.x < s.x1 && hit.y > s.y0 && hit.y < s.y1)
                    return std::optional<AmbientSample>(AmbientSample{Rgb::Grey(s.radiance), t});
            }
            return std::optional<AmbientSample>(AmbientSample{Rgb(), kFhuge});
        };
    }

    /// ∫ over the rectangle's solid angle of the direction (local frame):
    /// ½ Σ_edges γ_i · unit(r_i × r_{i+1}) (Lambert).
    Vec3 VectorIrradianceFactor(const Vec3& localPoint) const {
        const std::array<Vec3, 4> corners = {Vec3(x0, y0, height), Vec3(x1, y0, height),
                                             Vec3(x1, y1, height), Vec3(x0, y1, height)};
        Vec3 phi;
        for (int i = 0; i < 4; ++i) {
            const Vec3 a = Normalize(corners[i] - localPoint);
            const Vec3 b = Normalize(corners[(i + 1) % 4] - localPoint);
            const Vec3 c = Cross(a, b);
            const double gamma = std::atan2(Length(c), Dot(a, b));
            phi += Normalize(c) * (0.5 * gamma);
        }
        const Vec3 toCentre = Vec3(0.5 * (x0 + x1), 0.5 * (y0 + y1), height) - localPoint;
        return Dot(phi, toCentre) < 0 ? -phi : phi;
    }
    /// Irradiance at a local point for a local unit normal (whole rectangle visible).
    double Irradiance(const Vec3& localPoint, const Vec3& localNormal) const {
        return radiance * Dot(localNormal, VectorIrradianceFactor(localPoint));
    }
};

/// The gradient tests' emitter: a 1.3 × 1.2 rectangle of radiance 2 one unit
/// above the point's plane, off to one side of it, in `frame`.
inline RectangleEmitter OffsetRectangle(const Frame& frame) {
    RectangleEmitter scene;
    scene.worldFromLocal = frame;
    scene.x0 = 0.2;
    scene.x1 = 1.5;
    scene.y0 = -0.3;
    scene.y1 = 0.9;
    scene.height = 1.0;
    scene.radiance = 2.0;
    return scene;
}

/// Upper chi² quantile for `dof` degrees of freedom at standard-normal z
/// (z = 3.09 for 1e-3), Wilson–Hilferty; accurate to ~1% for dof >= 10.
inline double Chi2Quantile(int dof, double z) {
    const double k = dof;
    const double a = 2.0 / (9.0 * k);
    const double c = 1.0 - a + z * std::sqrt(a);
    return k * c * c * c;
}

}  // namespace rt::testing
