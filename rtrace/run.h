// SPDX-License-Identifier: MIT
//
// rtrace's program flow (rtmain.c main() and rtrace.c rtrace(),
// radiance-notes.md §1.4-1.5): parse, open the -e file, build the evaluator,
// write the header, then read rays and write records with Radiance's -x/-y
// counting, flush points and zero-direction flush records. The scene and the
// renderer come in through RayEvaluator (rtrace/ray_evaluator.h); messages,
// -e and exit codes through the program shell (program/shell.h).
//
// Differences from Radiance (deliberate): a zero-direction record always
// flushes output after its record (Radiance may defer that flush while an -x
// countdown runs); bad input is an error (see ray_input.h); -n N > 1 runs
// one process with N threads.
//
//   RunEnvironment env{.makeEvaluator = MakeSceneEvaluator};
//   return Run(args, std::cin, std::cout, std::cerr, env);
#pragma once

#include <istream>
#include <ostream>
#include <span>
#include <string>

#include "rtrace/ray_evaluator.h"

namespace rt {

/// Runs rtrace with `args` (argv[0] first). Returns the exit status: 0, or
/// Radiance's 1 (user error), 2 (system error), 3 (internal error). Messages
/// go to `err` (or the -e file) as "<prog>: <kind> - <text>".
int Run(std::span<const std::string> args, std::istream& in, std::ostream& out,
        std::ostream& err, const RunEnvironment& env);

}  // namespace rt
