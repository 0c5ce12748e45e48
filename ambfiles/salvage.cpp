// SPDX-License-Identifier: MIT
#include "ambfiles/salvage.h"

#include <algorithm>

#include "ambfiles/header.h"
#include "ambfiles/record_codec.h"

namespace rt {
namespace {

/// Canonical windows in a row that confirm a record in step with the last one.
constexpr std::size_t kResyncRun = 3;

class Scanner {
public:
    explicit Scanner(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}

    bool Valid(std::size_t at) const { return Decode(at).has_value(); }

    /// Valid, and written as Radiance (and lazyrad) write: re-encoding gives the
    /// same bytes. A window straddling two records almost never is, since its
    /// float fields start mid-number.
    bool Canonical(std::size_t at) const {
        const std::optional<AmbientRecord> r = Decode(at);
        if (!r) return false;
        const RecordBytes again = EncodeRecord(*r);
        return std::equal(again.begin(), again.end(), bytes_.begin() + static_cast<std::ptrdiff_t>(at));
    }

    /// kResyncRun canonical windows from `at`, or fewer followed by less than
    /// a record (the end of the file, or a torn tail).
    bool StartsRun(std::size_t at) const {
        for (std::size_t k = 0; k < kResyncRun; ++k) {
            const std::size_t p = at + k * kRecordBytes;
            if (p + kRecordBytes > bytes_.size()) return k > 0;
            if (!Canonical(p)) return false;
        }
        return true;
    }

    /// The first offset in [from, to) where a canonical window starts, or `to`.
    std::size_t NextCanonical(std::size_t from, std::size_t to) const {
        for (std::size_t p = from; p < to; ++p) {
            if (Canonical(p)) return p;
        }
        return to;
    }

    std::size_t Size() const { return bytes_.size(); }

private:
    std::optional<AmbientRecord> Decode(std::size_t at) const {
        if (at + kRecordBytes > bytes_.size()) return std::nullopt;
        return DecodeRecord(
            std::span<const std::uint8_t, kRecordBytes>(bytes_.data() + at, kRecordBytes));
    }

    std::span<const std::uint8_t> bytes_;
};

}  // namespace

std::optional<SalvageResult> SalvageAmbientFile(std::span<const std::uint8_t> bytes,
                                                std::string* problem) {
    const HeaderParse parse = ParseAmbientHeader(bytes);
    if (!parse.header) {
        if (problem) *problem = parse.problem;
        return std::nullopt;
    }
    const std::size_t start = parse.header->recordsOffset;
    SalvageResult out;
    out.file.assign(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(start));
    const Scanner scan(bytes);
    auto drop = [&](std::size_t from, std::size_t to) {
        if (to <= from) return;
        if (out.firstDamage < 0) out.firstDamage = static_cast<std::int64_t>(from);
        out.droppedBytes += to - from;
        ++out.damagedStretches;
    };
    std::size_t pos = start;
    while (pos + kRecordBytes <= scan.Size()) {
        std::size_t next = pos;  // where the next kept record starts
        if (scan.Valid(pos)) {
            // In step and starting a run: keep it. Otherwise it may be the torn
            // fragment of a record joined to the start of the next one (for a
            // fragment of 63 bytes or more it is even canonical), which a
            // canonical window starting inside it shows.
            const std::size_t end = pos + kRecordBytes;
            if (!scan.StartsRun(pos)) {
                const std::size_t inside = scan.NextCanonical(pos + 1, end);
                if (inside < end) next = inside;
            }
        } else {
            next = scan.NextCanonical(pos + 1, scan.Size());
        }
        if (next != pos) {
            drop(pos, next);
            pos = next;
            continue;
        }
        out.file.insert(out.file.end(), bytes.begin() + static_cast<std::ptrdiff_t>(pos),
                        bytes.begin() + static_cast<std::ptrdiff_t>(pos + kRecordBytes));
        ++out.records;
        pos += kRecordBytes;
    }
    drop(pos, scan.Size());  // a torn tail
    return out;
}

}  // namespace rt
