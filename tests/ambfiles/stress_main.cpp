// SPDX-License-Identifier: MIT
//
// ambfile_stress: the shared-ambient-file stress test at any size, for
// bench/ambfile_stress.sh. Prints one line and exits 1 when a guarantee failed.
//   ambfile_stress DIR CONCURRENT TOTAL_WRITERS RECORDS_PER_WRITER KILLS_PER_S
//                  SHORT_WRITE_CHANCE SEED
#include <cstdio>
#include <cstdlib>
#include <string>

#include "tests/ambfiles/stress.h"

int main(int argc, char** argv) {
    if (argc != 8) {
        std::fprintf(stderr,
                     "usage: %s DIR CONCURRENT TOTAL_WRITERS RECORDS_PER_WRITER KILLS_PER_S "
                     "SHORT_WRITE_CHANCE SEED\n",
                     argv[0]);
        return 2;
    }
    rt::testing::StressConfig c;
    c.directory = argv[1];
    c.concurrentWriters = std::atoi(argv[2]);
    c.totalWriters = std::atoi(argv[3]);
    c.recordsPerWriter = std::atoi(argv[4]);
    c.killsPerSecond = std::atof(argv[5]);
    c.shortWriteChance = std::atof(argv[6]);
    c.seed = std::strtoull(argv[7], nullptr, 10);
    try {
        const rt::testing::StressResult r = rt::testing::RunAmbientFileStress(c);
        std::printf("%s: %s\n", r.Ok() ? "ok" : "FAILED", r.ToString().c_str());
        return r.Ok() ? 0 : 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s: %s\n", argv[0], e.what());
        return 2;
    }
}
