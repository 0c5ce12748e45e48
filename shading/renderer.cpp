// SPDX-License-Identifier: MIT
#include "shading/renderer.h"

#include "shading/integrator.h"

namespace rt {

struct Renderer::Impl {
    Integrator integrator;
};

std::shared_ptr<AmbientCache> Renderer::MakeCache(const Scene& scene,
                                                 const AmbientOptions& ambient) {
    if (ambient.bounces <= 0 || ambient.divisions <= 0 || ambient.accuracy <= kFtiny) {
        return nullptr;
    }
    return std::make_shared<AmbientCache>(
        scene.cubeOrigin, scene.cubeSize, ambient.accuracy,
        AmbientLimits::FromResolution(ambient.resolution, scene.cubeSize, scene.ToleranceScale()));
}

Renderer::Renderer(const Scene& scene, const RayCore& core, const ShadingOptions& shading,
                   const AmbientOptions& ambient, WarningSink warn)
    : Renderer(scene, core, shading, ambient, std::move(warn), MakeCache(scene, ambient)) {}

Renderer::Renderer(const Scene& scene, const RayCore& core, const ShadingOptions& shading,
                   const AmbientOptions& ambient, WarningSink warn,
                   std::shared_ptr<AmbientCache> cache)
    : impl_(new Impl{Integrator(scene, core, shading, ambient, std::move(warn), std::move(cache))}) {}

Renderer::~Renderer() = default;

RayResult Renderer::TraceInput(const Vec3& org, const Vec3& dir, double rmax,
                               std::uint64_t rayIndex) {
    return impl_->integrator.TraceInput(org, dir, rmax, rayIndex);
}

void Renderer::SetTraceCallback(std::function<void(const RayResult&)> callback,
                                bool shadowRays) {
    impl_->integrator.SetTraceCallback(std::move(callback), shadowRays);
}

const RenderStats& Renderer::Stats() const { return impl_->integrator.stats(); }

void Renderer::EnableTiming(bool on) { impl_->integrator.EnableTiming(on); }

std::vector<AmbientRecord> Renderer::TakeNewRecords() { return impl_->integrator.TakeNewRecords(); }

std::vector<AmbientRecord> Renderer::CacheRecords() const { return impl_->integrator.CacheRecords(); }

}  // namespace rt
