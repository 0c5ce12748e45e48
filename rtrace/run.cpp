// SPDX-License-Identifier: MIT
#include "rtrace/run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include "core/conventions.h"
#include "core/error.h"
#include "program/arguments.h"
#include "program/shell.h"
#include "rtrace/output.h"
#include "rtrace/ray_input.h"

namespace rt {
namespace {

/// Warnings about options that are accepted but do nothing yet, where a user
/// would otherwise believe they had an effect.
void WarnUnimplemented(const RtraceOptions& o, const WarningSink& warn) {
    if (!o.persistFile.empty())
        warn("persistent mode (-P/-PP) not implemented, processing input once");
    if (!o.photonMaps.empty()) warn("photon mapping (-ap) not implemented, option ignored");
}

/// The record Radiance's bogusray() prints for a flush request: the previous
/// ray re-initialised as an untraced primary ray (value 0, no object, length
/// FHUGE, point at its origin).
RayResult BogusRecord(const Vec3& origin, const Vec3& direction) {
    RayResult r;
    r.origin = origin;
    r.direction = direction;
    r.point = origin;
    r.coefficient = Rgb(1, 1, 1);
    return r;
}

/// The options the renderer gets. When no output letter needs a value,
/// Radiance 5.4a's rtrace only intersects the rays (castonly), in one
/// process, and leaves the ambient calculation out altogether: its -af file
/// is neither opened nor created, and no record is computed. A flush
/// interval (-x without -y) below the process count lowers the count to it.
RtraceOptions RendererOptions(const RtraceOptions& options, const OutputSpec& spec,
                              const WarningSink& warn) {
    RtraceOptions o = options;
    if (spec.castOnly) {
        o.shading.castOnly = true;
        o.ambient.bounces = 0;
        o.ambient.file.clear();
        o.processes = 1;
    }
    if (o.yResolution <= 0 && o.xResolution > 0 && o.xResolution < o.processes) {
        warn("reducing number of processes to match flush interval");
        o.processes = o.xResolution;
    }
    return o;
}

bool TraceListAccepts(const RtraceOptions& o, const RayResult& r) {
    if (!o.traceListSet) return true;
    // No object: Radiance's ourtrace() prints it only for an exclude list.
    if (r.modifierName == "*") return !o.traceListIsInclude;
    bool listed = false;
    for (const std::string& m : o.traceModifiers)
        if (m == r.modifierName) listed = true;
    return listed == o.traceListIsInclude;
}

/// Reads the rays and writes their records: everything between the -e file
/// and the end of the run. Throws rt::Error (BadRayError for bad input).
void Trace(const CommandLine& cl, std::istream& in, RecordWriter& writer,
           const RunEnvironment& env, ProgramShell& shell) {
    const RtraceOptions& opt = cl.options;
    const WarningSink& warn = shell.Warn();
    WarnUnimplemented(opt, warn);
    const std::time_t now = env.clock();

    const OutputSpec spec = ParseOutputSpec(opt, warn);
    if (!env.makeEvaluator) throw Error(Error::Kind::Internal, "no renderer configured");
    const RtraceOptions rendererOptions = RendererOptions(opt, spec, warn);
    std::unique_ptr<RayEvaluator> evaluator =
        env.makeEvaluator(cl.sceneFiles, rendererOptions, warn);

    if (opt.header) {
        std::span<const std::string> commandLine(cl.args.data(), cl.firstScene);
        writer.WriteText(FormatHeader(commandLine, spec, opt.outputFormat, now,
                                      evaluator->SceneHeaderLines()));
    }
    if (spec.trace) {
        evaluator->SetTraceCallback(
            [&](const RayResult& r) {
                if (TraceListAccepts(opt, r)) writer.WriteTraceRecord(spec.traceFields, r);
            },
            spec.traceShadows);
    }

    const int x = opt.xResolution, y = opt.yResolution;
    // rtrace.c: -x with -y counts pixels, -y alone counts records; 0 = all
    // input. Its count is unsigned, so a negative one never runs out: all
    // input is read, and its end is "unexpected", as in Radiance.
    std::uint64_t remaining =
        x > 1 ? static_cast<std::uint64_t>(static_cast<std::int64_t>(x) * y)
              : static_cast<std::uint64_t>(static_cast<std::int64_t>(y));
    const bool counting = remaining > 0;
    // Periodic flush every x records unless this is a picture (x and y given).
    const long flushInterval = (y > 0 && x > 1) ? 0 : x;
    long nextFlush = flushInterval;
    if (x > 0) {
        if (y > 0) writer.WriteText(FormatResolution(x, y));
        writer.Flush();
    }

    // -t: progress every reportSeconds, checked cheaply every 64 records.
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    auto nextReport = start + std::chrono::seconds(std::max(opt.reportSeconds, 0));
    auto seconds = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };

    RayReader reader(in, opt.inputFormat);
    Vec3 lastOrigin, lastDirection;
    const bool immediate = opt.shading.irradiance == IrradianceMode::Immediate;
    // Rays are evaluated in batches so that -n threads can share them;
    // one process (or trace output, which Radiance never parallelises)
    // evaluates them one at a time, as they arrive.
    const int threads = spec.trace ? 1 : RenderThreads(rendererOptions);
    const std::size_t batchLimit = threads > 1 ? 1024 * static_cast<std::size_t>(threads) : 1;
    std::vector<RayQuery> pending;
    std::vector<RayResult> results;
    auto evaluatePending = [&] {
        if (pending.empty()) return;
        results.resize(pending.size());
        evaluator->TraceBatch(pending, results);
        for (const RayResult& r : results) {
            lastOrigin = r.origin;
            lastDirection = r.direction;
            writer.WriteRecord(spec.fields, r);
            if (--nextFlush == 0) {
                if (!writer.Flush()) ThrowSystemError("write error");
                nextFlush = flushInterval;
            }
        }
        pending.clear();
    };
    std::uint64_t index = 0;
    while (auto ray = reader.Next()) {
        // hypot: no overflow for components beyond 1e154, unlike sqrt(dot).
        const Vec3& d = ray->direction;
        const double length = std::hypot(d.x, d.y, d.z);
        if (length == 0) {
            // A flush request: everything before it is answered first,
            // then its own record, then the output is flushed and the -x
            // countdown starts again.
            evaluatePending();
            writer.WriteRecord(spec.fields, BogusRecord(lastOrigin, lastDirection));
            if (!writer.Flush()) ThrowSystemError("write error");
            nextFlush = flushInterval;
        } else {
            // Radiance takes an aft distance of FTINY or less as no limit.
            const double rmax = (opt.limitDistance && !immediate && length > kFtiny) ? length : 0.0;
            pending.push_back({ray->origin, ray->direction / length, rmax, index});
            // A batch ends where a -x flush falls, so output is as prompt.
            if (pending.size() >= batchLimit ||
                (nextFlush > 0 && pending.size() >= static_cast<std::size_t>(nextFlush))) {
                evaluatePending();
            }
        }
        ++index;
        if (opt.reportSeconds > 0 && index % 64 == 0 && Clock::now() >= nextReport) {
            char line[128];
            std::snprintf(line, sizeof line, "%llu rays after %.1f s",
                          static_cast<unsigned long long>(index), seconds());
            shell.Say(line);
            nextReport = Clock::now() + std::chrono::seconds(opt.reportSeconds);
        }
        if (counting && --remaining == 0) break;
    }
    evaluatePending();
    evaluator->Finish();
    if (!writer.Flush()) ThrowSystemError("write error");
    if (counting && remaining > 0) warn("unexpected EOF on input");
    if (opt.reportSeconds > 0) {
        std::string summary = evaluator->Summary();
        char tail[96];
        std::snprintf(tail, sizeof tail, "%s%llu input rays in %.2f s", summary.empty() ? "" : ", ",
                      static_cast<unsigned long long>(index), seconds());
        shell.Say(summary + tail);
    }
}

}  // namespace

int Run(std::span<const std::string> args, std::istream& in, std::ostream& out,
        std::ostream& err, const RunEnvironment& env) {
    ProgramShell shell(args.empty() ? "rtrace" : ProgramName(args[0]), err);
    const WarningSink& warn = shell.Warn();
    return shell.Run([&] {
        CommandLine cl = ParseCommandLine(args, warn, SceneArgument::CheckedLater);
        const RtraceOptions& opt = cl.options;
        shell.SetName(cl.args[0]);
        shell.SetWarnings(opt.warnings);
        if (const std::optional<std::string> text = InfoText(cl)) {
            out << *text;
            out.flush();
            return 0;
        }
        if (!shell.OpenErrorFile(opt.errorFile, env.pid, cl.args)) return 2;
        RequireScene(cl);

        RecordWriter writer(opt.outputFormat, out);
        try {
            Trace(cl, in, writer, env, shell);
        } catch (const BadRayError& e) {
            // Results computed before the problem are delivered first. The
            // message is lazyrad's own: "<prog>: bad ray at ..." (ray_input.h).
            writer.Flush();
            shell.Say(e.what());
            return e.ExitCode();
        } catch (...) {
            writer.Flush();
            throw;
        }
        return 0;
    });
}

}  // namespace rt
