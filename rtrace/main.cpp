// SPDX-License-Identifier: MIT
//
// rtrace: parse, build, run (rtrace/run.cpp), with errors mapped to exit codes
// by the program shell (program/shell.h).
#include <iostream>
#include <string>
#include <vector>

#include "core/huge_pages.h"
#include "program/arguments.h"
#include "program/signals.h"
#include "rtrace/run.h"
#include "rtrace/scene_evaluator.h"

int main(int argc, char** argv) {
    // Heap blocks from huge pages from the start (core/huge_pages.h).
    rt::ReserveHeapInHugePages(rt::kProgramHeapReserve);
    rt::ReportFatalSignals(rt::ProgramName(argc > 0 ? argv[0] : "rtrace"));
    // Run() buffers its own output; iostreams need not track stdio.
    std::ios::sync_with_stdio(false);
    std::vector<std::string> args(argv, argv + argc);
    return rt::Run(args, std::cin, std::cout, std::cerr, rt::ProcessEnvironment());
}
