// SPDX-License-Identifier: MIT
//
// The ray tree: rayorigin() limits, raytrace(), rayshade(), raytrans(),
// sourcehit() and the -I/-i irradiance modes (radiance-notes.md §1.9, §2.5).
#include "shading/integrator.h"

#include <cmath>
#include <cstdlib>

namespace rt {
namespace {

constexpr unsigned kReflectionTypes = kShadowRay | kReflectedRay | kAmbientRay | kSpecularRay;

/// -I: the measurement point is moved this far along the normal (Radiance's
/// rtrace uses 1.1e-4 for the ray origin and a pretend hit 1e-5 back), times
/// Scene::ToleranceScale() so that scenes smaller than a unit keep the same
/// proportions.
constexpr double kImmediateOffset = 1.1e-4;
constexpr double kImmediateHit = 1e-5;

bool HasGlowSky(const Scene& scene) {
    for (const Surface& s : scene.surfaces) {
        if (s.material >= 0 && scene.materials[s.material].type == MaterialType::Glow) return true;
    }
    return false;
}

}  // namespace

Integrator::Integrator(const Scene& scene, const RayCore& core, const ShadingOptions& shading,
                       const AmbientOptions& ambient, WarningSink warn,
                       std::shared_ptr<AmbientCache> cache)
    : scene_(scene),
      core_(core),
      shading_(shading),
      ambient_(ambient),
      warn_(std::move(warn)),
      rng_(shading.seed),
      cache_(std::move(cache)) {
    if (scene.functions) functionContext_ = std::make_unique<cal::Context>(*scene.functions);
    // Radiance's hidden "Lamb" material for -i/-I: reflectance π turns the
    // reflected radiance into irradiance.
    lambertian_.name = "Lamb";
    lambertian_.type = MaterialType::Plastic;
    lambertian_.args = {kPi, kPi, kPi, 0.0, 0.0};
    lambertian_.params = MakeMaterialParams(lambertian_.type, lambertian_.args);

    // With indirect bounces, a glow sky lights the scene through ambient rays,
    // so the absence of direct sources is not worth a warning (as Radiance).
    const bool quiet = ambient.bounces > 0 && HasGlowSky(scene);
    WarningSink sourceWarn = [this, quiet](const std::string& msg) {
        if (quiet && msg == "no light sources found") return;
        if (warn_) warn_(msg);
    };
    Rng frameRng(MixSeed(shading.seed, 0x5eed5eedULL));
    sources_ = FindLightSources(scene, sourceWarn, shading.uncorrelated, frameRng);

    ambientList_.insert(ambient.modifierList.begin(), ambient.modifierList.end());

    shadowCheckCounts_.resize(257);
    for (size_t n = 0; n < shadowCheckCounts_.size(); ++n) {
        shadowCheckCounts_[n] = static_cast<int>(std::pow(double(n), shading.direct.certainty) + 0.5);
    }

    opaqueShadows_ = shading.backfaceVisible;
    for (const Surface& s : scene.surfaces) {
        if (s.material < 0) continue;
        MaterialType t = scene.materials[s.material].type;
        if (IsTransparentType(t) || t == MaterialType::Illum) opaqueShadows_ = false;
    }
    // A mixture may be partly a hole, or partly a transparent material.
    for (const Pattern& p : scene.patterns) {
        if (p.kind == ModifierKind::Mixture) opaqueShadows_ = false;
    }
}

bool Integrator::StartChild(TracedRay& child, const TracedRay& parent, unsigned type,
                            const Rgb* coef) {
    child.org = parent.rop;
    child.parent = &parent;
    child.rtype = type;
    child.crtype = parent.crtype | type;
    child.depth = parent.depth + 1;
    child.rlvl = parent.rlvl + ((type & kReflectionTypes) ? 1 : 0);
    child.rcoef = coef ? *coef : Rgb(1, 1, 1);
    double w = coef ? std::fmin(1.0, Intens(*coef)) : 1.0;
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
    if (type == kShadowRay) return true;
    const int lr = shading_.limits.reflections;
    const double lw = shading_.limits.weight;
    if (lr <= 0 && coef) {
        if (lr < 0 && child.rlvl > -lr) return false;
        if (child.rweight >= lw) return true;
        // Russian roulette: survive with probability weight/lw, boosted.
        if (rng_.Uniform() * lw > child.rweight) return false;
        child.rcoef *= lw / child.rweight;
        child.rweight = lw;
        return true;
    }
    return child.rweight >= lw && child.rlvl <= std::abs(lr);
}

bool Integrator::HitDistantSource(TracedRay& ray) const {
    int found = -1;
    for (int i = 0; i < static_cast<int>(sources_.size()); ++i) {
        const LightSource& src = sources_[i];
        if (src.shape != LightSource::Shape::Distant) continue;
        if (ray.rsrc >= 0 && ray.rsrc != i) continue;  // an aimed ray tests its own source only
        if (2.0 * kPi * (1.0 - Dot(src.location, ray.dir)) > src.area) continue;
        const Material& m = scene_.materials[src.material];
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
    ray.SetDistantHit(sources_[found].surface);
    return true;
}

void Integrator::Trace(TracedRay& ray) {
    ++stats_.raysTraced;
    ray.rcol = Rgb();
    ray.mcol = Rgb();
    if (auto hit = core_.Intersect(ray.org, ray.dir, ray.rmax)) {
        ray.SetHit(*hit, scene_.PatternSpace(hit->instance));
        Shade(ray);
    } else if (ray.rmax > 0) {
        // -ld: nothing before the clipping distance; no distant-source test.
        ray.rot = kFhuge;
        ray.rop = ray.org + ray.dir * ray.rmax;
    } else if (HitDistantSource(ray)) {
        const Surface& source = scene_.surfaces[ray.surface];
        if (!ApplyModifiers(ray, source.patterns)) {
            ShadeMaterial(ray, scene_.materials[source.material]);
        }
    } else {
        ray.rot = kFhuge;
        ray.rop = ray.org;
    }
    Report(ray);
}

void Integrator::Shade(TracedRay& ray) {
    const Surface& surface = scene_.HitSurface(ray.instance, ray.surface);
    if (surface.material < 0 && surface.patterns.empty()) return;  // void: nothing to shade, black
    if (ApplyModifiers(ray, surface.patterns)) return;  // a mixture shaded it
    if (surface.material < 0) {
        // A chain of modifiers without material (a mixture that reached none,
        // or patterns only) is a hole in the surface, as in Radiance.
        PassThrough(ray);
        return;
    }
    ShadeSurfaceMaterial(ray, scene_.materials[surface.material]);
}

void Integrator::ShadeSurfaceMaterial(TracedRay& ray, const Material& m) {
    // -i: the first opaque, non-emitting surface reached along primary and
    // transmitted rays is measured as a Lambertian irradiance meter. The
    // transparent surfaces before it are passed straight through, unattenuated
    // (Radiance's irr_ignore and raytrans): the meter reads what arrives at the
    // surface behind the glass, not through it a second time.
    if (shading_.irradiance == IrradianceMode::AtHit &&
        (ray.crtype & ~(kPrimaryRay | kTransRay)) == 0 && !IsLightType(m.type)) {
        if (IsTransparentType(m.type)) {
            PassThrough(ray);
            return;
        }
        ray.lambertian = true;
        ShadeNormal(ray, lambertian_);
        return;
    }
    ShadeMaterial(ray, m);
}

void Integrator::PassThrough(TracedRay& ray) {
    TracedRay child;
    StartChild(child, ray, kTransRay, nullptr);  // always continues, whatever the limits
    child.dir = ray.dir;
    Trace(child);
    ray.mcol = child.mcol;
    ray.rcol = child.rcol;
    ray.rmt = ray.rot + child.rmt;
    ray.rxt = ray.rot + child.rxt;
}

Vec3 Integrator::OffWallsThroughSensor(Vec3 point, const Vec3& normal, double offset) const {
    // The surface the sensor sits on, just below the measuring point.
    const auto floor = core_.Intersect(point, -normal, 2 * offset);
    if (!floor) return point;
    const Frame frame = Frame::Around(normal);
    for (const Vec3& d : {frame.u, -frame.u, frame.v, -frame.v}) {
        // A surface through the point crosses this short probe at its middle.
        const auto wall = core_.Intersect(point - d * offset, d, 2 * offset);
        if (!wall || wall->SameSurface(*floor) ||
            std::fabs(wall->t - offset) > 1e-2 * offset) {
            continue;
        }
        // The room is on the side of the wall where the floor goes on.
        const auto floorOn = [&](double side) {
            const auto h = core_.Intersect(point + wall->normal * (side * offset), -normal,
                                           2 * offset);
            return h && h->SameSurface(*floor);
        };
        const bool front = floorOn(1), back = floorOn(-1);
        if (front != back) point += wall->normal * (front ? offset : -offset);
    }
    return point;
}

void Integrator::FlipSurface(TracedRay& ray) const {
    ray.ron = -ray.ron;
    ray.rod = -ray.rod;
    ray.pert = -ray.pert;
}

void Integrator::Report(const TracedRay& ray) {
    if (!trace_) return;
    if (ray.rtype == kShadowRay && !traceShadows_) return;
    trace_(MakeResult(ray));
}

RayResult Integrator::WithAmbientOutcome(RayResult r) const {
    r.ambientOutcome = firstOutcome_;
    r.indirectIrradiance = firstIndirectIrradiance_;
    return r;
}

RayResult Integrator::MakeResult(const TracedRay& ray) {
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
        const Surface& s = scene_.HitSurface(ray.instance, ray.surface);
        // rtrace's -on is raynormal(). Without any perturbation that is ron
        // renormalised; ron is unit already, and taking it as it is keeps
        // the output of untextured surfaces bit for bit what it was.
        if (ray.pert == Vec3()) {
            r.normal = ray.ron;
        } else {
            PerturbedNormal(ray, r.normal);
        }
        r.geometricNormal = ray.geometricNormal;
        r.surfaceName = s.name;
        r.u = ray.lu;
        r.v = ray.lv;
        r.modifierName = s.modifierName;
        r.materialName = s.material >= 0 ? std::string_view(scene_.materials[s.material].name)
                                         : std::string_view("void");
    }
    return r;
}

RayResult Integrator::TraceInput(const Vec3& org, const Vec3& dir, double rmax,
                                 std::uint64_t rayIndex) {
    // -u+: a stream per input position, so identical rays are independent
    // samples; -u-: the same stream for every ray (correlated sampling).
    rng_.Seed(MixSeed(shading_.seed, shading_.uncorrelated ? rayIndex : 0));
    firstAmbientSeen_ = false;
    firstOutcome_ = RayResult::AmbientOutcome::None;
    firstIndirectIrradiance_ = Rgb();
    TracedRay ray;
    ray.org = org;
    ray.dir = dir;
    ray.rmax = rmax;
    if (shading_.irradiance == IrradianceMode::Immediate) {
        // The input is a measurement point and the normal of the measuring
        // plane: pretend a ray came down the normal and hit a Lambertian meter.
        const double scale = scene_.ToleranceScale();
        ray.org = org + dir * (kImmediateOffset * scale);
        ray.dir = -dir;
        ray.rmax = 0;
        ray.rot = ray.rxt = ray.rmt = kImmediateHit * scale;
        ray.rop = OffWallsThroughSensor(ray.org + ray.dir * ray.rot, dir,
                                        kImmediateOffset * scale);
        ray.ron = dir;
        ray.rod = 1.0;
        ray.irradianceHit = true;
        ray.lambertian = true;
        ShadeNormal(ray, lambertian_);
        Report(ray);
        return WithAmbientOutcome(MakeResult(ray));
    }
    Trace(ray);
    return WithAmbientOutcome(MakeResult(ray));
}

}  // namespace rt
