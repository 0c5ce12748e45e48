// SPDX-License-Identifier: MIT
//
// Encodes and decodes Radiance ambient records in the portable 67-byte
// "Radiance_ambval" layout written by Radiance 5's ambio.c (writambval,
// readambval, ambvalOK; radiance-notes.md §5.2, §5.6). Pure functions over
// bytes: no files, no locks (those live in shared_file.h).
//
// In Radiance every stored field is a float in memory (AMBVAL), so a record passes
// through float precision before it is written and a decoded record holds
// float-exact doubles: EncodeRecord(*DecodeRecord(b)) == b for the records Radiance
// writes. Arbitrary valid bytes need not come back byte for byte (putflt has
// non-canonical encodings, setcolr writes colours below 1e-32 as zero, and a float
// denormal weight underflows putflt's exponent byte, so that record is not
// IsStorable), but a storable decoded record is a fixed point after one trip
// (tests/fuzz/fuzz_ambfile.cpp checks this).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

#include "ambient/record.h"

namespace rt {

inline constexpr int kAmbientMagic = 559;             // 2 bytes, big-endian, after the header
inline constexpr std::size_t kAmbientMagicBytes = 2;
inline constexpr std::size_t kRecordBytes = 67;       // AMBVALSIZ
inline constexpr std::string_view kAmbientFormat = "Radiance_ambval";  // FORMAT= value
using RecordBytes = std::array<std::uint8_t, kRecordBytes>;

/// One field of the on-disk record, in file order (the table the 67-byte test pins).
struct RecordField {
    std::string_view name;
    std::size_t offset;
    std::size_t bytes;
};
inline constexpr std::array<RecordField, 10> kRecordLayout{{
    {"lvl", 0, 1},       // unsigned byte
    {"weight", 1, 5},    // putflt
    {"pos", 6, 15},      // 3 × putflt
    {"ndir", 21, 4},     // direction code, big-endian
    {"udir", 25, 4},     // direction code, big-endian
    {"val", 29, 4},      // RGBE
    {"rad", 33, 10},     // 2 × putflt
    {"gpos", 43, 10},    // 2 × putflt
    {"gdir", 53, 10},    // 2 × putflt
    {"corral", 63, 4},   // uint32, big-endian
}};

/// Byte-for-byte what Radiance's writambval() produces for `record` (fields first
/// rounded to float, directions through EncodeDirection, colour through RGBE).
RecordBytes EncodeRecord(const AmbientRecord& record);

/// readambval(): std::nullopt when the bytes fail Radiance's ambvalOK() checks —
/// pos/gpos/gdir in [−1e10, 1e10], nonzero direction codes, 0 < weight ≤ 1,
/// 0 < rad < 1e10, colour in [0, 1e10) — or (stricter than Radiance, and only
/// possible in damaged data) when a direction code decodes to a non-finite vector.
/// `level` is the byte as unsigned (0..255), `corral` is unchecked, as in Radiance.
std::optional<AmbientRecord> DecodeRecord(std::span<const std::uint8_t, kRecordBytes> bytes);

/// True when `record` survives EncodeRecord → DecodeRecord, i.e. readers will accept
/// it. Writers skip records that fail this, because a reader stops at the first
/// invalid record and would lose everything after it.
bool IsStorable(const AmbientRecord& record);

}  // namespace rt
