// SPDX-License-Identifier: MIT
//
// One ray of Radiance's ray tree (ray.h's RAY, the fields lazyrad uses): what
// is set before tracing, what tracing fills in, and the results shading adds.
// A ray lives on the stack of the function that traces it; children point at
// their parent for the path quantities (T, coefficients, trace output).
#pragma once

#include <algorithm>
#include <vector>

#include "core/affine.h"
#include "core/conventions.h"
#include "core/rgb.h"
#include "core/vecmath.h"
#include "raycore/raycore.h"
#include "shading/shading_options.h"

namespace rt {

/// Radiance's ray type bits (ray.h); a ray's `crtype` ORs them along its path.
enum RayTypeBits : unsigned {
    kPrimaryRay = 1,
    kShadowRay = 2,
    kReflectedRay = 4,
    kRefractedRay = 8,
    kTransRay = 16,
    kAmbientRay = 32,
    kSpecularRay = 64,
};

/// One ray of the ray tree (Radiance's RAY, the fields lazyrad uses).
struct TracedRay {
    // Set before tracing.
    Vec3 org;
    Vec3 dir;                  // unit
    double rmax = 0;           // > 0 limits the distance
    unsigned rtype = kPrimaryRay;
    unsigned crtype = kPrimaryRay;
    int rlvl = 0;              // reflection level
    double rweight = 1;        // importance: Russian roulette, -lw, -dt
    /// Importance for light-source subdivision (-ds): like rweight, except
    /// that ambient sample rays carry their path's real coefficient instead
    /// of the cache's nominal 0.5 (see SampleAmbient).
    double sourceWeight = 1;
    Rgb rcoef{1, 1, 1};        // coefficient this ray's value will be multiplied by
    const TracedRay* parent = nullptr;
    int rsrc = -1;             // light source this shadow ray aims at, -1 for none
    int depth = 0;             // ray-tree depth for trace output
    /// Surface::modifierIds whose surfaces this ray passes (Radiance's
    /// clipset): set by antimatter the ray's path entered (ClipParams),
    /// inherited by every child. Null (the rule) or empty: none.
    const std::vector<int>* clip = nullptr;
    /// The medium the ray travels through, inherited by every child unless
    /// a dielectric sets it; null (the rule) for none: a vacuum.
    const Medium* medium = nullptr;

    // Filled by tracing.
    int surface = -1;          // hit surface (Scene::HitSurface(instance, surface)) or -1
    int instance = -1;         // instance the hit surface is in, -1 for none
    /// World to the space patterns start from (Scene::PatternSpace): an
    /// instance's object space; null for world space.
    const Transform* objectFromRender = nullptr;
    bool hitDistant = false;   // hit a distant source (surface is then that source)
    double rot = kFhuge;       // first intersection distance
    Vec3 rop;                  // intersection point
    Vec3 ron;                  // normal at rop, flipped by materials toward the ray
    Vec3 geometricNormal;      // unflipped normal as the surface defines it
    Vec3 pert;                 // normal perturbation (textures; mesh vertex normals), world space; negated with the surface
    double lu = 0, lv = 0;     // mesh (u,v) at the hit (Lu, Lv), 0 when none
    double rod = 0;            // -Dot(dir, ron): > 0 on the front
    Rgb pcol{1, 1, 1};         // pattern colour: the product of the patterns met
    bool irradianceHit = false;  // -I pretend hit (no object)
    bool lambertian = false;   // -i/-I: shade with Radiance's hidden Lamb material

    // Results.
    Rgb rcol;                  // radiance
    Rgb mcol;                  // mirrored part
    double rmt = kFhuge;       // mirror distance
    double rxt = kFhuge;       // unmirrored distance

    /// Normal (unit, either way round) of the surface this ray starts on, for
    /// RayCore's `leaving`: its parent's hit when it starts there; null for a
    /// primary ray and any other ray that starts on no known surface.
    const Vec3* Leaving() const {
        return parent && !parent->hitDistant && org == parent->rop ? &parent->ron : nullptr;
    }

    /// Whether the ray passes surfaces modified by `modifierId` (antimatter).
    bool Clips(int modifierId) const {
        return clip != nullptr && std::binary_search(clip->begin(), clip->end(), modifierId);
    }

    /// Radiance's hastexture: |pert|² > FTINY².
    bool Textured() const { return Dot(pert, pert) > kFtiny * kFtiny; }

    /// Turns the surface to face the other way (shading the side a ray sees).
    void FlipSurface() {
        ron = -ron;
        rod = -rod;
        pert = -pert;
    }

    double EffectiveDistance() const {
        return Bright(mcol) > 0.5 * Bright(rcol) ? rmt : rxt;
    }

    /// Records that the ray reached distant source `sourceSurface` (Radiance's
    /// sourcehit(): no hit point, the normal faces the ray).
    void SetDistantHit(int sourceSurface) {
        surface = sourceSurface;
        instance = -1;
        objectFromRender = nullptr;
        hitDistant = true;
        rot = kFhuge;
        rop = org;
        ron = geometricNormal = -dir;
        rod = 1.0;
    }

    /// Records where the ray hit a surface (before any shading flips).
    /// `patternSpace` is Scene::PatternSpace(hit.instance).
    void SetHit(const Hit& hit, const Transform* patternSpace) {
        surface = hit.surface;
        instance = hit.instance;
        objectFromRender = patternSpace;
        // rmt stays kFhuge unless a pure specular reflection sets it, as in
        // Radiance (its -oR prints 1e10 for an ordinary hit).
        rot = rxt = hit.t;
        rop = hit.point;
        ron = geometricNormal = hit.normal;
        rod = -Dot(dir, hit.normal);
        // Mesh vertex normals shade as a perturbation (o_mesh.c), so that
        // patterns still see the geometric normal.
        pert = hit.shadingNormal - hit.normal;
        lu = hit.u;
        lv = hit.v;
    }
};

}  // namespace rt
