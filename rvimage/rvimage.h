// SPDX-License-Identifier: MIT
//
// rvimage's program flow: rtrace's options plus view and picture options in,
// a picture out (OpenEXR with optional layers and provenance metadata,
// Radiance RGBE, or a tone-mapped PNG; rvimage/picture.h). Runs in the same
// program shell as rtrace (program/shell.h).
//
//   RvimageCommandLine cl = ParseRvimageCommandLine(args, warn);  // throws rt::Error
//   return RunRvimage(args, std::cout, std::cerr, env, isatty(STDERR_FILENO));
#pragma once

#include <iosfwd>
#include <span>
#include <string>
#include <vector>

#include "core/diagnostics.h"
#include "rtrace/command_line.h"
#include "rtrace/ray_evaluator.h"
#include "rvimage/picture.h"
#include "view/view.h"

namespace rt {

struct RvimageCommandLine {
    PictureSettings settings;
    CommandLine rtrace;  // everything else, parsed by rtrace's ParseCommandLine
    /// The argument list after @file/$VAR expansion, argv[0] first (without
    /// its directory); the -e banner prints these.
    std::vector<std::string> args;
};

enum class OutputKind { Exr, Hdr, Png };

/// What rvimage renders for a parsed command line: the view set up, the
/// picture's resolution fitted to the view's aspect (-x, -y, -pa, as Radiance's
/// rpict fits them) and the output's kind by its name. Throws rt::Error (User)
/// for a bad view, a picture too small or an unknown output name.
struct PicturePlan {
    PreparedView view;
    int width = 0, height = 0;
    OutputKind kind = OutputKind::Exr;
};
[[nodiscard]] PicturePlan PlanPicture(const PictureSettings& settings);

/// Pulls the view options, -x -y -pa -pj -o -rscale and -layers out of `args`
/// (argv[0] first; @file and $VAR words are expanded first) and hands the
/// rest to ParseCommandLine. Throws rt::Error (User) for bad values or a
/// missing -o.
[[nodiscard]] RvimageCommandLine ParseRvimageCommandLine(std::span<const std::string> args,
                                                         const WarningSink& warn);

/// The whole program: parse, render, write. -defaults and -version print to
/// `out`. The progress bar goes to `err` only when `errIsTerminal`; otherwise
/// nothing is printed there but warnings, errors and (with -t N) a line every
/// N seconds plus the summary. Returns 0, or Radiance's exit codes 1 (user),
/// 2 (system), 3 (internal); messages read "rvimage: <kind> - <text>".
int RunRvimage(std::span<const std::string> args, std::ostream& out, std::ostream& err,
               const RunEnvironment& env, bool errIsTerminal);

}  // namespace rt
