// SPDX-License-Identifier: MIT
//
// rtrace's program flow (rtmain.c main() and rtrace.c rtrace(),
// radiance-notes.md §1.4-1.5): parse, open the -e file, build the evaluator,
// write the header, then read rays and write records with Radiance's -x/-y
// counting, flush points and zero-direction flush records. The scene and the
// renderer come in through RayEvaluator so the flow can be tested with
// string streams and a fake evaluator.
//
// Differences from Radiance (deliberate): a zero-direction record always
// flushes output after its record (Radiance may defer that flush while an -x
// countdown runs); bad input is an error (see ray_input.h); -n N > 1 runs
// one process with a warning.
//
//   RunEnvironment env{.makeEvaluator = MakeSceneEvaluator};
//   return Run(args, std::cin, std::cout, std::cerr, env);
#pragma once

#include <cstdint>
#include <ctime>
#include <functional>
#include <istream>
#include <memory>
#include <ostream>
#include <span>
#include <string>
#include <vector>

#include "ambient/record.h"
#include "core/diagnostics.h"
#include "core/vecmath.h"
#include "rtrace/options.h"
#include "shading/ray_result.h"

namespace rt {

/// One input ray, as TraceBatch takes it.
struct RayQuery {
    Vec3 org;
    Vec3 dir;            // unit
    double rmax = 0;     // > 0 limits the ray (-ld)
    std::uint64_t index = 0;  // 0-based position in the input
};

/// What Run needs from the renderer: shading::Renderer's TraceInput and
/// SetTraceCallback behind an interface.
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

/// Builds the evaluator for `sceneFiles` with the effective options (seed
/// filled in). Throws rt::Error for scene problems.
using EvaluatorFactory = std::function<std::unique_ptr<RayEvaluator>(
    const std::vector<std::string>& sceneFiles, const RtraceOptions& options,
    const WarningSink& warn)>;

struct RunEnvironment {
    EvaluatorFactory makeEvaluator;
    /// Seconds since the epoch: seeds -u+ and dates the header.
    std::function<std::time_t()> clock = [] { return std::time(nullptr); };
    /// Process id printed in the -e banner.
    int pid = 0;
};

/// Runs rtrace with `args` (argv[0] first). Returns the exit status: 0, or
/// Radiance's 1 (user error), 2 (system error), 3 (internal error). Messages
/// go to `err` (or the -e file) as "<prog>: <kind> - <text>".
int Run(std::span<const std::string> args, std::istream& in, std::ostream& out,
        std::ostream& err, const RunEnvironment& env);

}  // namespace rt
