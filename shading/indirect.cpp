// SPDX-License-Identifier: MIT
//
#include "shading/indirect.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "ambient/leak.h"
#include "shading/ray_tree.h"

namespace rt {
namespace {

double Now() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

/// Radiance's assumed average reflectance: weights ambient sample rays and
/// makes deeper records count less (AVGREFL).
constexpr double kAverageReflectance = 0.5;

}  // namespace

bool IndirectLight::Excluded(const TracedRay& ray) const {
    if (s_.ambientList.empty() && !s_.ambient.listIsInclude) return false;
    if (ray.surface < 0 || ray.hitDistant) return false;  // -I: no object to test
    const bool listed = s_.ambientList.count(s_.scene.HitSurface(ray.instance, ray.surface).modifierName) > 0;
    return s_.ambient.listIsInclude ? !listed : listed;
}

Rgb IndirectLight::Fallback(const Rgb& coefficient) const {
    if (!s_.cache) return coefficient * s_.ambient.value;
    if (s_.ambient.valueWeight <= 0) return coefficient * s_.ambient.value;
    const AmbientCache::LogBrightSum s = s_.cache->logBright();
    return coefficient * AveragedAmbientValue(s_.ambient.value, s_.ambient.valueWeight, s.sum, s.count);
}

Hemisphere IndirectLight::Sample(ThreadState& ts, const TracedRay& ray, const Rgb& coefficient,
                                  double weight) const {
    const bool caching = s_.cache != nullptr;
    HemisphereOptions options;
    options.divisions = s_.ambient.divisions;
    options.superSamples = s_.ambient.superSamples;
    options.weight = weight;
    options.caching = caching;
    const DivisionCounts counts = HemisphereDivisions(options);
    // With the cache every sample ray weighs half its parent (Radiance's
    // AVGREFL); without it, each carries its true share of the coefficient.
    const Rgb sampleCoef = caching ? Rgb::Grey(kAverageReflectance)
                                   : coefficient / static_cast<double>(counts.total());
    const Vec3 point = ray.rop;
    // Timing: only the outermost hemisphere counts (deeper ones are inside
    // it), less what its samples spend in direct lighting and lookups.
    const bool timeThis = ts.timing && ts.ambientDepth == 0;
    const double start = timeThis ? Now() : 0.0;
    const double directBefore = ts.stats.secondsDirect, lookupBefore = ts.stats.secondsLookup;
    ++ts.ambientDepth;
    ++ts.stats.hemispheres;
    Hemisphere h = SampleHemisphere(ray.ron, options, ts.rng, [&](const Vec3& dir)
                                        -> std::optional<AmbientSample> {
        // Hemisphere samples never go to Russian roulette, with or without
        // the cache; only -lr's depth cap refuses them. Their number is
        // already set by the weight, and -ab bounds the depth. Radiance
        // rolls for them below -lw and fails the division of every loser:
        // below -lw no record can be cached, every query computes its own
        // hemisphere, and the work grows as (samples/2)^depth (-ab 12 -lr -60
        // in a closed box never ended). Counting losers as zeros instead
        // kept it linear, but one coarse record per wall then carried that
        // noise multiplicatively down 40 levels (a rho 0.999 box 62 % dark
        // for most seeds at -ar 4 -ab 50).
        TracedRay child;
        tree_.StartChild(ts, child, ray, kAmbientRay, nullptr);
        child.rweight = ray.rweight * std::fmin(1.0, Intens(sampleCoef));
        child.rcoef = sampleCoef;
        const int lr = s_.shading.limits.reflections;
        if (lr != 0 && child.rlvl > std::abs(lr)) return std::nullopt;
        // Light sources seen from the sample's hit are subdivided (-ds) for
        // the path's real importance: the cache's nominal 0.5 would halve the
        // subdivision distance and turn lamps partly hidden by an edge into
        // all-or-nothing points (the cornell corridor behind the tall block
        // came out 4 % dark against Radiance's converged reference).
        child.sourceWeight = ray.sourceWeight * std::fmin(1.0, Intens(coefficient));
        child.org = point;
        child.dir = dir;
        tree_.Trace(ts, child);
        const double dist = child.EffectiveDistance();
        if (!(dist > s_.scene.distanceTolerance)) return std::nullopt;
        return AmbientSample{child.rcol, dist};
    });
    --ts.ambientDepth;
    if (timeThis) {
        ts.stats.secondsSampling += (Now() - start) - (ts.stats.secondsDirect - directBefore) -
                                  (ts.stats.secondsLookup - lookupBefore);
    }
    return h;
}

void IndirectLight::Note(ThreadState& ts, RayResult::AmbientOutcome outcome,
                         const Rgb& meanRadiance) {
    if (ts.firstAmbientSeen || ts.ambientDepth != 0) return;
    ts.firstAmbientSeen = true;
    ts.firstOutcome = outcome;
    ts.firstIndirectIrradiance = meanRadiance * kPi;
}

Rgb IndirectLight::Ambient(ThreadState& ts, const Rgb& coefficient, const TracedRay& ray,
                           const Vec3& normal) const {
    using Outcome = RayResult::AmbientOutcome;
    if (s_.ambient.divisions <= 0 || ts.ambientDepth >= s_.ambient.bounces || Excluded(ray) ||
        Bright(coefficient) <= kFtiny) {
        const Rgb value = Fallback(coefficient);
        if (s_.ambient.bounces > 0) Note(ts, Outcome::Fallback, Fallback(Rgb(1, 1, 1)));
        return value;
    }
    if (!s_.cache) {
        // -aa 0: a fresh hemisphere for every shading point, sized by the
        // ray's weight so that sample rays stay near -lw.
        double weight = ray.rweight;
        const double lw = s_.shading.limits.weight;
        if (lw > 0) {
            weight = std::min(weight, 0.8 * Intens(coefficient) * ray.rweight /
                                          (std::max(s_.ambient.divisions, 1) * lw));
        }
        Hemisphere h = Sample(ts, ray, coefficient, weight);
        if (!h.anySample) return Fallback(coefficient);
        Note(ts, Outcome::Computed, h.value);
        return coefficient * h.value;
    }
    AmbientQuery query;
    query.point = ray.rop;
    query.normal = ray.ron;
    query.shadingNormal = normal;
    query.level = ts.ambientDepth;
    query.rayWeight = ray.rweight;
    ++ts.stats.ambientLookups;
    int used = 0;
    const double lookupStart = ts.timing ? Now() : 0.0;
    // Radiance 5's leak test: a record that saw a wall nearby in the query's
    // direction is not used if the wall stands between them.
    const auto hidden = [&](const AmbientRecord& record) {
        if (!CorralCovers(record, query.point)) return false;
        const LeakTest leak = MakeLeakTest(query.point, query.normal, record.position,
                                           record.normal, s_.scene.distanceTolerance);
        switch (leak.outcome) {
            case LeakTest::Outcome::kVisible: return false;
            case LeakTest::Outcome::kHidden: return true;
            case LeakTest::Outcome::kTrace: break;
        }
        ++ts.stats.leakRays;
        return s_.core.Occluded(query.point, leak.dir, leak.length);
    };
    std::optional<Rgb> interpolated = s_.cache->Interpolate(query, &used, hidden);
    if (ts.timing) ts.stats.secondsLookup += Now() - lookupStart;
    if (auto value = interpolated) {
        ++ts.stats.ambientHits;
        Note(ts, used > 1 ? Outcome::Interpolated : Outcome::Extrapolated, *value);
        return coefficient * *value;
    }
    // A new record at this level: weight 0.5^level, or about the ray's own
    // weight when the ray matters much less than that (§4.4). Below -lw,
    // Russian roulette raises the survivors' weight to -lw, above 0.5^level;
    // the record takes that weight too, or no query at this depth (all
    // carrying -lw) could use it and every one would compute its own.
    double weight = std::pow(kAverageReflectance, ts.ambientDepth);
    if (ray.rweight < 0.1 * weight) weight = 1.25 * ray.rweight;
    weight = std::max(weight, ray.rweight);
    const int level = ts.ambientDepth;
    Hemisphere h = Sample(ts, ray, coefficient, weight);
    // No division got a sample (every ray refused, e.g. by -lr): Radiance's
    // makeambient() failure, answered with the ambient value.
    if (!h.anySample) return Fallback(coefficient);
    if (auto record = MakeClassicRecord(ray.rop, ray.ron, h, level, weight, s_.cache->limits())) {
        const double a = s_.ambient.accuracy;
        record->corral =
            CorralBits(h, record->radius[0] * a, 1.0 / s_.cache->limits().BehindTolerance(a));
        if (s_.cache->Add(*record)) {
            ts.newRecords.push_back(*record);
            if (ts.stats.recordsPerLevel.size() <= static_cast<size_t>(level)) {
                ts.stats.recordsPerLevel.resize(level + 1);
            }
            ++ts.stats.recordsPerLevel[level];
        }
    }
    // An incomplete hemisphere still gives a usable value; it is just not
    // kept (Radiance's soft failure).
    Note(ts, Outcome::Computed, h.value);
    return coefficient * h.value;
}

}  // namespace rt
