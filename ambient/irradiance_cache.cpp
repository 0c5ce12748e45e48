// SPDX-License-Identifier: MIT
#include "ambient/irradiance_cache.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "ambient/leak.h"

namespace rt {
namespace {

double Now() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

/// Radiance's assumed average reflectance: makes deeper records count less
/// (AVGREFL).
constexpr double kAverageReflectance = 0.5;

}  // namespace

IrradianceCache::IrradianceCache(const IrradianceSettings& settings,
                                 std::shared_ptr<AmbientCache> store)
    : settings_(settings), store_(std::move(store)) {}

double IrradianceCache::RecordWeight(int level, double rayWeight) {
    // Below -lw, Russian roulette raises the survivors' weight to -lw, above
    // 0.5^level; the record takes that weight too, or no query at this depth
    // (all carrying -lw) could use it and every one would compute its own.
    double weight = std::pow(kAverageReflectance, level);
    if (rayWeight < 0.1 * weight) weight = 1.25 * rayWeight;
    return std::max(weight, rayWeight);
}

std::optional<Rgb> IrradianceCache::Lookup(const AmbientQuery& query,
                                           IrradianceCounters& counters, OccludedRef occluded,
                                           int* used) const {
    // Radiance 5's leak test: a record that saw a wall nearby in the query's
    // direction is not used if the wall stands between them.
    const auto hidden = [&](const AmbientRecord& record) {
        if (!CorralCovers(record, query.point)) return false;
        const LeakTest leak = MakeLeakTest(query.point, query.normal, record.position,
                                           record.normal, settings_.distanceTolerance);
        switch (leak.outcome) {
            case LeakTest::Outcome::kVisible: return false;
            case LeakTest::Outcome::kHidden: return true;
            case LeakTest::Outcome::kTrace: break;
        }
        ++counters.leakRays;
        return occluded(query.point, leak.dir, leak.length);
    };
    return store_->Interpolate(query, used, hidden);
}

double IrradianceCache::DeeperSampleFraction(double share) {
    if (!(share < 1)) return 1;  // NaN too
    return std::max(kMinDeeperFraction, share * share);
}

double IrradianceCache::FirstLevelFraction(int bounces, int firstLevelRecords,
                                           int deeperRecords) {
    if (bounces < 2 || firstLevelRecords <= 0 || deeperRecords <= 0) return 1;
    const double ratio = double(deeperRecords) / double(firstLevelRecords);
    return std::clamp(kFirstLevelBoost * std::sqrt(ratio / kFullBoostRatio), 1.0,
                      kFirstLevelBoost);
}

double IrradianceCache::UnlitDeeperScale(double boost) {
    const double taken = (boost - 1) / (kFirstLevelBoost - 1);
    return 1 - std::clamp(taken, 0.0, 1.0) * (1 - kDeeperScale);
}

std::optional<double> IrradianceCache::AmbientShare(int level, double coefficientIntensity,
                                                    const IrradianceThread& thread,
                                                    const OtherRadianceRef* otherRadiance) const {
    if (!otherRadiance || static_cast<size_t>(level) >= thread.madeBright.size()) {
        return std::nullopt;
    }
    const auto [sum, count] = thread.madeBright[static_cast<size_t>(level)];
    if (count < kShareGuessRecords) return std::nullopt;
    // The ambient term's guess: the material's coefficient times the level's
    // typical Ē, from records made before this one (not from this record's
    // own samples, so that how many it takes cannot depend on what they saw,
    // which would bias it).
    const double ambient = coefficientIntensity * sum / count;
    const double other = (*otherRadiance)();
    if (!(ambient > 0) || !(other > 0)) return std::nullopt;
    return ambient / (ambient + other);
}

double IrradianceCache::SampleFraction(int level, double coefficientIntensity,
                                       const IrradianceThread& thread,
                                       const OtherRadianceRef* otherRadiance) const {
    if (level > 0) {
        if (const auto share = AmbientShare(level, coefficientIntensity, thread, otherRadiance)) {
            return kDeeperScale * DeeperSampleFraction(*share);
        }
    }
    int first = 0, deeper = 0;
    for (size_t l = 0; l < thread.madeBright.size(); ++l) {
        (l == 0 ? first : deeper) += thread.madeBright[l].second;
    }
    if (level <= 0) return FirstLevelFraction(settings_.bounces, first, deeper);
    // A deeper record is made inside a first-level hemisphere that is not
    // yet counted among the records made: count it, or the first sensor's
    // hemisphere, which makes many of a run's deeper records, would see no
    // boost and take their whole share.
    return UnlitDeeperScale(FirstLevelFraction(settings_.bounces, first + 1, deeper));
}

namespace {

/// Whether the shading normal turns away from the surface normal far enough
/// to turn the hemisphere's value (Radiance's DOT(nrm, ron) < 0.9999).
bool TurnedNormal(const AmbientQuery& q) { return Dot(q.normal, q.shadingNormal) < 0.9999; }

}  // namespace

IrradianceCache::Sampled IrradianceCache::Sample(const AmbientQuery& query, double weight,
                                                 double fraction, int level,
                                                 IrradianceThread& thread,
                                                 IrradianceCounters& counters, Rng& rng,
                                                 IrradianceTraceRef trace) const {
    HemisphereOptions options;
    options.divisions = settings_.divisions;
    options.superSamples = settings_.superSamples;
    // Both -ad's and -as's counts scale with this weight; the record keeps
    // its own (`weight`).
    options.weight = weight * fraction;
    options.caching = store_ != nullptr;
    // -aa 0 at a textured point: the rotational gradient turns the value
    // (records have their gradients anyway).
    const bool turnHere = level < 0 && TurnedNormal(query);
    options.gradients = turnHere;
    // The level's own method (-ah); -aa 0 hemispheres (level -1) take the first level's.
    const bool hessian = settings_.MethodAt(level) == RecordMethod::Hessian;
    // Hessian records below the first level take extra samples only where
    // their first pass is still rough by -aa, the relative error the cache
    // already accepts from interpolation (SuperSamplesForContrast). Measured
    // neutral for their error on every shared job; with the classic records
    // it cost the cornell floor 4-6 % (README, Differences), so they keep
    // Radiance's rule.
    if (hessian && level > 0) options.contrastTarget = settings_.accuracy;
    const int divisions = hessian ? HessianDivisions(options) * HessianDivisions(options)
                                  : HemisphereDivisions(options).total();
    const AmbientSampleShare share{options.caching, divisions};
    // Timing: only the outermost hemisphere counts (deeper ones are inside
    // it), less the lookups its samples make.
    const bool timeThis = thread.timing && thread.depth == 0;
    const double start = timeThis ? Now() : 0.0;
    const double lookupBefore = counters.secondsLookup;
    ++thread.depth;
    ++counters.hemispheres;
    // Hits nearer than the distance tolerance are real: the ray core returns
    // them only on a surface that meets the record's own at an angle (a wall
    // at a floor point's edge; RayCore::Intersect's `leaving`). Refusing them
    // would fail the division and darken the point, as letting them through
    // the wall did.
    const auto sample = [&](const Vec3& dir) { return trace(dir, share); };
    Sampled out;
    if (hessian) {
        const HessianHemisphere h = SampleHessianHemisphere(query.point, query.normal, options,
                                                            settings_.farDistance, rng, sample);
        if (h.anySample) out.value = h.value;
        if (h.anySample && level >= 0) {
            out.record = MakeHessianRecord(h, level, weight, settings_.accuracy, store_->limits());
        }
        if (turnHere) {
            if (const auto g = HessianRotationalGradient(h, h.frame.u, h.frame.v)) {
                out.dirGradient = h.frame.u * (*g)[0] + h.frame.v * (*g)[1];
            }
        }
    } else {
        const Hemisphere h = SampleHemisphere(query.normal, options, rng, sample);
        if (h.anySample) out.value = h.value;
        if (turnHere) out.dirGradient = h.dirGradient;
        if (h.anySample && level >= 0) {
            out.record = MakeClassicRecord(query.point, query.normal, h, level, weight,
                                           store_->limits());
            if (out.record) {
                const double a = settings_.accuracy;
                out.record->corral = CorralBits(h, out.record->radius[0] * a);
            }
        }
    }
    --thread.depth;
    if (timeThis) {
        counters.secondsSampling += (Now() - start) - (counters.secondsLookup - lookupBefore);
    }
    return out;
}

IrradianceResult IrradianceCache::Evaluate(const AmbientQuery& levelFree,
                                           double coefficientIntensity, IrradianceThread& thread,
                                           IrradianceCounters& counters, Rng& rng,
                                           IrradianceTraceRef trace, OccludedRef occluded,
                                           const OtherRadianceRef* otherRadiance) const {
    using Source = IrradianceResult::Source;
    AmbientQuery query = levelFree;
    query.level = thread.depth;
    if (!store_) {
        // -aa 0: a fresh hemisphere for every shading point, sized by the
        // ray's weight so that sample rays stay near -lw.
        double weight = query.rayWeight;
        const double lw = settings_.minimumWeight;
        if (lw > 0) {
            weight = std::min(weight, 0.8 * coefficientIntensity * query.rayWeight /
                                          (std::max(settings_.divisions, 1) * lw));
        }
        const Sampled h = Sample(query, weight, 1.0, -1, thread, counters, rng, trace);
        if (!h.value) return {};
        // Turned to the shading normal by the rotational gradient, unless
        // that would take it below 5 % (Radiance's multambient()).
        const double f = 1.0 + RotationTerm(query.normal, query.shadingNormal, h.dirGradient);
        return {f >= kMinExtrapolation ? *h.value * f : *h.value, Source::Computed};
    }
    ++counters.ambientLookups;
    int used = 0;
    const double lookupStart = thread.timing ? Now() : 0.0;
    const std::optional<Rgb> interpolated = Lookup(query, counters, occluded, &used);
    if (thread.timing) counters.secondsLookup += Now() - lookupStart;
    if (interpolated) {
        ++counters.ambientHits;
        return {interpolated, used > 1 ? Source::Interpolated : Source::Extrapolated};
    }
    // A new record of this level.
    const double weight = RecordWeight(thread.depth, query.rayWeight);
    const int level = thread.depth;
    const double fraction = SampleFraction(level, coefficientIntensity, thread, otherRadiance);
    const Sampled h = Sample(query, weight, fraction, level, thread, counters, rng, trace);
    // No division got a sample (every ray refused, e.g. by -lr): Radiance's
    // makeambient() failure, answered with the ambient value.
    if (!h.value) return {};
    if (const auto& record = h.record) {
        if (thread.madeBright.size() <= static_cast<size_t>(level)) {
            thread.madeBright.resize(static_cast<size_t>(level) + 1);
        }
        thread.madeBright[static_cast<size_t>(level)].first += Bright(record->value);
        ++thread.madeBright[static_cast<size_t>(level)].second;
        if (store_->Add(*record)) {
            if (thread.queueNewRecords) thread.newRecords.push_back(*record);
            if (counters.recordsPerLevel.size() <= static_cast<size_t>(level)) {
                counters.recordsPerLevel.resize(level + 1);
            }
            ++counters.recordsPerLevel[level];
        }
    }
    if (h.record) {
        // The new record answers its own point as a lookup would, turned to
        // the shading normal; below the trusted factor, the ambient value
        // (Radiance's makeambient() returns extambient()'s verdict).
        const double f = ExtrapolationFactor(*h.record, query.point, query.shadingNormal);
        if (!(f >= kMinExtrapolation)) return {};
        return {*h.value * std::min(f, kMaxExtrapolation), Source::Computed};
    }
    // An incomplete hemisphere still gives a usable value; it is just not
    // kept (Radiance's soft failure).
    return {h.value, Source::Computed};
}

}  // namespace rt
