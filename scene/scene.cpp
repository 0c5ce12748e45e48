// SPDX-License-Identifier: MIT
#include "scene/scene.h"

#include <algorithm>
#include <cmath>

namespace rt {
namespace {

// Exact extent of a circle (centre c, unit normal n, radius r): along axis k the
// circle reaches r·sqrt(1 − n_k²) from its centre.
void ExtendByCircle(Bounds3& bounds, const Vec3& center, const Vec3& normal, double radius) {
    Vec3 half;
    for (int k = 0; k < 3; ++k) half[k] = radius * std::sqrt(std::max(0.0, 1.0 - normal[k] * normal[k]));
    bounds.Extend(center - half);
    bounds.Extend(center + half);
}

}  // namespace

const char* MaterialTypeName(MaterialType type) {
    switch (type) {
        case MaterialType::Plastic: return "plastic";
        case MaterialType::Metal: return "metal";
        case MaterialType::Trans: return "trans";
        case MaterialType::Light: return "light";
        case MaterialType::Illum: return "illum";
        case MaterialType::Glow: return "glow";
        case MaterialType::Spotlight: return "spotlight";
        case MaterialType::Mirror: return "mirror";
        case MaterialType::Glass: return "glass";
        case MaterialType::Dielectric: return "dielectric";
        case MaterialType::Interface: return "interface";
        case MaterialType::Plastic2: return "plastic2";
        case MaterialType::Metal2: return "metal2";
        case MaterialType::Trans2: return "trans2";
        case MaterialType::PlasFunc: return "plasfunc";
        case MaterialType::MetFunc: return "metfunc";
        case MaterialType::TransFunc: return "transfunc";
        case MaterialType::PlasData: return "plasdata";
        case MaterialType::MetData: return "metdata";
        case MaterialType::TransData: return "transdata";
        case MaterialType::BRTDFunc: return "BRTDfunc";
        case MaterialType::Antimatter: return "antimatter";
        case MaterialType::Ashik2: return "ashik2";
        case MaterialType::Bsdf: return "BSDF";
        case MaterialType::ABsdf: return "aBSDF";
        case MaterialType::Mist: return "mist";
        case MaterialType::Prism1: return "prism1";
        case MaterialType::Prism2: return "prism2";
    }
    return "unknown";
}

const char* SurfaceTypeName(SurfaceType type) {
    switch (type) {
        case SurfaceType::Polygon: return "polygon";
        case SurfaceType::Sphere: return "sphere";
        case SurfaceType::Bubble: return "bubble";
        case SurfaceType::Cone: return "cone";
        case SurfaceType::Cup: return "cup";
        case SurfaceType::Cylinder: return "cylinder";
        case SurfaceType::Tube: return "tube";
        case SurfaceType::Ring: return "ring";
        case SurfaceType::Source: return "source";
        case SurfaceType::Instance: return "instance";
        case SurfaceType::Mesh: return "polygon";  // Radiance's mesh triangles are faces
    }
    return "unknown";
}

MaterialParams MakeMaterialParams(MaterialType type, const std::vector<double>& a) {
    // The builder fills in what antimatter clips; it has no real arguments.
    if (type == MaterialType::Antimatter) return ClipParams{};
    if (type == MaterialType::Mist) {
        // The builder adds the source names.
        MistParams p;
        if (a.size() >= 3) p.extinction = Rgb(a[0], a[1], a[2]);
        if (a.size() >= 6) p.albedo = Rgb(a[3], a[4], a[5]);
        if (a.size() >= 7) p.eccentricity = a[6];
        return p;
    }
    if (type == MaterialType::Bsdf || type == MaterialType::ABsdf) {
        // The builder sets the data and the proxy flag.
        BsdfParams p;
        if (a.size() >= 3) p.frontDiffuse = Rgb(a[0], a[1], a[2]);
        if (a.size() >= 6) p.backDiffuse = Rgb(a[3], a[4], a[5]);
        if (a.size() >= 9) p.diffuseTransmission = Rgb(a[6], a[7], a[8]);
        return p;
    }
    if (type == MaterialType::Prism1) return PrismParams{1};
    if (type == MaterialType::Prism2) return PrismParams{2};
    const Rgb color(a[0], a[1], a[2]);
    switch (type) {
        case MaterialType::Plastic:
        case MaterialType::Metal: return NormalParams{color, a[3], a[4], 0, 0};
        case MaterialType::Trans: return NormalParams{color, a[3], a[4], a[5], a[6]};
        case MaterialType::Light:
        case MaterialType::Illum: return LightParams{color, 0, 0, Vec3()};
        case MaterialType::Glow: return LightParams{color, a[3], 0, Vec3()};
        case MaterialType::Spotlight: return LightParams{color, 0, a[3], Vec3(a[4], a[5], a[6])};
        case MaterialType::Mirror: return MirrorParams{color};
        case MaterialType::Glass: return GlassParams{color, a.size() > 3 ? a[3] : 1.52};
        case MaterialType::Dielectric:
            // Radiance's MLAMBDA: the Hartmann constant is given for 500 nm.
            return DielectricParams{color, a[3] + a[4] / 500.0, Rgb(1, 1, 1), 1.0};
        case MaterialType::Interface:
            return DielectricParams{color, a[3], Rgb(a[4], a[5], a[6]), a[7]};
        case MaterialType::Plastic2:
        case MaterialType::Metal2: return AnisoParams{color, a[3], a[4], a[5], 0, 0};
        case MaterialType::Trans2: return AnisoParams{color, a[3], a[4], a[5], a[6], a[7]};
        case MaterialType::PlasFunc:
        case MaterialType::MetFunc:
        case MaterialType::PlasData:
        case MaterialType::MetData: return BrdfParams{color, a[3], 0, 0};
        case MaterialType::TransFunc:
        case MaterialType::TransData: return BrdfParams{color, a[3], a[4], a[5]};
        case MaterialType::BRTDFunc:
            return BrtdParams{color, Rgb(a[3], a[4], a[5]), Rgb(a[6], a[7], a[8])};
        case MaterialType::Antimatter: break;
        case MaterialType::Ashik2:
            return AshikParams{color, Rgb(a[3], a[4], a[5]), a[6], a[7]};
        case MaterialType::Bsdf:
        case MaterialType::ABsdf:
        case MaterialType::Mist:
        case MaterialType::Prism1:
        case MaterialType::Prism2: break;  // above
    }
    return NormalParams{};
}

bool IsTransparentType(MaterialType type) {
    // transfunc and transdata are not: Radiance's -i meters them as opaque.
    return type == MaterialType::Trans || type == MaterialType::Trans2 || type == MaterialType::Glass ||
           type == MaterialType::Dielectric || type == MaterialType::Interface ||
           type == MaterialType::ABsdf || type == MaterialType::Mist;
}

bool IsLightType(MaterialType type) {
    return type == MaterialType::Light || type == MaterialType::Illum ||
           type == MaterialType::Glow || type == MaterialType::Spotlight;
}

bool IsSourceMaterial(const Material& m, SurfaceType type) {
    if (!IsLightType(m.type)) return false;
    const LightParams& params = std::get<LightParams>(m.params);
    // A glow without radius only shows through indirect rays.
    if (m.type == MaterialType::Glow && type != SurfaceType::Source && params.radius <= kFtiny) {
        return false;
    }
    return params.color.r > kFtiny || params.color.g > kFtiny || params.color.b > kFtiny;
}

Bounds3 SurfaceBounds(const Surface& surface) {
    Bounds3 bounds;
    if (const auto* polygon = std::get_if<Polygon>(&surface.shape)) {
        for (const Vec3& v : polygon->vertices) bounds.Extend(v);
    } else if (const auto* sphere = std::get_if<Sphere>(&surface.shape)) {
        const Vec3 r(sphere->radius, sphere->radius, sphere->radius);
        bounds.Extend(sphere->center - r);
        bounds.Extend(sphere->center + r);
    } else if (const auto* cone = std::get_if<Cone>(&surface.shape)) {
        const Vec3 axis = Normalize(cone->p1 - cone->p0);
        ExtendByCircle(bounds, cone->p0, axis, cone->r0);
        ExtendByCircle(bounds, cone->p1, axis, cone->r1);
    } else if (const auto* ring = std::get_if<Ring>(&surface.shape)) {
        ExtendByCircle(bounds, ring->center, ring->normal, ring->r1);
    }
    return bounds;  // distant source: empty
}

Bounds3 InstanceBounds(const Scene& scene, const Instance& instance) {
    const Prototype& p = scene.prototypes[static_cast<std::size_t>(instance.prototype)];
    Bounds3 bounds;
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3 c = p.cubeOrigin + Vec3(corner & 1 ? p.cubeSize : 0, corner & 2 ? p.cubeSize : 0,
                                           corner & 4 ? p.cubeSize : 0);
        bounds.Extend(instance.renderFromObject.Point(c));
    }
    return bounds;
}

}  // namespace rt
