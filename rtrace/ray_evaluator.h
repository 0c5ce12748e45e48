// SPDX-License-Identifier: MIT
//
// How rtrace's and rvimage's program flows reach the renderer: batches of
// rays in, RayResults out, behind an interface so the flows can be tested with
// a fake evaluator and string streams. The scene-backed evaluator is in
// rtrace/scene_evaluator.h.
#pragma once

#include <cstdint>
#include <ctime>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "ambient/record.h"
#include "core/diagnostics.h"
#include "core/vecmath.h"
#include "rtrace/command_line.h"
#include "shading/ray_result.h"

namespace rt {

/// One input ray, as TraceBatch takes it.
struct RayQuery {
    Vec3 org;
    Vec3 dir;            // unit
    double rmax = 0;     // > 0 limits the ray (-ld)
    std::uint64_t index = 0;  // 0-based position in the input
};

/// What the programs need from the renderer: shading::Renderer's TraceInput
/// and SetTraceCallback behind an interface.
class RayEvaluator {
public:
    virtual ~RayEvaluator() = default;
    /// Evaluates `rays` (possibly in parallel, -n); out[i] answers rays[i].
    virtual void TraceBatch(std::span<const RayQuery> rays, std::span<RayResult> out) {
        for (std::size_t i = 0; i < rays.size(); ++i)
            out[i] = TraceInput(rays[i].org, rays[i].dir, rays[i].rmax, rays[i].index);
    }
    /// Called once after the last ray: final ambient-file sync. May throw rt::Error.
    virtual void Finish() {}
    /// `dir` unit; `rmax` > 0 limits the ray (-ld), 0 = unlimited; `rayIndex`
    /// is the 0-based position of the record in the input.
    virtual RayResult TraceInput(const Vec3& org, const Vec3& dir, double rmax,
                                 std::uint64_t rayIndex) = 0;
    virtual void SetTraceCallback(std::function<void(const RayResult&)> callback,
                                  bool shadowRays) = 0;
    /// One line on what the renderer did (records per level, lookups, hit
    /// rate, rays traced), for -t and -e; empty if there is nothing to say.
    virtual std::string Summary() const { return {}; }
    /// Header lines of the octree the scene came from, which rtrace copies
    /// into its own header; empty for .rad input.
    virtual std::vector<std::string> SceneHeaderLines() const { return {}; }
    /// A copy of every ambient cache record (to draw where the cache put
    /// them); empty without a cache or for evaluators that have none.
    virtual std::vector<AmbientRecord> CacheRecords() const { return {}; }
};

/// Builds the evaluator for `sceneFiles` with the effective options (as
/// ParseCommandLine derives them). Throws rt::Error for scene problems.
using EvaluatorFactory = std::function<std::unique_ptr<RayEvaluator>(
    const std::vector<std::string>& sceneFiles, const RtraceOptions& options,
    const WarningSink& warn)>;

/// What a program takes from its process, so tests can stand in for it.
struct RunEnvironment {
    EvaluatorFactory makeEvaluator;
    /// Seconds since the epoch: dates rtrace's header.
    std::function<std::time_t()> clock = [] { return std::time(nullptr); };
    /// Process id printed in the -e banner.
    int pid = 0;
};

}  // namespace rt
