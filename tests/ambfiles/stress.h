// SPDX-License-Identifier: MIT
//
// The shared-ambient-file stress test (issue 18): many writer processes append
// to one file through SharedAmbientFile while the driver SIGKILLs some of them
// at random moments (often inside write(2), leaving a torn record) and the
// writers' own fault hook makes some appends stop short, either failing as a
// full disk does or dying on the spot with the lock held. Each writer logs the
// ids of the records it synced, after Sync() returns. At the end one more
// process syncs, and the file must hold every logged record exactly once, with
// every record valid and nothing after the last whole record.
//
// Run small in ctest (stress_test.cpp) and at full size by hand through
// bench/ambfile_stress.sh (the ambfile_stress program).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace rt::testing {

struct StressConfig {
    std::string directory;        // where the file and the writers' logs go
    int concurrentWriters = 8;    // writer processes alive at once
    int totalWriters = 24;        // writer processes over the whole run
    int recordsPerWriter = 200;   // each writer's quota, in batches of 1..122
    double killsPerSecond = 20;   // driver's SIGKILLs, at random running writers
    double shortWriteChance = 0.05;  // per append: stops short (half ENOSPC, half death)
    // When > 0, writers number 0, k, 2k, ... are spared the driver's SIGKILLs and
    // their first append stops short for certain: as a full disk for the even
    // multiples, dying with the lock held for the odd ones. The random faults
    // alone can miss a kind in a small run; these make every kind happen.
    int certainFaultsEvery = 0;
    std::uint64_t seed = 1;
};

struct StressResult {
    int writers = 0;              // writer processes started
    int killedByDriver = 0;       // SIGKILLed by the driver
    int diedInShortWrite = 0;     // killed themselves inside a short write
    int fullDiskErrors = 0;       // short writes reported as ENOSPC (then retried)
    int otherFailures = 0;        // writers that exited with an error (must be 0)
    std::size_t syncedRecords = 0;    // logged by writers after Sync() returned
    std::size_t recordsInFile = 0;    // after the final sync
    std::size_t missing = 0;          // logged but not in the file (must be 0)
    std::size_t invalid = 0;          // slots failing the validity rules (must be 0)
    std::size_t duplicates = 0;       // records in the file twice (must be 0)
    std::size_t trailingBytes = 0;    // after the last whole record (must be 0)
    std::size_t tornTailsCut = 0;     // torn records cut off by a later sync
    double seconds = 0;

    bool Ok() const {
        return otherFailures == 0 && missing == 0 && invalid == 0 && duplicates == 0 &&
               trailingBytes == 0 && recordsInFile > 0;
    }
    std::string ToString() const;
};

StressResult RunAmbientFileStress(const StressConfig& config);

}  // namespace rt::testing
