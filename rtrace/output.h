// SPDX-License-Identifier: MIT
//
// rtrace's output side (radiance-notes.md §1.6-1.8, 1.10): the -o spec parsed
// into field lists, buffered writers for the ascii/float/double/RGBE number
// formats with Radiance's exact byte layout, and the information header.
// Replaces rtrace.c's setrtoutput(), oput*(), put[afd]() and the header part
// of rtmain.c.
//
//   OutputSpec spec = ParseOutputSpec(options, warn);
//   RecordWriter writer(options.outputFormat, std::cout);
//   writer.WriteRecord(spec.fields, result);   // ... writer.Flush();
#pragma once

#include "core/rgbe.h"

#include <array>
#include <cstdint>
#include <ctime>
#include <ostream>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/diagnostics.h"
#include "rtrace/command_line.h"
#include "shading/ray_result.h"

namespace rt {

struct OutputSpec {
    std::string fields;       // letters of the record written per input ray
    std::string traceFields;  // letters written for every traced ray; empty: no trace
    bool trace = false;       // a t/T section exists (with at least one letter after it)
    bool traceShadows = false;  // T: shadow rays are reported too
    bool castOnly = true;     // no letter needs shading (Radiance then only intersects)
    int components = 0;       // NCOMP: 0 in trace mode
};

/// Radiance's setrtoutput(): validates options.outputSpec against the output
/// format and irradiance mode. Throws rt::Error (User) with Radiance's text:
/// "empty output specification", "unrecognized output option 'X'",
/// "color format only with -ov, -or, -ox", "-I+ and -i+ options require some
/// value output". Warnings ("-oVW options require trace mode", ...) go to `warn`.
OutputSpec ParseOutputSpec(const RtraceOptions& options, const WarningSink& warn);


/// Collects output in memory and hands it to the stream in large writes; no
/// per-value iostream calls. Flush() pushes everything through and flushes the
/// stream (what Radiance's fflush(stdout) points are mapped to).
class RecordWriter {
public:
    /// `format`: 'a' ascii, 'f' float, 'd' double, 'c' RGBE.
    RecordWriter(char format, std::ostream& out);
    ~RecordWriter();
    RecordWriter(const RecordWriter&) = delete;
    RecordWriter& operator=(const RecordWriter&) = delete;

    /// The fields of `letters` for `r`, then "\n" in ascii format (printvals()).
    void WriteRecord(std::string_view letters, const RayResult& r);
    /// A ray-tree line: one TAB per r.depth, the fields, "\n" in ascii (ourtrace()).
    void WriteTraceRecord(std::string_view letters, const RayResult& r);
    void WriteText(std::string_view text);
    /// Hands buffered bytes to the stream and flushes it. Returns false when
    /// the stream reports an error.
    bool Flush();
    bool HasPending() const { return !buffer_.empty(); }

private:
    void WriteFields(std::string_view letters, const RayResult& r);
    void PutReals(std::span<const double> values);
    void PutRgb(const Rgb& c);
    void PutString(std::string_view s);
    void Drain();

    char format_;
    std::ostream& out_;
    std::string buffer_;
};

/// The information header rtrace writes with -h+ (§1.8): "#?RADIANCE",
/// the octree's own header lines (`sceneHeader`, copied as Radiance copies
/// them), `commandLine` (argv[0] and the options, not the scene files),
/// SOFTWARE=, CAPDATE= (local time) and GMT= of `now`, NCOMP=, BigEndian=
/// (f/d only), FORMAT=, and the empty line that ends it.
std::string FormatHeader(std::span<const std::string> commandLine, const OutputSpec& spec,
                         char outputFormat, std::time_t now,
                         std::span<const std::string> sceneHeader = {});

/// The picture resolution line "-Y <y> +X <x>\n".
std::string FormatResolution(int x, int y);

}  // namespace rt
