// SPDX-License-Identifier: MIT
#include "rtrace/scene_evaluator.h"

#include <filesystem>
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
