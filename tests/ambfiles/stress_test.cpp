// SPDX-License-Identifier: MIT
//
// The shared-ambient-file stress test at CI size (a few seconds): writers
// appending at once, SIGKILLs at random moments, short writes that fail as a
// full disk or kill the writer mid-record. Every synced record must be in the
// file once, every record valid. Full size: bench/ambfile_stress.sh.
#include "tests/ambfiles/stress.h"

#include <gtest/gtest.h>

#include <cstdio>

#include "tests/ambfiles/test_util.h"

namespace rt {
namespace {

TEST(AmbientFileStress, WritersKilledAndShortWritesLoseNoSyncedRecord) {
    testing::TempDir dir;
    testing::StressConfig c;
    c.directory = dir.Path();
    c.concurrentWriters = 8;
    c.totalWriters = 40;
    c.recordsPerWriter = 400;
    c.killsPerSecond = 100;
    c.shortWriteChance = 0.08;
    c.seed = 18;
    c.certainFaultsEvery = 8;  // 5 writers: 3 full disks and 2 deaths for certain
    const testing::StressResult r = testing::RunAmbientFileStress(c);
    std::printf("%s\n", r.ToString().c_str());
    EXPECT_TRUE(r.Ok()) << r.ToString();
    // The faults did happen.
    EXPECT_GT(r.killedByDriver, 0) << r.ToString();
    EXPECT_GT(r.diedInShortWrite, 0) << r.ToString();
    EXPECT_GT(r.fullDiskErrors, 0) << r.ToString();
    EXPECT_GT(r.tornTailsCut, 0u) << r.ToString();
    EXPECT_GT(r.syncedRecords, 3000u) << r.ToString();
}

}  // namespace
}  // namespace rt
