// SPDX-License-Identifier: MIT
//
// lookamb -s (ambfiles/salvage.h) against files mangled the way Radiance
// mangles a shared file (issue 18): a torn tail, cut, then a flush outside the
// lock that stops mid-record, so that every later record is misaligned. The
// files are built from real Radiance records (tests/data/ambfiles/).
#include "ambfiles/salvage.h"

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <string>
#include <vector>

#include "ambfiles/record_codec.h"
#include "ambfiles/shared_file.h"
#include "tests/ambfiles/test_util.h"

namespace rt {
namespace {

using testing::DataPath;
using testing::kRadianceRecordCount;
using testing::kRadianceRecordsOffset;
using testing::ReadBytes;
using testing::TempDir;
using Bytes = std::vector<std::uint8_t>;

struct Radiance {
    Bytes header;                // up to and including the magic
    std::vector<Bytes> records;  // 3429 records written by real Radiance 5.4a
};

const Radiance& RadianceFile() {
    static const Radiance file = [] {
        const Bytes all = ReadBytes(DataPath("cornell_radiance54.amb"));
        Radiance r;
        r.header.assign(all.begin(), all.begin() + kRadianceRecordsOffset);
        for (std::size_t i = 0; i < kRadianceRecordCount; ++i) {
            const auto at = all.begin() + static_cast<std::ptrdiff_t>(kRadianceRecordsOffset +
                                                                      i * kRecordBytes);
            r.records.emplace_back(at, at + kRecordBytes);
        }
        return r;
    }();
    return file;
}

/// A file mangled as Radiance mangles one: records [0, n) in order, where
/// fragments[k] = {i, b} replaces record i by its first b bytes (a write that
/// stopped mid-record), so every record after it is off the 67-byte grid.
/// `expected` gets the records that survive whole.
Bytes Mangled(std::size_t n, const std::vector<std::pair<std::size_t, std::size_t>>& fragments,
              std::size_t tornTail, Bytes* expected) {
    const Radiance& r = RadianceFile();
    Bytes file = r.header;
    expected->assign(r.header.begin(), r.header.end());
    for (std::size_t i = 0; i < n; ++i) {
        std::size_t keep = kRecordBytes;
        for (const auto& [at, bytes] : fragments) {
            if (at == i) keep = bytes;
        }
        file.insert(file.end(), r.records[i].begin(),
                    r.records[i].begin() + static_cast<std::ptrdiff_t>(keep));
        if (keep == kRecordBytes) expected->insert(expected->end(), r.records[i].begin(),
                                                   r.records[i].end());
    }
    file.insert(file.end(), r.records[n].begin(),
                r.records[n].begin() + static_cast<std::ptrdiff_t>(tornTail));
    return file;
}

/// Every fragment length from 1 to 66 bytes, including the ones whose first 63
/// bytes make a record that passes every check (only its corral is wrong).
TEST(Salvage, RecoversEveryWholeRecordAfterAFragmentOfAnyLength) {
    for (std::size_t b = 1; b < kRecordBytes; ++b) {
        Bytes expected;
        const Bytes file = Mangled(300, {{100, b}}, 0, &expected);
        const auto result = SalvageAmbientFile(file);
        ASSERT_TRUE(result);
        EXPECT_EQ(result->file, expected) << "fragment of " << b << " bytes";
        EXPECT_EQ(result->records, 299u) << b;
        EXPECT_EQ(result->damagedStretches, 1u) << b;
        EXPECT_EQ(result->droppedBytes, b) << b;
        EXPECT_EQ(result->firstDamage,
                  static_cast<std::int64_t>(kRadianceRecordsOffset + 100 * kRecordBytes))
            << b;
    }
}

/// The case at full size: a torn tail cut, flushes stopping mid-record
/// four more times (hundreds of misaligned slots after each), one record alone
/// between two fragments, and a torn tail again. Every whole record comes
/// back, in order, and nothing else.
TEST(Salvage, RecoversARadianceFileMisalignedSeveralTimes) {
    Bytes expected;
    const Bytes file = Mangled(kRadianceRecordCount - 1,
                               {{500, 40}, {1383, 13}, {2200, 64}, {3000, 5}, {3002, 30}}, 29,
                               &expected);
    const auto result = SalvageAmbientFile(file);
    ASSERT_TRUE(result);
    EXPECT_EQ(result->file, expected);
    EXPECT_EQ(result->records, kRadianceRecordCount - 1 - 5);
    EXPECT_EQ(result->damagedStretches, 6u);
    EXPECT_EQ(result->droppedBytes, 40u + 13 + 64 + 5 + 30 + 29);
    // Radiance's reader stops at the first fragment.
    std::size_t plain = 0;
    for (std::size_t at = kRadianceRecordsOffset; at + kRecordBytes <= file.size();
         at += kRecordBytes, ++plain) {
        if (!DecodeRecord(std::span<const std::uint8_t, kRecordBytes>(file.data() + at,
                                                                      kRecordBytes))) {
            break;
        }
    }
    EXPECT_LE(plain, 501u);
}

/// Many mangled files: six fragments of random length at random places (some
/// with a single record between them), a random torn tail after at least one
/// more whole record (see the limit in salvage.h). Exact recovery.
TEST(Salvage, RecoversRandomlyMangledFiles) {
    std::uint64_t state = 18;
    auto next = [&](std::uint64_t n) {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        return (state >> 33) % n;
    };
    for (int trial = 0; trial < 100; ++trial) {
        std::vector<std::pair<std::size_t, std::size_t>> fragments;
        std::size_t at = 0;
        for (int k = 0; k < 6; ++k) {
            at += 2 + next(400);
            fragments.emplace_back(at, 1 + next(kRecordBytes - 1));
        }
        Bytes expected;
        const Bytes file = Mangled(at + 2 + next(50), fragments, next(kRecordBytes), &expected);
        const auto result = SalvageAmbientFile(file);
        ASSERT_TRUE(result);
        if (result->file == expected) continue;
        std::size_t diff = 0;
        while (diff < std::min(result->file.size(), expected.size()) &&
               result->file[diff] == expected[diff]) {
            ++diff;
        }
        std::string where;
        for (const auto& [i, b] : fragments) {
            where.append(" ").append(std::to_string(i)).append(":").append(std::to_string(b));
        }
        ADD_FAILURE() << "trial " << trial << ": " << result->file.size() << " bytes for "
                      << expected.size() << ", first difference in record "
                      << (diff - kRadianceRecordsOffset) / kRecordBytes << "; fragments" << where;
    }
}

TEST(Salvage, UndamagedFileIsCopiedAndNonAmbientFileIsRefused) {
    const Bytes all = ReadBytes(DataPath("cornell_radiance54.amb"));
    const auto result = SalvageAmbientFile(all);
    ASSERT_TRUE(result);
    EXPECT_EQ(result->file, all);
    EXPECT_EQ(result->damagedStretches, 0u);
    EXPECT_EQ(result->firstDamage, -1);
    const std::string text = "not an ambient file\n\n";
    std::string problem;
    EXPECT_FALSE(SalvageAmbientFile(
        std::span<const std::uint8_t>(reinterpret_cast<const std::uint8_t*>(text.data()),
                                      text.size()),
        &problem));
    EXPECT_FALSE(problem.empty());
}

/// The tool: writes the salvaged file to stdout, one line on stderr, leaves the
/// damaged file byte for byte as it was, and lazyrad loads the result cleanly.
TEST(Salvage, LookambMinusSWritesANewFileAndLeavesTheOriginal) {
    TempDir dir;
    Bytes expected;
    const Bytes damaged = Mangled(1200, {{700, 21}}, 50, &expected);
    const std::string in = dir.File("damaged.amb"), out = dir.File("fixed.amb");
    testing::WriteBytes(in, damaged);
    const std::string cmd = std::string(RT_BINARY_DIR "/bin/lookamb") + " -s " + in + " > " +
                            out + " 2> " + dir.File("err.txt");
    const int st = std::system(cmd.c_str());
    ASSERT_TRUE(WIFEXITED(st) && WEXITSTATUS(st) == 0);
    EXPECT_EQ(ReadBytes(in), damaged);
    EXPECT_EQ(ReadBytes(out), expected);
    EXPECT_EQ(testing::ReadText(dir.File("err.txt")),
              std::string(RT_BINARY_DIR "/bin/lookamb") + ": " + in +
                  ": 1199 records recovered; 71 bytes dropped in 2 damaged stretches, the first "
                  "at byte " + std::to_string(kRadianceRecordsOffset + 700 * kRecordBytes) +
                  "\n");
    std::vector<std::string> warnings;
    SharedAmbientFile loaded(out, AmbientHeaderParams{},
                             [&](const std::string& w) { warnings.push_back(w); });
    EXPECT_EQ(loaded.LoadAll().size(), 1199u);
    EXPECT_TRUE(warnings.empty());
}

}  // namespace
}  // namespace rt
