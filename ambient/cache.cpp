// SPDX-License-Identifier: MIT
#include "ambient/cache.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <type_traits>

#include "core/conventions.h"

namespace rt {
namespace {

/// Deeper records than this are refused (Radiance's files store the level in
/// one byte; -ab this deep is far beyond any use).
constexpr int kMaxLevel = 1000;

bool IsUsable(const AmbientRecord& r) {
    return r.level >= 0 && r.level <= kMaxLevel && std::isfinite(r.radius[0]) &&
           std::isfinite(r.radius[1]) && r.radius[0] > 0 &&
           r.radius[1] > 0 && IsFinite(r.value) && IsFinite(r.position) && IsFinite(r.normal) &&
           r.value.r >= 0 && r.value.g >= 0 && r.value.b >= 0;
}

}  // namespace

AmbientCache::AmbientCache(const Vec3& cubeOrigin, double cubeSize, double accuracy,
                           AmbientLimits limits, RecordWeighting weighting,
                           std::optional<RecordWeighting> deeperWeighting)
    : accuracy_(accuracy),
      weighting_(weighting),
      deeperWeighting_(deeperWeighting.value_or(weighting)),
      limits_(limits),
      indexOrigin_(cubeOrigin),
      indexSize_(cubeSize > 0 ? cubeSize : 1.0) {}

// Blocks are raw storage, filled in place: no record is constructed before it
// is stored, and none needs destroying.
static_assert(std::is_trivially_destructible_v<AmbientRecord>);

void AmbientCache::RecordBlocks::push_back(const AmbientRecord& r) {
    if (size_ % kBlock == 0) {
        blocks_.emplace_back(static_cast<AmbientRecord*>(::operator new(kBlock * sizeof(AmbientRecord))));
    }
    std::construct_at(blocks_.back().get() + size_ % kBlock, r);
    ++size_;
}

bool AmbientCache::Add(const AmbientRecord& record) {
    if (!IsUsable(record)) return false;
    std::unique_lock lock(mutex_);
    const auto id = static_cast<std::uint32_t>(records_.size());
    records_.push_back(record);
    // A record can only be accepted within a·r1 of its position (ε >= |Δ|/r1).
    while (indexByLevel_.size() <= static_cast<size_t>(record.level)) {
        indexByLevel_.emplace_back(indexOrigin_, indexSize_);
    }
    indexByLevel_[static_cast<size_t>(record.level)].Insert(
        record.position, accuracy_ * std::max(record.radius[0], record.radius[1]), id);
    const double b = Bright(record.value);
    if (b > kFtiny) {
        logBrightSum_ += std::log(b);
        ++logBrightCount_;
    }
    return true;
}

std::optional<Rgb> AmbientCache::Interpolate(const AmbientQuery& q, int* recordsUsed,
                                             FunctionRef<bool(const AmbientRecord&)> hidden) const {
    const double a = accuracy_;
    // A record whose plane lies in front of the query point by more than this
    // is on another surface (Radiance's "behind" tolerance).
    const double behindTolerance = limits_.BehindTolerance(a);
    *recordsUsed = 0;
    Rgb sum;
    double weightSum = 0;
    const bool hat = (q.level > 0 ? deeperWeighting_ : weighting_) == RecordWeighting::Hat;
    // Radiance 5's normal limit (radians), widened for weak rays.
    double maxAngle = 10.0 * kPi / 180.0 + a;
    if (hat && q.rayWeight < 0.6) {
        // Queries come with few distinct weights (one per bounce and sample
        // share), so the last power is kept rather than calling std::pow for
        // every lookup (docs/measured-choices.md).
        thread_local double lastWeight = -1, lastPower = 0;
        if (q.rayWeight != lastWeight) {
            lastWeight = q.rayWeight;
            lastPower = std::pow(q.rayWeight, 0.13);
        }
        maxAngle = (maxAngle - 0.5 * kPi) * lastPower + 0.5 * kPi;
    }
    std::shared_lock lock(mutex_);
    // A record answers only queries of its own bounce depth: its value holds
    // exactly the bounces left at that depth. (Radiance also lets deeper
    // queries use shallower records, which mixes bounce counts and darkens
    // its white furnace.) Hence one index per depth: a lookup never visits
    // the other depths' records.
    if (q.level < 0 || static_cast<size_t>(q.level) >= indexByLevel_.size()) return std::nullopt;
    // The candidates are gathered first and their records prefetched, so that
    // the memory latency of each record (the lookup's main cost where
    // queries are dense) overlaps the rest of the traversal; they are then
    // weighed (below).
    constexpr std::size_t kInline = 32;
    std::uint32_t inlineIds[kInline];
    std::vector<std::uint32_t> moreIds;
    std::size_t found = 0;
    indexByLevel_[static_cast<size_t>(q.level)].ForEachContaining(q.point, [&](std::uint32_t id) {
        // A record spans three cache lines (168 bytes); the tests read all.
        const char* bytes = reinterpret_cast<const char*>(&records_[id]);
        for (std::size_t line = 0; line < sizeof(AmbientRecord); line += 64) {
            __builtin_prefetch(bytes + line);
        }
        if (found < kInline) {
            inlineIds[found] = id;
        } else {
            moreIds.push_back(id);
        }
        ++found;
    });
    const auto weigh = [&](std::uint32_t id) {
        const AmbientRecord& r = records_[id];
        // Within the depth, the record must come from a ray about as
        // important as this one.
        if (r.weight < 0.9 * q.rayWeight) return;
        const double cosNormals = Dot(r.normal, q.normal);
        if (cosNormals <= 0) return;
        const Vec3 delta = q.point - r.position;
        // Two unit normals of one plane can have a dot product an ulp above 1
        // (|n|² rounds above 1); the square root below must not see the
        // negative chord that gives, or the weight is NaN and the record,
        // which is exactly right for the query, is refused.
        const double chord2 = std::max(0.0, 2.0 - 2.0 * cosNormals);
        // The "behind" test: Radiance 5 measures along the record's own
        // normal; the classic rule along the mean of the two normals.
        if (hat ? chord2 >= maxAngle * maxAngle || Dot(delta, r.normal) < -behindTolerance
                : 0.5 * Dot(delta, r.normal + q.normal) < -behindTolerance) {
            return;
        }
        // Distance in units of the record's radius (its ellipse for
        // anisotropic records).
        const Vec3 u = r.uAxis;
        const Vec3 v = r.VAxis();
        const double du = Dot(delta, u) / r.radius[0];
        const double dv = Dot(delta, v) / r.radius[1];
        const double dn = Dot(delta, r.normal) / r.radius[0];
        const double e1 = du * du + dv * dv + dn * dn;
        double w = 0;
        if (hat) {
            // Radiance 5: a hat in the normals' chord and the distance.
            if (e1 >= a * a) return;
            w = (1.0 - std::sqrt(chord2) / maxAngle) * (1.0 - std::sqrt(e1) / a);
            if (!(w > 0)) return;
        } else {
            // Split-sphere error: the distance plus the normal divergence.
            const double e2 = std::max(0.0, 1.0 - cosNormals);
            const double eps = std::sqrt(e1) + std::sqrt(e2);
            if (eps >= a) return;  // weight 1/ε must exceed 1/a
            w = eps > 1e-3 ? 1.0 / eps : 1e3;
        }
        double f = ExtrapolationFactor(r, q.point, q.shadingNormal);
        if (!(f >= kMinExtrapolation)) return;
        // Last, because it may trace a ray.
        if (hidden(r)) return;
        f = std::min(f, kMaxExtrapolation);
        sum += r.value * (w * f);
        weightSum += w;
        ++*recordsUsed;
    };
    // Weighed in record order, whatever order the index found them in: the
    // sums' rounding, and so the output, then does not depend on the index.
    if (found <= kInline) {
        std::sort(inlineIds, inlineIds + found);
        for (std::size_t k = 0; k < found; ++k) weigh(inlineIds[k]);
    } else {
        moreIds.insert(moreIds.end(), inlineIds, inlineIds + kInline);
        std::sort(moreIds.begin(), moreIds.end());
        for (const std::uint32_t id : moreIds) weigh(id);
    }
    if (weightSum <= kFtiny) return std::nullopt;
    return sum / weightSum;
}

double ExtrapolationFactor(const AmbientRecord& r, const Vec3& point, const Vec3& shadingNormal) {
    const Vec3 u = r.uAxis;
    const Vec3 v = r.VAxis();
    return 1.0 + Dot(point - r.position, u * r.posGradient[0] + v * r.posGradient[1]) +
           RotationTerm(r.normal, shadingNormal, u * r.dirGradient[0] + v * r.dirGradient[1]);
}

std::size_t AmbientCache::size() const {
    std::shared_lock lock(mutex_);
    return records_.size();
}

std::vector<AmbientRecord> AmbientCache::Records() const {
    std::shared_lock lock(mutex_);
    std::vector<AmbientRecord> all;
    all.reserve(records_.size());
    for (std::size_t i = 0; i < records_.size(); ++i) all.push_back(records_[i]);
    return all;
}

AmbientCache::LogBrightSum AmbientCache::logBright() const {
    std::shared_lock lock(mutex_);
    return {logBrightSum_, logBrightCount_};
}

Rgb AveragedAmbientValue(const Rgb& av, int valueWeight, double logBrightSum, int logBrightCount) {
    if (valueWeight <= 0 || logBrightCount <= 0) return av;
    const double logAverageReflectance = std::log(0.5);  // Radiance's AVGREFL
    const double l = Bright(av);
    if (l > kFtiny) {
        const double mean = std::exp((valueWeight * std::log(l) + logBrightSum +
                                      logAverageReflectance * logBrightCount) /
                                     (valueWeight + logBrightCount));
        return av * (mean / l);
    }
    return Rgb::Grey(std::exp(logBrightSum / logBrightCount + logAverageReflectance));
}

}  // namespace rt
