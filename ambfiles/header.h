// SPDX-License-Identifier: MIT
//
// The text header in front of an ambient file's records (Radiance's initambfile()
// in ambient.c writing, getheader()/checkheader() in header.c plus hasambmagic()
// reading; radiance-notes.md §5.1). Pure functions over bytes.
//
//   #?RADIANCE
//   rtrace -av 0 0 0 -aw 0 -ab 2 -aa 0.15 -ad 512 -as 256 -ar 128 cornell.oct
//   SOFTWARE= <software>
//   CAPDATE= 2026:11:22 01:24:37        (optional)
//   GMT= 2026:11:22 01:24:37            (optional)
//   FORMAT=Radiance_ambval
//   <blank line><magic 0x02 0x2F><records...>
#pragma once

#include <cstddef>
#include <cstdint>
#include <ctime>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/rgb.h"

namespace rt {

/// What initambfile() records on the command-line line: the effective ambient
/// options. Informational only; Radiance never compares them when reopening.
struct AmbientHeaderParams {
    std::string programName = "rtrace";  // basename of argv[0]
    Rgb ambientValue;                    // -av
    int valueWeight = 0;                 // -aw
    int bounces = 0;                     // -ab
    double accuracy = 0.1;               // -aa
    int divisions = 1024;                // -ad
    int superSamples = 512;              // -as
    int resolution = 256;                // -ar
    std::string octreeName;              // scene name; empty leaves a trailing space, as Radiance
    std::string software;                // SOFTWARE= value, e.g. "lazyrad 0.1.0"
    std::optional<std::time_t> captureTime;  // CAPDATE=/GMT= lines; nullopt omits them
};

/// The full header text including the blank line, followed by the 2-byte magic.
std::string FormatAmbientHeader(const AmbientHeaderParams& params);

struct ParsedAmbientHeader {
    std::vector<std::string> lines;     // each header line without its '\n', blank line excluded
    std::optional<std::string> format;  // FORMAT= value if present
    std::size_t recordsOffset = 0;      // byte offset of the first record (just after the magic)
};

/// Result of looking at the start of a file.
struct HeaderParse {
    std::optional<ParsedAmbientHeader> header;  // set when the bytes start an ambient file
    std::string problem;                        // otherwise: why not, one line
};

/// formatval(): the value of a "FORMAT=" header line, nullopt for other lines.
std::optional<std::string> HeaderFormatValue(std::string_view line);

/// Accepts what Radiance accepts, except that the first line must start with "#?"
/// (every file Radiance 5 writes does; this keeps arbitrary text files out):
/// header lines up to a blank line ("\n" or "\r\n"), an optional FORMAT= that must be
/// Radiance_ambval, then the magic 559. `bytes` is the file from its start; it
/// only needs to extend past the magic.
HeaderParse ParseAmbientHeader(std::span<const std::uint8_t> bytes);

}  // namespace rt
