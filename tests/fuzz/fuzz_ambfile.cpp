// SPDX-License-Identifier: MIT
//
// Fuzz target: the ambient file reader. ParseAmbientHeader on the bytes, then
// DecodeRecord on every whole 67-byte chunk after the header (from offset 0 when
// there is no header); a decoded record that IsStorable() must be stable after one
// encode/decode trip. Finally the bytes as a file through SharedAmbientFile
// (open, LoadAll), in a fixed per-process temporary file; rt::Error is expected.
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <span>
#include <sstream>
#include <string>

#include <unistd.h>

#include "ambfiles/header.h"
#include "ambfiles/record_codec.h"
#include "ambfiles/shared_file.h"
#include "core/error.h"
#include "tests/fuzz/fuzz_entry.h"

namespace {

const std::string& TempPath() {
    static const std::string path =
        "/tmp/lazyrad_fuzz_ambfile_" + std::to_string(getpid()) + ".amb";
    return path;
}

void DecodeAll(std::span<const std::uint8_t> bytes, std::size_t start) {
    for (std::size_t at = start; at + rt::kRecordBytes <= bytes.size(); at += rt::kRecordBytes) {
        const std::span<const std::uint8_t, rt::kRecordBytes> chunk(bytes.data() + at,
                                                                    rt::kRecordBytes);
        const std::optional<rt::AmbientRecord> record = rt::DecodeRecord(chunk);
        if (!record) continue;
        // A storable record (IsStorable) is a fixed point after one trip through the
        // format. Not byte equality with `chunk`: putflt has non-canonical encodings, RGBE
        // colours below 1e-32 are written as zero (Radiance's setcolr), and a value whose
        // exponent underflows putflt's byte (a float denormal weight) is written as zero,
        // which no reader accepts: such a valid record is not storable, as in Radiance.
        if (!rt::IsStorable(*record)) continue;
        const rt::RecordBytes once = rt::EncodeRecord(*record);
        const std::optional<rt::AmbientRecord> back = rt::DecodeRecord(once);
        if (!back || rt::EncodeRecord(*back) != once) {
            std::ostringstream message;
            message << "fuzz_ambfile: record at byte " << at
                    << " is not stable after one encode/decode trip:\n  decoded " << *record
                    << "\n  again   ";
            if (back) message << *back; else message << "(invalid)";
            std::fprintf(stderr, "%s\n", message.str().c_str());
            std::abort();
        }
    }
}

}  // namespace

extern "C" int RT_FUZZ_ENTRY(const std::uint8_t* data, std::size_t size) {
    const std::span<const std::uint8_t> bytes(data, size);
    const rt::HeaderParse parse = rt::ParseAmbientHeader(bytes);
    if (parse.header && parse.header->recordsOffset > size) {
        std::fprintf(stderr, "fuzz_ambfile: recordsOffset %zu past the end (%zu)\n",
                     parse.header->recordsOffset, size);
        std::abort();
    }
    DecodeAll(bytes, parse.header ? parse.header->recordsOffset : 0);

    {
        std::ofstream out(TempPath(), std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    }
    try {
        rt::SharedAmbientFile file(TempPath(), rt::AmbientHeaderParams{}, rt::WarningSink{});
        const std::vector<rt::AmbientRecord> records = file.LoadAll();
        static_cast<void>(records);
    } catch (const rt::Error& e) {
        rt::fuzz::ExpectRefusal(e);
        // Not an ambient file: expected.
    }
    std::remove(TempPath().c_str());
    return 0;
}
