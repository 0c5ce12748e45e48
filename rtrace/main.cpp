// SPDX-License-Identifier: MIT
//
// rtrace: parse, build, run (rtrace/run.cpp), with errors mapped to exit codes
// by the program shell (program/shell.h).
#include <iostream>
#include <string>
#include <vector>

#include "core/huge_pages.h"
#include "rtrace/run.h"
#include "rtrace/scene_evaluator.h"

int main(int argc, char** argv) {
    // Heap blocks from huge pages: on the virtual machines lazyrad is measured
    // on, each 4 KiB page's first touch costs some 10-20 µs (docs/measured-choices.md).
    rt::ReserveHeapInHugePages(rt::kProgramHeapReserve);
    // Run() buffers its own output; iostreams need not track stdio.
    std::ios::sync_with_stdio(false);
    std::vector<std::string> args(argv, argv + argc);
    return rt::Run(args, std::cin, std::cout, std::cerr, rt::ProcessEnvironment());
}
