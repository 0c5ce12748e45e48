// SPDX-License-Identifier: MIT
#include "shading/indirect.h"

#include <algorithm>
#include <cmath>

#include "shading/ray_tree.h"

namespace rt {
namespace {

/// Radiance's assumed average reflectance: with the cache, every ambient
/// sample ray weighs this much of its parent (AVGREFL).
constexpr double kAverageReflectance = 0.5;

}  // namespace

bool IndirectLight::Excluded(const TracedRay& ray) const {
    if (s_.ambientList.empty() && !s_.ambient.listIsInclude) return false;
    if (ray.surface < 0 || ray.hitDistant) return false;  // -I: no object to test
    const bool listed =
        s_.ambientList.count(s_.scene.HitSurface(ray.instance, ray.surface).modifierName) > 0;
    return s_.ambient.listIsInclude ? !listed : listed;
}

Rgb IndirectLight::Fallback(const Rgb& coefficient) const {
    if (!s_.cache) return coefficient * s_.ambient.value;
    if (s_.ambient.valueWeight <= 0) return coefficient * s_.ambient.value;
    const AmbientCache::LogBrightSum s = s_.cache->logBright();
    return coefficient *
           AveragedAmbientValue(s_.ambient.value, s_.ambient.valueWeight, s.sum, s.count);
}

void IndirectLight::Note(ThreadState& ts, RayResult::AmbientOutcome outcome,
                         const Rgb& meanRadiance) {
    if (ts.firstAmbientSeen || ts.ambient.depth != 0) return;
    ts.firstAmbientSeen = true;
    ts.firstOutcome = outcome;
    ts.firstIndirectIrradiance = meanRadiance * kPi;
}

Rgb IndirectLight::Ambient(ThreadState& ts, const Rgb& coefficient, const TracedRay& ray,
                           const Vec3& normal, const OtherRadianceRef* otherRadiance) const {
    using Outcome = RayResult::AmbientOutcome;
    if (s_.ambient.divisions <= 0 || ts.ambient.depth >= s_.ambient.bounces || Excluded(ray) ||
        Bright(coefficient) <= kFtiny) {
        const Rgb value = Fallback(coefficient);
        if (s_.ambient.bounces > 0) Note(ts, Outcome::Fallback, Fallback(Rgb(1, 1, 1)));
        return value;
    }
    AmbientQuery query;
    query.point = ray.rop;
    query.normal = ray.ron;
    query.shadingNormal = normal;
    query.rayWeight = ray.rweight;
    // Hemisphere rays carry a coefficient in Radiance, so Russian roulette
    // with no weight limit stops the run at the first of them.
    const bool zeroWeightRoulette =
        s_.shading.limits.reflections <= 0 && s_.shading.limits.weight <= 0;
    // One hemisphere ray (Radiance's ambsample()).
    const auto trace = [&](const Vec3& dir,
                           const AmbientSampleShare& share) -> std::optional<AmbientSample> {
        if (zeroWeightRoulette) ThrowZeroWeightRoulette();
        // With the cache every sample ray weighs half its parent; without
        // it, each carries its true share of the coefficient.
        const Rgb sampleCoef = share.caching ? Rgb::Grey(kAverageReflectance)
                                             : coefficient / static_cast<double>(share.divisions);
        // Hemisphere samples never go to Russian roulette, with or without
        // the cache; only -lr's depth cap refuses them. Their number is
        // already set by the weight, and -ab bounds the depth. Radiance
        // rolls for them below -lw and fails the division of every loser:
        // below -lw no record can be cached, every query computes its own
        // hemisphere, and the work grows as (samples/2)^depth. Counting
        // losers as zeros instead kept it linear, but one coarse record per
        // wall then carried that noise multiplicatively down the levels, and
        // deep bounces came out dark (README, "Differences").
        TracedRay child;
        tree_.StartChild(ts, child, ray, kAmbientRay, nullptr);
        // std::min(1.0, x) is std::fmin's value for every x, NaN included,
        // without its library call (one per hemisphere ray).
        child.rweight = ray.rweight * std::min(1.0, Intens(sampleCoef));
        child.rcoef = sampleCoef;
        const int lr = s_.shading.limits.reflections;
        if (lr != 0 && child.rlvl > std::abs(lr)) return std::nullopt;
        // Light sources seen from the sample's hit are subdivided (-ds) for
        // the path's real importance: the cache's nominal 0.5 would halve
        // the subdivision distance and turn lamps partly hidden by an edge
        // into all-or-nothing points, which darkens penumbrae seen from the
        // hemisphere (README, "Differences").
        child.sourceWeight = ray.sourceWeight * std::min(1.0, Intens(coefficient));
        child.org = ray.rop;
        child.dir = dir;
        tree_.Trace(ts, child);
        return AmbientSample{child.rcol, child.EffectiveDistance()};
    };
    const auto occluded = [&](const Vec3& from, const Vec3& dir, double length) {
        return s_.core.Occluded(from, dir, length);
    };
    // The irradiance cache times its sampling; the direct light at the
    // samples' hits is reported apart, so it is taken off here.
    const double directBefore = ts.stats.secondsDirect;
    const bool outermost = ts.ambient.depth == 0;
    const IrradianceResult r = s_.irradiance.Evaluate(query, Intens(coefficient), ts.ambient,
                                                      ts.stats, ts.rng, trace, occluded,
                                                      otherRadiance);
    if (ts.ambient.timing && outermost) {
        ts.stats.secondsSampling -= ts.stats.secondsDirect - directBefore;
    }
    if (!r.value) return Fallback(coefficient);
    switch (r.source) {
        case IrradianceResult::Source::Interpolated: Note(ts, Outcome::Interpolated, *r.value); break;
        case IrradianceResult::Source::Extrapolated: Note(ts, Outcome::Extrapolated, *r.value); break;
        default: Note(ts, Outcome::Computed, *r.value); break;
    }
    return coefficient * *r.value;
}

}  // namespace rt
