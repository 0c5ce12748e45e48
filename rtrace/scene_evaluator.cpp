// SPDX-License-Identifier: MIT
#include "rtrace/scene_evaluator.h"

#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <ctime>
#include <exception>
#include <filesystem>
#include <mutex>
#include <memory>
#include <new>
#include <optional>
#include <string>
#include <system_error>
#include <thread>

#include "ambfiles/shared_file.h"
#include "core/error.h"
#include "raycore/raycore.h"
#include "scene/loader.h"
#include "shading/renderer.h"

namespace rt {
namespace {

/// The ambient file's header records the effective ambient options, as
/// Radiance's initambfile() does.
AmbientHeaderParams HeaderParams(const std::vector<std::string>& sceneFiles,
                                 const RtraceOptions& options) {
    AmbientHeaderParams p;
    p.programName = "rtrace";
    p.ambientValue = options.ambient.value;
    p.valueWeight = options.ambient.valueWeight;
    p.bounces = options.ambient.bounces;
    p.accuracy = options.ambient.accuracy;
    p.divisions = options.ambient.divisions;
    p.superSamples = options.ambient.superSamples;
    p.resolution = options.ambient.resolution;
    for (const std::string& f : sceneFiles) {
        if (!p.octreeName.empty()) p.octreeName.append(" ");
        p.octreeName.append(f);
    }
    p.software = std::string(kVersionString);
    p.captureTime = std::time(nullptr);
    return p;
}

/// Scene, ray core and one Renderer per thread (-n). With the cache, all
/// renderers share one in-memory AmbientCache, so a record made by one
/// thread serves the others at once; with -af the cache is also kept in sync
/// with the file (and so with any other process using it).
class SceneEvaluator final : public RayEvaluator {
public:
    SceneEvaluator(Scene scene, const std::vector<std::string>& sceneFiles,
                   const RtraceOptions& options, const WarningSink& warn)
        : scene_(std::move(scene)), core_(scene_), warn_(warn) {
        cache_ = Renderer::MakeCache(scene_, options.ambient);
        const int threads = RenderThreads(options);
        // Set-up warnings ("no light sources found") once, not per thread.
        const auto shared =
            Renderer::Share(scene_, core_, options.shading, options.ambient, warn, cache_);
        // Every thread's warnings reach the sink, one at a time: Radiance's
        // -n processes each print their own.
        WarningSink serialized;
        if (warn) {
            serialized = [warn, mutex = std::make_shared<std::mutex>()](const std::string& m) {
                const std::lock_guard<std::mutex> lock(*mutex);
                warn(m);
            };
        }
        for (int i = 0; i < threads; ++i) {
            renderers_.push_back(std::make_unique<Renderer>(shared, threads == 1 ? warn : serialized));
            // -t asks for the report, which then says where the time went.
            renderers_.back()->EnableTiming(options.reportSeconds > 0);
        }
        OpenAmbientFile(sceneFiles, options);
        for (auto& r : renderers_) r->QueueNewRecords(file_.has_value());
    }

    RayResult TraceInput(const Vec3& org, const Vec3& dir, double rmax,
                         std::uint64_t rayIndex) override {
        RayResult r;
        try {
            r = renderers_[0]->TraceInput(org, dir, rmax, rayIndex);
        } catch (const std::bad_alloc&) {
            ThrowOutOfMemory();
        }
        SyncIfDue();
        return r;
    }

    void TraceBatch(std::span<const RayQuery> rays, std::span<RayResult> out) override {
        const size_t threads = std::min(renderers_.size(), rays.size());
        if (threads <= 1) {
            try {
                for (size_t i = 0; i < rays.size(); ++i) {
                    out[i] = renderers_[0]->TraceInput(rays[i].org, rays[i].dir, rays[i].rmax,
                                                       rays[i].index);
                }
            } catch (const std::bad_alloc&) {
                ThrowOutOfMemory();
            }
        } else {
            // Each thread takes the next unclaimed ray; results land in input
            // order whatever finishes first. An exception escaping a jthread
            // would call std::terminate, so the first one is kept and rethrown
            // here, after the others stop taking rays.
            std::atomic<size_t> next{0};
            std::mutex failureMutex;
            std::exception_ptr failure;
            auto work = [&](Renderer& renderer) {
                try {
                    for (size_t i; (i = next.fetch_add(1)) < rays.size();) {
                        out[i] = renderer.TraceInput(rays[i].org, rays[i].dir, rays[i].rmax,
                                                     rays[i].index);
                    }
                } catch (...) {
                    next.store(rays.size());
                    const std::lock_guard<std::mutex> lock(failureMutex);
                    if (!failure) failure = std::current_exception();
                }
            };
            {
                std::vector<std::jthread> pool;
                for (size_t t = 1; t < threads; ++t) {
                    pool.emplace_back(work, std::ref(*renderers_[t]));
                }
                work(*renderers_[0]);
            }
            if (failure) {
                try {
                    std::rethrow_exception(failure);
                } catch (const std::bad_alloc&) {
                    ThrowOutOfMemory();
                }
            }
        }
        SyncIfDue();
    }

    void SetTraceCallback(std::function<void(const RayResult&)> callback,
                          bool shadowRays) override {
        renderers_[0]->SetTraceCallback(std::move(callback), shadowRays);
    }

    void Finish() override { Sync(); }

    std::vector<std::string> SceneHeaderLines() const override { return scene_.headerLines; }

    std::vector<AmbientRecord> CacheRecords() const override {
        return renderers_[0]->CacheRecords();
    }

    std::string Summary() const override {
        RenderStats s;
        for (const auto& r : renderers_) s += r->Stats();
        std::string out = "records per level";
        if (s.recordsPerLevel.empty()) out += " 0";
        for (size_t i = 0; i < s.recordsPerLevel.size(); ++i) {
            // append(), not "x" + std::string: GCC 12 warns falsely on the latter (bug 105329).
            out.append(i ? "/" : " ");
            out.append(std::to_string(s.recordsPerLevel[i]));
        }
        // Records another program removed from the ambient file and we put back
        // (ambfiles/shared_file.h); named only when it happened.
        const size_t restored = file_ ? file_->RestoredRecords() : 0;
        const std::string putBack =
            restored > 0 ? "; " + std::to_string(restored) + " put back after another program "
                                                             "removed them"
                         : std::string();
        char buf[512];
        std::snprintf(buf, sizeof buf,
                      " (+%zu from the ambient file%s), %llu lookups, %.1f%% interpolated, %llu "
                      "hemispheres, %llu rays traced + %llu shadow rays (%llu more samples "
                      "found blocked in the obstructor cache) + %llu leak-test rays; "
                      "thread time %.2f s "
                      "sampling, %.2f s lookups, %.2f s direct",
                      recordsLoaded_, putBack.c_str(),
                      static_cast<unsigned long long>(s.ambientLookups),
                      s.ambientLookups ? 100.0 * double(s.ambientHits) / double(s.ambientLookups)
                                       : 0.0,
                      static_cast<unsigned long long>(s.hemispheres),
                      static_cast<unsigned long long>(s.raysTraced),
                      static_cast<unsigned long long>(s.shadowRays),
                      static_cast<unsigned long long>(s.samplesObstructed),
                      static_cast<unsigned long long>(s.leakRays), s.secondsSampling,
                      s.secondsLookup, s.secondsDirect);
        return out + buf;
    }

private:
    /// Radiance's SYSTEM error for a failed allocation ("out of memory in
    /// samp_hemi", exit 2), never "internal - std::bad_alloc".
    [[noreturn]] static void ThrowOutOfMemory() {
        throw Error(Error::Kind::System, "out of memory while tracing rays");
    }

    void OpenAmbientFile(const std::vector<std::string>& sceneFiles, const RtraceOptions& options) {
        const std::string& path = options.ambient.file;
        if (path.empty()) return;
        if (options.ambient.accuracy <= kFtiny) {
            // Radiance's message for -aa 0; with -ab 0 nothing would use it.
            if (options.ambient.bounces > 0 && warn_) {
                warn_("zero ambient accuracy so \"" + path + "\" not opened");
            }
            return;
        }
        // As Radiance's setambient(), the file is opened (and created with its
        // header if need be) whenever -aa > 0, even when -ab 0 or -ad 0 leave
        // no cache; its records are then not even read.
        file_.emplace(path, HeaderParams(sceneFiles, options), warn_);
        if (!cache_) return;
        for (const AmbientRecord& r : file_->LoadAll()) {
            if (cache_->Add(r)) ++recordsLoaded_;
        }
    }

    /// Radiance syncs every kSyncInterval new records and at exit.
    void SyncIfDue() {
        if (!file_) return;
        for (auto& r : renderers_) {
            for (AmbientRecord& rec : r->TakeNewRecords()) unsynced_.push_back(rec);
        }
        if (unsynced_.size() >= static_cast<size_t>(SharedAmbientFile::kSyncInterval)) Sync();
    }

    void Sync() {
        if (!file_) return;
        for (auto& r : renderers_) {
            for (AmbientRecord& rec : r->TakeNewRecords()) unsynced_.push_back(rec);
        }
        std::vector<AmbientRecord> foreign = file_->Sync(unsynced_);
        unsynced_.clear();
        if (!cache_) return;
        for (const AmbientRecord& rec : foreign) {
            if (cache_->Add(rec)) ++recordsLoaded_;
        }
    }

    // Declaration order matters: the core and renderers refer to scene_.
    Scene scene_;
    RayCore core_;
    WarningSink warn_;
    std::shared_ptr<AmbientCache> cache_;
    std::vector<std::unique_ptr<Renderer>> renderers_;
    std::optional<SharedAmbientFile> file_;
    std::vector<AmbientRecord> unsynced_;
    size_t recordsLoaded_ = 0;
};

}  // namespace

std::unique_ptr<RayEvaluator> MakeSceneEvaluator(const std::vector<std::string>& sceneFiles,
                                                 const RtraceOptions& options,
                                                 const WarningSink& warn,
                                                 const std::string& toolDirectory) {
    SceneLoadOptions load;
    load.toolDirectory = toolDirectory;
    return std::make_unique<SceneEvaluator>(LoadScene(sceneFiles, load, warn), sceneFiles,
                                            options, warn);
}

RunEnvironment ProcessEnvironment() {
    RunEnvironment env;
    env.makeEvaluator = [toolDirectory = ExecutableDirectory()](
                            const std::vector<std::string>& files, const RtraceOptions& options,
                            const WarningSink& warn) {
        return MakeSceneEvaluator(files, options, warn, toolDirectory);
    };
    env.pid = static_cast<int>(getpid());
    return env;
}

std::string ExecutableDirectory() {
    std::error_code ec;
    std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (ec) return {};
    return exe.parent_path().string();
}

}  // namespace rt
