// SPDX-License-Identifier: MIT
#include "shading/renderer.h"

#include <utility>

#include "ambient/irradiance_cache.h"
#include "shading/ray_tree.h"
#include "shading/shading_state.h"

namespace rt {

struct Renderer::Shared {
    Shared(const Scene& scene, const RayCore& core, const ShadingOptions& shading,
           const AmbientOptions& ambient, const WarningSink& warn,
           std::shared_ptr<AmbientCache> cache)
        : setup(scene, core, shading, ambient, warn, std::move(cache)), tree(setup) {}
    ShadingSetup setup;
    RayTree tree;  // refers to `setup`, declared before it
};

struct Renderer::Impl {
    std::shared_ptr<const Shared> shared;
    ThreadState state;
};

std::shared_ptr<AmbientCache> Renderer::MakeCache(const Scene& scene,
                                                 const AmbientOptions& ambient) {
    if (ambient.bounces <= 0 || ambient.divisions <= 0 || ambient.accuracy <= kFtiny) {
        return nullptr;
    }
    const LevelMethods methods = MethodsFor(ambient.recordMethods);
    return std::make_shared<AmbientCache>(
        scene.cubeOrigin, scene.cubeSize, ambient.accuracy,
        AmbientLimits::FromResolution(ambient.resolution, scene.cubeSize, scene.ToleranceScale()),
        WeightingFor(methods.firstLevel), WeightingFor(methods.deeper));
}

std::shared_ptr<const Renderer::Shared> Renderer::Share(const Scene& scene, const RayCore& core,
                                                       const ShadingOptions& shading,
                                                       const AmbientOptions& ambient,
                                                       const WarningSink& warn,
                                                       std::shared_ptr<AmbientCache> cache) {
    return std::make_shared<const Shared>(scene, core, shading, ambient, warn, std::move(cache));
}

Renderer::Renderer(std::shared_ptr<const Shared> shared, WarningSink warn)
    : impl_(new Impl{shared, ThreadState(shared->setup, std::move(warn))}) {}

Renderer::Renderer(const Scene& scene, const RayCore& core, const ShadingOptions& shading,
                   const AmbientOptions& ambient, WarningSink warn)
    : Renderer(scene, core, shading, ambient, std::move(warn), MakeCache(scene, ambient)) {}

Renderer::Renderer(const Scene& scene, const RayCore& core, const ShadingOptions& shading,
                   const AmbientOptions& ambient, WarningSink warn,
                   std::shared_ptr<AmbientCache> cache)
    : Renderer(Share(scene, core, shading, ambient, warn, std::move(cache)), warn) {}

Renderer::~Renderer() = default;

RayResult Renderer::TraceInput(const Vec3& org, const Vec3& dir, double rmax,
                               std::uint64_t rayIndex) {
    return impl_->shared->tree.TraceInput(impl_->state, org, dir, rmax, rayIndex);
}

void Renderer::SetTraceCallback(std::function<void(const RayResult&)> callback,
                                bool shadowRays) {
    impl_->state.trace = std::move(callback);
    impl_->state.traceShadows = shadowRays;
}

const RenderStats& Renderer::Stats() const { return impl_->state.stats; }

void Renderer::EnableTiming(bool on) { impl_->state.EnableTiming(on); }

std::vector<AmbientRecord> Renderer::TakeNewRecords() {
    return std::exchange(impl_->state.ambient.newRecords, {});
}

void Renderer::QueueNewRecords(bool on) {
    impl_->state.ambient.queueNewRecords = on;
    if (!on) impl_->state.ambient.newRecords = {};
}

std::vector<AmbientRecord> Renderer::CacheRecords() const {
    const auto& cache = impl_->shared->setup.cache;
    return cache ? cache->Records() : std::vector<AmbientRecord>{};
}

}  // namespace rt
