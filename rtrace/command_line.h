// SPDX-License-Identifier: MIT
//
// rtrace's command line (radiance-notes.md §1.1-1.3): RtraceOptions and every
// option Radiance 5.4a's rtrace accepts, parsed from one table with one row
// per flag, with Radiance's value validation, boolean toggles, `@file`/`$VAR`
// expansion and the exact `-defaults` text, both from the same table.
// rvimage takes the same options. Replaces rtmain.c's option loop,
// renderopts.c and pmapopt.c.
//
//   CommandLine cl = ParseCommandLine(args, warn);   // throws rt::Error
//   if (std::optional<std::string> text = InfoText(cl)) out << *text;  // -version, -defaults
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "ambient/ambient_options.h"
#include "core/diagnostics.h"
#include "shading/shading_options.h"

namespace rt {

inline constexpr std::string_view kLazyradVersion = "lazyrad 0.1.0";
/// What -version prints and the header's SOFTWARE= line carries.
inline constexpr std::string_view kVersionString = "lazyrad 0.1.0 (RADIANCE 5.4a compatible)";

/// -ap file [minGather [maxGather]]: parsed only (photon maps are out of scope).
struct PhotonMapOption {
    std::string file;
    int minGather = 0;
    int maxGather = 0;
};

struct RtraceOptions {
    ShadingOptions shading;
    AmbientOptions ambient;

    std::string outputSpec = "v";  // -o<spec>, validated later by ParseOutputSpec
    char inputFormat = 'a';        // -f<in>: a, f or d
    char outputFormat = 'a';       // -f<in><out>: a, f, d or c
    int xResolution = 0;           // -x: flush interval, or picture width with -y
    int yResolution = 0;           // -y: number of records (scan lines with -x) to read
    bool limitDistance = false;    // -ld: ray length limited to |input direction|
    bool header = true;            // -h
    bool warnings = true;          // -w
    bool irradianceAtHit = false;  // -i (Radiance's do_irrad); read shading.irradiance
    bool immediateIrradiance = false;  // -I (Radiance's imm_irrad); read shading.irradiance
    std::string errorFile;         // -e: append messages here; empty = stderr
    int processes = 1;             // -n as given (-defaults shows it); see RenderThreads
    int reportSeconds = 0;         // -t: progress interval (lazyrad extension, as rpict's -t)
    int seed = 0;                  // -seed: random seed (lazyrad extension; Radiance uses the
                                   // clock); read shading.seed

    /// -ti/-tI (include) or -te/-tE (exclude) modifier names for trace output;
    /// the first use of the other kind restarts the list (Radiance's rule).
    std::vector<std::string> traceModifiers;
    bool traceListSet = false;
    bool traceListIsInclude = false;

    std::string persistFile;       // -P / -PP
    bool persistParallel = false;  // -PP
    std::vector<PhotonMapOption> photonMaps;  // -ap
    double photonMaxRadius = 0.0;  // -am
};

/// Threads -n runs: Radiance accepts any positive count and prints it, but
/// forks at most 64 processes; lazyrad runs at most as many threads.
inline constexpr int kMaxRenderThreads = 64;
inline int RenderThreads(const RtraceOptions& o) {
    return o.processes < 1 ? 1 : (o.processes > kMaxRenderThreads ? kMaxRenderThreads : o.processes);
}

enum class ValueKind {
    Toggle,    // -h, -h+, -h- ...: bare toggles, suffix in "+1yYtT" sets, "-0nNfF" clears
    Int,       // one argument: optional sign and digits
    Real,      // one argument: C-like float literal
    Rgb,       // three Real arguments
    Word,      // one printable argument
    Attached,  // the value is the rest of the same word (-o<spec>, -f<in><out>)
    Custom,    // variable arity (-ap)
};

/// One row of the option table. The table drives parsing, -defaults, the
/// tests and the README option list.
struct OptionInfo {
    std::string_view name;      // e.g. "-ab"
    ValueKind kind;
    std::string_view help;      // one line
    std::string_view status;    // "yes", or why the option has no effect yet
};

/// Every option in table order (the special words -defaults, -help and
/// -version are handled before the table and are not listed).
std::span<const OptionInfo> OptionTable();

struct CommandLine {
    enum class Action { Render, PrintDefaults, PrintVersion };
    Action action = Action::Render;
    RtraceOptions options;
    /// The argument list after @file/$VAR expansion, argv[0] first; the
    /// header and the -e banner print these.
    std::vector<std::string> args;
    /// Index in `args` of the first scene file (args.size() when none).
    std::size_t firstScene = 0;
    std::vector<std::string> sceneFiles;
};

/// Whether ParseCommandLine() itself stops on a command line with no scene,
/// or leaves that to RequireScene() (rtrace, which opens its -e file first,
/// as Radiance does, so that the message lands there).
enum class SceneArgument { Required, CheckedLater };

/// Parses `args` (argv[0] first) the way rtrace does, and derives
/// options.shading.irradiance (from -i and -I) and options.shading.seed (from
/// -seed). Warnings emitted while parsing (-ap without bandwidth) go to
/// `warn`. Throws rt::Error: User "command line error at '<arg>'", "missing
/// octree argument" (unless `scene` says later), ... (exit 1); System "cannot
/// expand '<arg>'" (exit 2).
CommandLine ParseCommandLine(std::span<const std::string> args, const WarningSink& warn,
                             SceneArgument scene = SceneArgument::Required);

/// Radiance's "missing octree argument" (User) when `cl` names no scene.
void RequireScene(const CommandLine& cl);

/// Radiance's `rtrace -defaults` text for `options` (tabs included).
std::string FormatDefaults(const RtraceOptions& options);

/// What -version or -defaults (-help) print, which rtrace and rvimage answer
/// alike; std::nullopt when `cl` asks for a rendering.
std::optional<std::string> InfoText(const CommandLine& cl);

/// Radiance's name of a -f format letter, as the header's FORMAT= line and
/// -defaults print it: a "ascii", f "float", d "double", c "32-bit_rle_rgbe".
std::string_view FormatName(char format);

}  // namespace rt
