// SPDX-License-Identifier: MIT
//
// The real RayEvaluator: loads the .rad files (scene/loader.h), builds the
// Embree ray core and the Renderer. Kept apart from rt_rtrace_lib so the front
// end and its tests do not need the rendering modules to link.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "rtrace/ray_evaluator.h"

namespace rt {

/// An EvaluatorFactory. `toolDirectory` (where the bundled genbox/xform live)
/// is put first on PATH for `!command` lines; empty leaves PATH alone.
std::unique_ptr<RayEvaluator> MakeSceneEvaluator(const std::vector<std::string>& sceneFiles,
                                                 const RtraceOptions& options,
                                                 const WarningSink& warn,
                                                 const std::string& toolDirectory);

/// Directory of the running executable (from /proc/self/exe), empty if unknown.
std::string ExecutableDirectory();

/// The environment of this process for Run()/RunRvimage(): real scenes
/// (bundled tools found next to the executable), the clock, the pid.
RunEnvironment ProcessEnvironment();

}  // namespace rt
