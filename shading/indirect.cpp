// SPDX-License-Identifier: MIT
//
// The indirect term: Radiance's multambient() (radiance-notes.md §4.1) on top
// of the lazy irradiance cache in ambient/: interpolate where records are
// good enough, otherwise sample a new hemisphere and keep it as a record.
#include <algorithm>
#include <chrono>
#include <cmath>

#include "ambient/leak.h"
#include "shading/integrator.h"

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

bool Integrator::AmbientExcluded(const TracedRay& ray) const {
    if (ambientList_.empty() && !ambient_.listIsInclude) return false;
    if (ray.surface < 0 || ray.hitDistant) return false;  // -I: no object to test
    const bool listed = ambientList_.count(scene_.HitSurface(ray.instance, ray.surface).modifierName) > 0;
    return ambient_.listIsInclude ? !listed : listed;
}

Rgb Integrator::AmbientFallback(const Rgb& coefficient) const {
    if (!cache_) return coefficient * ambient_.value;
    if (ambient_.valueWeight <= 0) return coefficient * ambient_.value;
    const AmbientCache::LogBrightSum s = cache_->logBright();
    return coefficient * AveragedAmbientValue(ambient_.value, ambient_.valueWeight, s.sum, s.count);
}

Hemisphere Integrator::SampleAmbient(const TracedRay& ray, const Rgb& coefficient,
                                     double weight) {
    const bool caching = cache_ != nullptr;
    HemisphereOptions options;
    options.divisions = ambient_.divisions;
    options.superSamples = ambient_.superSamples;
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
    const bool timeThis = timing_ && ambientDepth_ == 0;
    const double start = timeThis ? Now() : 0.0;
    const double directBefore = stats_.secondsDirect, lookupBefore = stats_.secondsLookup;
    ++ambientDepth_;
    ++stats_.hemispheres;
    Hemisphere h = SampleHemisphere(ray.ron, options, rng_, [&](const Vec3& dir)
                                        -> std::optional<AmbientSample> {
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
        StartChild(child, ray, kAmbientRay, nullptr);
        child.rweight = ray.rweight * std::fmin(1.0, Intens(sampleCoef));
        child.rcoef = sampleCoef;
        const int lr = shading_.limits.reflections;
        if (lr != 0 && child.rlvl > std::abs(lr)) return std::nullopt;
        // Light sources seen from the sample's hit are subdivided (-ds) for
        // the path's real importance: the cache's nominal 0.5 would halve the
        // subdivision distance and turn lamps partly hidden by an edge into
        // all-or-nothing points, which darkens penumbrae seen from the
        // hemisphere (README, "Differences").
        child.sourceWeight = ray.sourceWeight * std::fmin(1.0, Intens(coefficient));
        child.org = point;
        child.dir = dir;
        Trace(child);
        const double dist = child.EffectiveDistance();
        if (!(dist > scene_.distanceTolerance)) return std::nullopt;
        return AmbientSample{child.rcol, dist};
    });
    --ambientDepth_;
    if (timeThis) {
        stats_.secondsSampling += (Now() - start) - (stats_.secondsDirect - directBefore) -
                                  (stats_.secondsLookup - lookupBefore);
    }
    return h;
}

void Integrator::NoteAmbient(RayResult::AmbientOutcome outcome, const Rgb& meanRadiance) {
    if (firstAmbientSeen_ || ambientDepth_ != 0) return;
    firstAmbientSeen_ = true;
    firstOutcome_ = outcome;
    firstIndirectIrradiance_ = meanRadiance * kPi;
}

Rgb Integrator::Ambient(const Rgb& coefficient, const TracedRay& ray, const Vec3& normal) {
    using Outcome = RayResult::AmbientOutcome;
    if (ambient_.divisions <= 0 || ambientDepth_ >= ambient_.bounces || AmbientExcluded(ray) ||
        Bright(coefficient) <= kFtiny) {
        const Rgb value = AmbientFallback(coefficient);
        if (ambient_.bounces > 0) NoteAmbient(Outcome::Fallback, AmbientFallback(Rgb(1, 1, 1)));
        return value;
    }
    if (!cache_) {
        // -aa 0: a fresh hemisphere for every shading point, sized by the
        // ray's weight so that sample rays stay near -lw.
        double weight = ray.rweight;
        const double lw = shading_.limits.weight;
        if (lw > 0) {
            weight = std::min(weight, 0.8 * Intens(coefficient) * ray.rweight /
                                          (std::max(ambient_.divisions, 1) * lw));
        }
        Hemisphere h = SampleAmbient(ray, coefficient, weight);
        if (!h.anySample) return AmbientFallback(coefficient);
        NoteAmbient(Outcome::Computed, h.value);
        return coefficient * h.value;
    }
    AmbientQuery query;
    query.point = ray.rop;
    query.normal = ray.ron;
    query.shadingNormal = normal;
    query.level = ambientDepth_;
    query.rayWeight = ray.rweight;
    ++stats_.ambientLookups;
    int used = 0;
    const double lookupStart = timing_ ? Now() : 0.0;
    // Radiance 5's leak test: a record that saw a wall nearby in the query's
    // direction is not used if the wall stands between them.
    const auto hidden = [&](const AmbientRecord& record) {
        if (!CorralCovers(record, query.point)) return false;
        const LeakTest leak = MakeLeakTest(query.point, query.normal, record.position,
                                           record.normal, scene_.distanceTolerance);
        switch (leak.outcome) {
            case LeakTest::Outcome::kVisible: return false;
            case LeakTest::Outcome::kHidden: return true;
            case LeakTest::Outcome::kTrace: break;
        }
        ++stats_.leakRays;
        return core_.Occluded(query.point, leak.dir, leak.length);
    };
    std::optional<Rgb> interpolated = cache_->Interpolate(query, &used, hidden);
    if (timing_) stats_.secondsLookup += Now() - lookupStart;
    if (auto value = interpolated) {
        ++stats_.ambientHits;
        NoteAmbient(used > 1 ? Outcome::Interpolated : Outcome::Extrapolated, *value);
        return coefficient * *value;
    }
    // A new record at this level: weight 0.5^level, or about the ray's own
    // weight when the ray matters much less than that (§4.4). Below -lw,
    // Russian roulette raises the survivors' weight to -lw, above 0.5^level;
    // the record takes that weight too, or no query at this depth (all
    // carrying -lw) could use it and every one would compute its own.
    double weight = std::pow(kAverageReflectance, ambientDepth_);
    if (ray.rweight < 0.1 * weight) weight = 1.25 * ray.rweight;
    weight = std::max(weight, ray.rweight);
    const int level = ambientDepth_;
    Hemisphere h = SampleAmbient(ray, coefficient, weight);
    // No division got a sample (every ray refused, e.g. by -lr): Radiance's
    // makeambient() failure, answered with the ambient value.
    if (!h.anySample) return AmbientFallback(coefficient);
    if (auto record = MakeClassicRecord(ray.rop, ray.ron, h, level, weight, cache_->limits())) {
        const double a = ambient_.accuracy;
        record->corral =
            CorralBits(h, record->radius[0] * a, 1.0 / cache_->limits().BehindTolerance(a));
        if (cache_->Add(*record)) {
            newRecords_.push_back(*record);
            if (stats_.recordsPerLevel.size() <= static_cast<size_t>(level)) {
                stats_.recordsPerLevel.resize(level + 1);
            }
            ++stats_.recordsPerLevel[level];
        }
    }
    // An incomplete hemisphere still gives a usable value; it is just not
    // kept (Radiance's soft failure).
    NoteAmbient(Outcome::Computed, h.value);
    return coefficient * h.value;
}

}  // namespace rt
