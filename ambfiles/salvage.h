// SPDX-License-Identifier: MIT
//
// Recovering the valid records of a damaged ambient file (lookamb -s). Radiance
// can leave a shared file misaligned: it cuts what it takes for a torn tail,
// and a later flush outside its lock stops mid-record, so every record after
// the fragment sits off the 67-byte grid and Radiance's reader (and ours) stop
// there. Salvage re-synchronises on record boundaries instead of stopping.
//
// Rules. A 67-byte window that straddles two records passes Radiance's
// validity checks about once in 600 windows (cornell_radiance54.amb, all 66
// shifts), but it is never canonical there (re-encoding its decoded record
// gives other bytes, its float fields starting mid-number), while every record
// Radiance or lazyrad writes is. So:
//  * after an invalid window the scan resumes at the next canonical window;
//  * a valid record in step with the last one is kept unless it is not
//    followed by two more canonical records (or the end of the file) and a
//    canonical window starts inside it: it is then the torn fragment of a
//    record joined to the start of the next one (a fragment of 63 bytes or
//    more, whose corral is the next record's first bytes, is canonical too).
// What a writer tore off is lost; records written whole are all recovered,
// even one alone between two damaged stretches. Limit: a fragment directly
// followed by a torn tail (no whole record between) reads as one record when
// the two make 67 bytes that pass as canonical; its last fields are then the
// tail's first bytes.

#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace rt {

struct SalvageResult {
    std::vector<std::uint8_t> file;   // the header as it was, then the records kept
    std::size_t records = 0;          // records kept
    std::size_t droppedBytes = 0;     // bytes after the header not kept
    std::size_t damagedStretches = 0; // runs of dropped bytes
    std::int64_t firstDamage = -1;    // byte offset of the first dropped byte, -1 if none
};

/// Salvages `bytes` (a whole ambient file). nullopt when the header is not an
/// ambient file's (`problem` says why); the input is never modified.
std::optional<SalvageResult> SalvageAmbientFile(std::span<const std::uint8_t> bytes,
                                                std::string* problem = nullptr);

}  // namespace rt
