// SPDX-License-Identifier: MIT
//
// rvimage: renders a Radiance view with the rtrace renderer (rvimage/rvimage.h).
//   rvimage [rtrace options] [view options] [-x X -y Y -pa A -pj J]
//           -o out.exr|out.hdr|out.png [-layers indirect,records,outcome] scene.rad ...
#include <unistd.h>

#include <iostream>
#include <string>
#include <vector>

#include "core/huge_pages.h"
#include "program/arguments.h"
#include "program/signals.h"
#include "rtrace/scene_evaluator.h"
#include "rvimage/rvimage.h"

int main(int argc, char** argv) {
    // Heap blocks from huge pages from the start (core/huge_pages.h).
    rt::ReserveHeapInHugePages(rt::kProgramHeapReserve);
    rt::ReportFatalSignals(rt::ProgramName(argc > 0 ? argv[0] : "rvimage"));
    std::vector<std::string> args(argv, argv + argc);
    return rt::RunRvimage(args, std::cout, std::cerr, rt::ProcessEnvironment(),
                          isatty(STDERR_FILENO) != 0);
}
