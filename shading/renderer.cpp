// SPDX-License-Identifier: MIT
#include "shading/renderer.h"

#include "shading/integrator.h"

namespace rt {

struct Renderer::Impl {
    Integrator integrator;
};

Renderer::Renderer(const Scene& scene, const RayCore& core, const ShadingOptions& shading,
                   const AmbientOptions& ambient, WarningSink warn)
    : impl_(new Impl{Integrator(scene, core, shading, ambient, std::move(warn))}) {}

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

}  // namespace rt
