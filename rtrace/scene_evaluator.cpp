// SPDX-License-Identifier: MIT
#include "rtrace/scene_evaluator.h"

#include <cstdio>
#include <filesystem>
#include <string>
#include <system_error>

#include "raycore/raycore.h"
#include "scene/loader.h"
#include "shading/renderer.h"

namespace rt {
namespace {

class SceneEvaluator final : public RayEvaluator {
public:
    SceneEvaluator(Scene scene, const RtraceOptions& options, const WarningSink& warn)
        : scene_(std::move(scene)),
          core_(scene_),
          renderer_(scene_, core_, options.shading, options.ambient, warn) {}

    RayResult TraceInput(const Vec3& org, const Vec3& dir, double rmax,
                         std::uint64_t rayIndex) override {
        return renderer_.TraceInput(org, dir, rmax, rayIndex);
    }
    void SetTraceCallback(std::function<void(const RayResult&)> callback,
                          bool shadowRays) override {
        renderer_.SetTraceCallback(std::move(callback), shadowRays);
    }
    std::string Summary() const override {
        const RenderStats& s = renderer_.Stats();
        std::string out = "records per level";
        if (s.recordsPerLevel.empty()) out += " 0";
        for (size_t i = 0; i < s.recordsPerLevel.size(); ++i) {
            // append(), not "x" + std::string: GCC 12 warns falsely on the latter (bug 105329).
            out.append(i ? "/" : " ");
            out.append(std::to_string(s.recordsPerLevel[i]));
        }
        char buf[200];
        std::snprintf(buf, sizeof buf,
                      ", %llu lookups, %.1f%% interpolated, %llu hemispheres, %llu rays traced"
                      " + %llu shadow rays",
                      static_cast<unsigned long long>(s.ambientLookups),
                      s.ambientLookups ? 100.0 * double(s.ambientHits) / double(s.ambientLookups) : 0.0,
                      static_cast<unsigned long long>(s.hemispheres),
                      static_cast<unsigned long long>(s.raysTraced),
                      static_cast<unsigned long long>(s.shadowRays));
        return out + buf;
    }

private:
    // Declaration order matters: the core and renderer refer to scene_.
    Scene scene_;
    RayCore core_;
    Renderer renderer_;
};

}  // namespace

std::unique_ptr<RayEvaluator> MakeSceneEvaluator(const std::vector<std::string>& sceneFiles,
                                                 const RtraceOptions& options,
                                                 const WarningSink& warn,
                                                 const std::string& toolDirectory) {
    SceneLoadOptions load;
    load.toolDirectory = toolDirectory;
    return std::make_unique<SceneEvaluator>(LoadScene(sceneFiles, load, warn), options, warn);
}

std::string ExecutableDirectory() {
    std::error_code ec;
    std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (ec) return {};
    return exe.parent_path().string();
}

}  // namespace rt
