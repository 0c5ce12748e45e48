// SPDX-License-Identifier: MIT
//
// The ray tree: rayorigin() limits, raytrace(), rayshade(), raytrans(),
// sourcehit() and the -I/-i irradiance modes (radiance-notes.md §1.9, §2.5).
#include "shading/ray_tree.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "core/error.h"
#include "shading/materials.h"

namespace rt {
namespace {

constexpr unsigned kReflectionTypes = kShadowRay | kReflectedRay | kAmbientRay | kSpecularRay;

/// -I: the measurement point is moved this far along the normal (Radiance's
/// rtrace uses 1.1e-4 for the ray origin and a pretend hit 1e-5 back), times
/// Scene::ToleranceScale() so that scenes smaller than a unit keep the same
/// proportions.
constexpr double kImmediateOffset = 1.1e-4;
constexpr double kImmediateHit = 1e-5;

/// exp(-optical depth) per channel as Radiance takes it: 1 below FTINY, 0
/// above 92.
Rgb Attenuation(const Rgb& depth) {
    Rgb a;
    for (int i = 0; i < 3; ++i) {
        a[i] = depth[i] <= kFtiny ? 1.0 : depth[i] > 92.0 ? 0.0 : std::exp(-depth[i]);
    }
    return a;
}

}  // namespace

double RayTree::MediumImportance(const TracedRay& parent) {
    if (!parent.medium) return 1.0;
    const Rgb& e = parent.medium->extinction;
    const double re = std::min({e.r, e.g, e.b}) * parent.rot;
    if (re <= 0.1) return 1.0;
    return re > 92.0 ? 0.0 : std::exp(-re);
}

[[noreturn]] void ThrowZeroWeightRoulette() {
    // Radiance's rayorigin(): Russian roulette (-lr <= 0) with no weight to
    // roll against (-lw <= 0) stops the run at the first ray that carries a
    // coefficient: a reflected or transmitted ray here, a hemisphere ray in
    // IndirectLight::Ambient, never a shadow ray.
    ThrowUserError("zero ray weight in Russian roulette");
}

bool RayTree::StartChild(ThreadState& ts, TracedRay& child, const TracedRay& parent,
                         unsigned type, const Rgb* coef) const {
    child.org = parent.rop;
    child.parent = &parent;
    child.rtype = type;
    child.crtype = parent.crtype | type;
    child.depth = parent.depth + 1;
    child.clip = parent.clip;
    child.rlvl = parent.rlvl + ((type & kReflectionTypes) ? 1 : 0);
    child.rcoef = coef ? *coef : Rgb(1, 1, 1);
    double w = coef ? std::min(1.0, Intens(*coef)) : 1.0;
    child.medium = parent.medium;
    w *= MediumImportance(parent);
    child.rweight = parent.rweight * w;
    child.sourceWeight = parent.sourceWeight * w;
    if (type & kReflectionTypes) {
        child.rmax = 0;
        child.rsrc = type == kShadowRay ? parent.rsrc : -1;
    } else {
        child.rsrc = parent.rsrc;
        child.rmax = parent.rmax > 0 ? parent.rmax - parent.rot : 0;
    }
    if (child.rweight <= 0) return false;
    // A shadow ray and everything it spawns go on whatever their weight,
    // neither cut nor put to Russian roulette (rayorigin()'s "shadow
    // commitment"): the source's light must arrive whole or not at all.
    if (child.crtype & kShadowRay) return true;
    const int lr = s_.shading.limits.reflections;
    const double lw = s_.shading.limits.weight;
    if (lr <= 0 && coef) {
        if (lw <= 0) ThrowZeroWeightRoulette();
        if (lr < 0 && child.rlvl > -lr) return false;
        if (child.rweight >= lw) return true;
        // Russian roulette: survive with probability weight/lw, boosted.
        if (ts.rng.Uniform() * lw > child.rweight) return false;
        child.rcoef *= lw / child.rweight;
        child.rweight = lw;
        return true;
    }
    return child.rweight >= lw && child.rlvl <= std::abs(lr);
}

bool RayTree::HitDistantSource(TracedRay& ray) const {
    int found = -1;
    for (int i = 0; i < static_cast<int>(s_.sources.size()); ++i) {
        const LightSource& src = s_.sources[i];
        // A distant image in a mirror is reached only through the mirror.
        if (src.shape != LightSource::Shape::Distant || src.IsVirtual()) continue;
        if (ray.rsrc >= 0 && ray.rsrc != i) continue;  // an aimed ray tests its own source only
        if (2.0 * kPi * (1.0 - Dot(src.location, ray.dir)) > src.area) continue;
        const Material& m = s_.scene.materials[src.material];
        // A transparent illum is counted directly: ambient and specular rays
        // must not see it again.
        bool transparentIllum = m.type == MaterialType::Illum && m.alternate < 0;
        if (!src.skip && !transparentIllum) {
            found = i;
            break;
        }
        if (transparentIllum && (ray.crtype & (kAmbientRay | kSpecularRay))) return false;
        if (src.skip && found < 0) found = i;
    }
    if (found < 0) return false;
    ray.SetDistantHit(s_.sources[found].surface);
    return true;
}

RayTree::Met RayTree::Cast(ThreadState& ts, TracedRay& ray) const {
    ++ts.stats.raysTraced;
    if (auto hit = s_.core.Intersect(ray.org, ray.dir, ray.rmax, ray.Leaving())) {
        ray.SetHit(*hit, s_.scene.PatternSpace(hit->instance));
        return Met::Surface;
    }
    if (ray.rmax > 0) {
        // -ld: nothing before the clipping distance; no distant-source test.
        ray.rot = kFhuge;
        ray.rop = ray.org + ray.dir * ray.rmax;
        return Met::Nothing;
    }
    if (HitDistantSource(ray)) return Met::DistantSource;
    ray.rot = kFhuge;
    ray.rop = ray.org;
    return Met::Nothing;
}

void RayTree::Trace(ThreadState& ts, TracedRay& ray) const {
    ray.rcol = Rgb();
    ray.mcol = Rgb();
    switch (Cast(ts, ray)) {
        case Met::Surface: Shade(ts, ray); break;
        case Met::DistantSource: ShadeDistantSource(ts, ray); break;
        case Met::Nothing: break;
    }
    // Trace output shows the value before the medium acts on it, as
    // Radiance's raytrace() reports before rayparticipate().
    Report(ts, ray);
    Participate(ts, ray);
}

void RayTree::ParticipateIn(ThreadState& ts, const Medium& medium, TracedRay& ray) const {
    if (Intens(medium.extinction) <= 1.0 / kFhuge) return;
    const bool shadow = (ray.crtype & kShadowRay) != 0;
    Rgb depth = medium.extinction * ray.rot;
    if (shadow) depth *= Rgb(1, 1, 1) - medium.albedo;  // scattered light is not lost to a source
    const Rgb kept = Attenuation(depth);
    ray.rcol *= kept;
    if (shadow || Intens(medium.albedo) <= kFtiny) return;
    // Light scattered into the ray, from the ambient value and from the
    // light sources the medium lists (none for the global medium).
    ray.rcol += medium.albedo * s_.ambient.value * (Rgb(1, 1, 1) - kept);
    if (medium.scatterCount > 0) ScatterSourceLight(ts, medium, ray);
}

void RayTree::ScatterSourceLight(ThreadState& ts, const Medium& medium, TracedRay& ray) const {
    const double g = medium.eccentricity;
    if (g >= 1.0 - kFtiny || ray.rot >= kFhuge) return;
    // -ms apart along the ray, at least one sample and at most 16 (MAXSSAMP).
    constexpr int kMaxSamples = 16;
    const double spacing = s_.shading.medium.samplingDistance;
    int samples = 1;
    if (spacing > kFtiny) samples = std::clamp(static_cast<int>(ray.rot / spacing + 0.5), 1, kMaxSamples);
    for (int i = medium.scatterCount - 1; i >= 0; --i) {
        const int source = medium.scatterSources[static_cast<std::size_t>(i)];
        for (int j = 0; j < samples; ++j) {
            // Stratified along the ray; the light scattered at t reaches the
            // ray's origin through t of the medium.
            const double t = ray.rot * (j + ts.rng.Uniform()) / samples;
            Rgb toOrigin;  // srcscatter()'s own: no FTINY floor, unlike Attenuation
            for (int c = 0; c < 3; ++c) {
                const double depth = medium.extinction[c] * t;
                toOrigin[c] = depth > 92.0 ? 0.0 : std::exp(-depth);
            }
            if (Intens(toOrigin) <= kFtiny) break;  // the rest is farther still
            SourceSample sample;
            if (!SampleWholeSource(s_.sources, source, ray.org + ray.dir * t, s_.shading.direct,
                                   ts.rng, sample)) {
                continue;
            }
            // Radiance's obstructor cache is asked first here too, and told
            // what stopped a ray that came back black.
            if (direct_.KnownBlocked(ts, sample, ray.org + ray.dir * t)) {
                ++ts.stats.samplesObstructed;
                continue;
            }
            // A shadow ray of its own, as srcscatter() makes it: no parent
            // (full weight, no antimatter passed), the ray's medium, followed
            // past whatever transmits.
            TracedRay sray;
            sray.org = ray.org + ray.dir * t;
            sray.dir = sample.dir;
            sray.rtype = sray.crtype = kShadowRay;
            sray.rsrc = source;
            sray.medium = &medium;
            sray.depth = ray.depth + 1;
            Trace(ts, sray);
            if (Bright(sray.rcol) <= kFtiny) {
                direct_.RecordBlockerOf(ts, sray);
                continue;
            }
            // Henyey–Greenstein phase function (4π-normalised), the sample's
            // solid angle, and this sample's share of the ray's length.
            double phase = 1.0;
            if (g > kFtiny) {
                const double d = 1.0 + g * g - 2.0 * g * Dot(ray.dir, sray.dir);
                phase = (1.0 - g * g) / (d * std::sqrt(d));
            }
            const double factor = phase * sample.omega * ray.rot / (4.0 * kPi * samples);
            ray.rcol += sray.rcol * medium.extinction * medium.albedo * toOrigin * factor;
        }
    }
}

Rgb RayTree::ShadowTransmittance(const Medium& medium, double distance) {
    if (Intens(medium.extinction) <= 1.0 / kFhuge) return Rgb(1, 1, 1);
    return Attenuation(medium.extinction * (Rgb(1, 1, 1) - medium.albedo) * distance);
}

void RayTree::Shade(ThreadState& ts, TracedRay& ray) const {
    const Surface& surface = s_.scene.HitSurface(ray.instance, ray.surface);
    // Inside antimatter that clips it, the surface is not there (raycont()).
    if (ray.Clips(surface.modifierId)) {
        PassThrough(ts, ray);
        return;
    }
    if (surface.material < 0 && surface.patterns.empty()) return;  // void: nothing to shade, black
    if (ApplyModifiers(ts, ray, surface.patterns)) return;  // a mixture shaded it
    if (surface.material < 0) {
        // A chain of modifiers without material (a mixture that reached none,
        // or patterns only) is a hole in the surface, as in Radiance.
        PassThrough(ts, ray);
        return;
    }
    ShadeSurfaceMaterial(ts, ray, s_.scene.materials[surface.material]);
}

void RayTree::ShadeSurfaceMaterial(ThreadState& ts, TracedRay& ray, const Material& m) const {
    // -i: the first opaque, non-emitting surface reached along primary and
    // transmitted rays is measured as a Lambertian irradiance meter. The
    // transparent surfaces before it are passed straight through, unattenuated
    // (Radiance's irr_ignore and raytrans): the meter reads what arrives at the
    // surface behind the glass, not through it a second time.
    if (s_.shading.irradiance == IrradianceMode::AtHit &&
        (ray.crtype & ~(kPrimaryRay | kTransRay)) == 0 && !IsLightType(m.type) &&
        m.type != MaterialType::Antimatter) {
        if (IsTransparentType(m.type) ||
            (m.type == MaterialType::Bsdf && std::get<BsdfParams>(m.params).proxy)) {
            PassThrough(ts, ray);
            return;
        }
        ray.lambertian = true;
        ShadeNormal(*this, ts, ray, s_.lambertian);
        return;
    }
    ShadeMaterial(ts, ray, m);
}

void RayTree::ShadeMaterial(ThreadState& ts, TracedRay& ray, const Material& m) const {
    // The material's own chain (Radiance's raytexture(m->omod)), before it
    // computes anything. Mixtures on it cannot reach a material (refused at
    // load as "conflicting material").
    ApplyModifiers(ts, ray, m.patterns);
    ShadeByType(*this, ts, ray, m);
}

void RayTree::PassThrough(ThreadState& ts, TracedRay& ray,
                          const std::vector<int>* clip) const {
    TracedRay child;
    StartChild(ts, child, ray, kTransRay, nullptr);  // always continues, whatever the limits
    child.clip = clip;
    Continue(ts, ray, child);
}

void RayTree::PassThrough(ThreadState& ts, TracedRay& ray, const Medium& beyond) const {
    TracedRay child;
    // Unlike raytrans(), m_mist.c stops a ray whose weight the medium
    // brought below -lw (StartChild follows shadow rays whatever it).
    if (!StartChild(ts, child, ray, kTransRay, nullptr)) return;
    child.medium = &beyond;
    Continue(ts, ray, child);
}

void RayTree::Continue(ThreadState& ts, TracedRay& ray, TracedRay& child) const {
    child.dir = ray.dir;
    Trace(ts, child);
    ray.mcol = child.mcol;
    ray.rcol = child.rcol;
    ray.rmt = ray.rot + child.rmt;
    ray.rxt = ray.rot + child.rxt;
}

Vec3 RayTree::OffWallsThroughSensor(Vec3 point, const Vec3& normal, double offset) const {
    // The surface the sensor sits on, just below the measuring point.
    const auto floor = s_.core.Intersect(point, -normal, 2 * offset);
    if (!floor) return point;
    const Frame frame = Frame::Around(normal);
    for (const Vec3& d : {frame.u, -frame.u, frame.v, -frame.v}) {
        // A surface through the point crosses this short probe at its middle.
        const auto wall = s_.core.Intersect(point - d * offset, d, 2 * offset);
        if (!wall || wall->SameSurface(*floor) ||
            std::fabs(wall->t - offset) > 1e-2 * offset) {
            continue;
        }
        // The room is on the side of the wall where the floor goes on.
        const auto floorOn = [&](double side) {
            const auto h = s_.core.Intersect(point + wall->normal * (side * offset), -normal,
                                           2 * offset);
            return h && h->SameSurface(*floor);
        };
        const bool front = floorOn(1), back = floorOn(-1);
        if (front != back) point += wall->normal * (front ? offset : -offset);
    }
    return point;
}

void RayTree::Report(ThreadState& ts, const TracedRay& ray) const {
    if (!ts.trace) return;
    if (ray.rtype == kShadowRay && !ts.traceShadows) return;
    ts.trace(MakeResult(ts, ray));
}

void RayTree::ReportFollowedShadow(ThreadState& ts, const TracedRay& ray) const {
    if (ts.trace) ts.trace(MakeResult(ts, ray));
}

void RayTree::ReportShadowAtDistantSource(ThreadState& ts, TracedRay& ray) const {
    if (!ts.trace || !ts.traceShadows || !HitDistantSource(ray)) return;
    ShadeDistantSource(ts, ray);
    Report(ts, ray);
}

void RayTree::ShadeDistantSource(ThreadState& ts, TracedRay& ray) const {
    const Surface& source = s_.scene.surfaces[ray.surface];
    if (!ApplyModifiers(ts, ray, source.patterns)) {
        ShadeMaterial(ts, ray, s_.scene.materials[source.material]);
    }
}

RayResult RayTree::MakeResult(ThreadState& ts, const TracedRay& ray) const {
    RayResult r;
    r.origin = ray.org;
    r.direction = ray.dir;
    r.value = ray.rcol;
    r.mirrored = ray.mcol;
    r.mirrorLength = ray.rmt;
    r.unmirroredLength = ray.rxt;
    r.firstLength = ray.rot;
    r.point = ray.rop;
    r.weight = ray.rweight;
    r.depth = ray.depth;
    Rgb coef(1, 1, 1);
    for (const TracedRay* p = &ray; p != nullptr; p = p->parent) coef *= p->rcoef;
    r.coefficient = coef;
    r.contribution = ray.rcol * coef;
    if (ray.surface >= 0 && !ray.irradianceHit) {
        const Surface& s = s_.scene.HitSurface(ray.instance, ray.surface);
        // rtrace's -on is raynormal(). Without any perturbation that is ron
        // renormalised; ron is unit already, and taking it as it is keeps
        // the output of untextured surfaces bit for bit what it was.
        if (ray.pert == Vec3()) {
            r.normal = ray.ron;
        } else {
            PerturbedNormal(s_.scene, ts, ray, r.normal);
        }
        r.geometricNormal = ray.geometricNormal;
        r.surfaceName = s.name;
        r.u = ray.lu;
        r.v = ray.lv;
        r.modifierName = s.modifierName;
        r.materialName = s.material >= 0 ? std::string_view(s_.scene.materials[s.material].name)
                                         : std::string_view("void");
    }
    return r;
}

RayResult RayTree::TraceInput(ThreadState& ts, const Vec3& org, const Vec3& dir, double rmax,
                              std::uint64_t rayIndex) const {
    // -u+: a stream per input position, so identical rays are independent
    // samples; -u-: the same stream for every ray (correlated sampling).
    ts.StartInputRay(s_.shading, rayIndex);
    // The result carries the indirect outcome at the first surface shaded.
    const auto withOutcome = [&ts](RayResult r) {
        r.ambientOutcome = ts.firstOutcome;
        r.indirectIrradiance = ts.firstIndirectIrradiance;
        return r;
    };
    TracedRay ray;
    ray.org = org;
    ray.dir = dir;
    ray.rmax = rmax;
    if (s_.hasMedium) ray.medium = &s_.medium;
    if (s_.shading.irradiance == IrradianceMode::Immediate) {
        // The input is a measurement point and the normal of the measuring
        // plane: pretend a ray came down the normal and hit a Lambertian meter.
        const double scale = s_.scene.ToleranceScale();
        ray.org = org + dir * (kImmediateOffset * scale);
        ray.dir = -dir;
        ray.rmax = 0;
        ray.rot = ray.rxt = kImmediateHit * scale;  // rmt stays kFhuge (Radiance)
        ray.rop = OffWallsThroughSensor(ray.org + ray.dir * ray.rot, dir,
                                        kImmediateOffset * scale);
        ray.ron = dir;
        ray.rod = 1.0;
        ray.irradianceHit = true;
        ray.lambertian = true;
        // Shaded directly (Radiance calls the Lambertian's shading function,
        // not raytrace()), so trace output (-ot, -oT) shows no line for it.
        ShadeNormal(*this, ts, ray, s_.lambertian);
        return withOutcome(MakeResult(ts, ray));
    }
    if (s_.shading.castOnly) {
        Cast(ts, ray);
    } else {
        Trace(ts, ray);
    }
    return withOutcome(MakeResult(ts, ray));
}

}  // namespace rt

