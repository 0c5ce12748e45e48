// SPDX-License-Identifier: MIT
//
// The in-memory irradiance cache: records indexed by one SphereGrid per
// bounce depth and
// interpolated with Ward's split-sphere weights and Ward & Heckbert's
// first-order gradients (radiance-notes.md §4.12, Radiance ≤ 4.2
// sumambient()). Records read from Radiance 5 files carry two radii and a
// u-axis; the distance term then uses the record's ellipse (§4.3).
//
// Thread-safe: any number of threads may Interpolate() and Add() at once
// (a reader-writer lock; lookups far outnumber insertions).
#pragma once

#include <cstddef>
#include <memory>
#include <mutex>
#include <optional>
#include <shared_mutex>
#include <vector>

#include "ambient/limits.h"
#include "ambient/record.h"
#include "core/function_ref.h"
#include "core/rgb.h"
#include "core/vecmath.h"
#include "octree/sphere_grid.h"

namespace rt {

/// Where and for whom an ambient value is wanted.
struct AmbientQuery {
    Vec3 point;          // shading point
    Vec3 normal;         // unperturbed surface normal, facing the incoming ray
    Vec3 shadingNormal;  // perturbed normal (== normal without textures)
    int level = 0;       // current ambient depth: only records of this level are used
    double rayWeight = 1;  // weight of the ray being shaded
};

/// How records are accepted and weighed at a query.
enum class RecordWeighting {
    /// Ward's split-sphere error ε (distance in radii plus normal divergence),
    /// weight 1/ε, accepted while ε < a (Radiance ≤ 4.2, §4.12).
    SplitSphere,
    /// Radiance 5's (§4.3): the normals within 10° + a radians, the elliptical
    /// distance ε below a, weight (1 − δ/θmax)(1 − ε/a), a hat that falls to
    /// zero at both limits.
    Hat,
};

class AmbientCache {
public:
    /// `cubeOrigin/cubeSize` bound the scene (records outside still work);
    /// `accuracy` is -aa (> 0). `weighting` weighs the first level's records,
    /// `deeperWeighting` (default: the same) those of every deeper level, so
    /// that each level's records are weighed as their method made them.
    AmbientCache(const Vec3& cubeOrigin, double cubeSize, double accuracy, AmbientLimits limits,
                 RecordWeighting weighting = RecordWeighting::SplitSphere,
                 std::optional<RecordWeighting> deeperWeighting = std::nullopt);

    /// Stores a record (computed here or read from a file). Records with a
    /// non-positive or non-finite radius, or non-finite values, are ignored
    /// (returns false).
    bool Add(const AmbientRecord& record);

    /// Weighted average Σ w_i E'_i / Σ w_i over the records acceptable at the
    /// query (w_i = 1/ε_i > 1/a); nullopt when none is acceptable. Never
    /// negative: a record whose extrapolation factor drops below 0.05 is not used.
    std::optional<Rgb> Interpolate(const AmbientQuery& query) const {
        int used = 0;
        return Interpolate(query, &used);
    }
    /// As above; `recordsUsed` receives how many records contributed.
    std::optional<Rgb> Interpolate(const AmbientQuery& query, int* recordsUsed) const {
        return Interpolate(query, recordsUsed, [](const AmbientRecord&) { return false; });
    }
    /// As above; `hidden` is asked last about each record that passed every
    /// other test, and returning true rejects it (the leak test, ambient/leak.h).
    /// It runs under the cache's read lock and must not call into the cache.
    std::optional<Rgb> Interpolate(const AmbientQuery& query, int* recordsUsed,
                                   FunctionRef<bool(const AmbientRecord&)> hidden) const;

    std::size_t size() const;
    /// A copy of every record, in insertion order.
    std::vector<AmbientRecord> Records() const;
    const AmbientLimits& limits() const { return limits_; }

    /// Σ ln(bright(value)) and count over records with bright > 1e-6, for the
    /// -aw running average (Radiance's avsum/navsum).
    struct LogBrightSum {
        double sum = 0;
        int count = 0;
    };
    LogBrightSum logBright() const;

private:
    /// The records, in insertion order, in fixed blocks that never move: a
    /// doubling vector would copy them all at each growth and touch fresh
    /// pages for the copy, and on a virtual machine a page's first touch can
    /// cost as much as tracing tens of rays (docs/measured-choices.md).
    class RecordBlocks {
      public:
        RecordBlocks() = default;
        RecordBlocks(const RecordBlocks&) = delete;
        RecordBlocks& operator=(const RecordBlocks&) = delete;
        void push_back(const AmbientRecord& r);
        const AmbientRecord& operator[](std::size_t i) const {
            return blocks_[i / kBlock][i % kBlock];
        }
        std::size_t size() const { return size_; }

      private:
        // 512 records, 86 KB: below glibc's mmap threshold, so blocks come
        // from (and go back to) the ordinary heap.
        static constexpr std::size_t kBlock = 512;
        struct Free {
            void operator()(AmbientRecord* p) const { ::operator delete(p); }
        };
        std::vector<std::unique_ptr<AmbientRecord[], Free>> blocks_;
        std::size_t size_ = 0;
    };

    mutable std::shared_mutex mutex_;
    double accuracy_;
    RecordWeighting weighting_;        // level 0
    RecordWeighting deeperWeighting_;  // levels 1 and more
    AmbientLimits limits_;
    Vec3 indexOrigin_;
    double indexSize_;
    std::vector<SphereGrid> indexByLevel_;  // [level]: records of that depth only
    RecordBlocks records_;
    double logBrightSum_ = 0;
    int logBrightCount_ = 0;
};

/// Extrapolation factors are trusted between these bounds (Radiance 5 uses
/// the same clamp; the classic code only cut negative values to zero, which
/// let one record drag an interpolation toward black): below the first a
/// record is not used, above the second the factor is capped.
constexpr double kMinExtrapolation = 0.05;
constexpr double kMaxExtrapolation = 20.0;

/// Ward & Heckbert's first-order extrapolation factor of record `r` at
/// `point` for the shading normal `shadingNormal` (Radiance's extambient()):
/// 1 + its translational gradient along the offset + its rotational gradient
/// along the turn from the record's normal. Exactly 1 at the record itself
/// with its own normal; a texture or a mesh's smooth normal turns it there.
double ExtrapolationFactor(const AmbientRecord& r, const Vec3& point, const Vec3& shadingNormal);

/// The rotational part of it: the relative change of a hemisphere's value
/// sampled about `normal` when turned to `shadingNormal`, for its relative
/// rotational gradient `dirGradient` (1/radian, tangent to `normal`).
inline double RotationTerm(const Vec3& normal, const Vec3& shadingNormal, const Vec3& dirGradient) {
    return Dot(Cross(normal, shadingNormal), dirGradient);
}

/// Radiance's -aw fallback ("dumbamb"): the ambient value `av` blended in log
/// space with the cache's values, assuming 50 % average reflectance
/// (radiance-notes.md §4.1 step 7). With `valueWeight <= 0` or no positive
/// record, `av` itself.
Rgb AveragedAmbientValue(const Rgb& av, int valueWeight, double logBrightSum, int logBrightCount);

}  // namespace rt
