// SPDX-License-Identifier: MIT
//
// rvimage: renders a Radiance view with the rtrace renderer (rtrace/render.h).
//   rvimage [rtrace options] [view options] [-x X -y Y -pa A -pj J]
//           -o out.exr|out.hdr|out.png [-layers indirect,records,outcome] scene.rad ...
#include <unistd.h>

#include <iostream>
#include <string>
#include <vector>

#include "rtrace/render.h"
#include "rtrace/scene_evaluator.h"

int main(int argc, char** argv) {
    std::vector<std::string> args(argv, argv + argc);
    const std::string toolDirectory = rt::ExecutableDirectory();
    rt::RunEnvironment env;
    env.makeEvaluator = [&toolDirectory](const std::vector<std::string>& files,
                                         const rt::RtraceOptions& options,
                                         const rt::WarningSink& warn) {
        return rt::MakeSceneEvaluator(files, options, warn, toolDirectory);
    };
    env.pid = static_cast<int>(getpid());
    return rt::RunRender(args, std::cout, std::cerr, env, isatty(STDERR_FILENO) != 0);
}
