// SPDX-License-Identifier: MIT
//
// The shell rtrace and rvimage run in (Radiance's rtmain.c and rpmain.c around
// error.c): messages read "<prog>: <kind> - <text>", warnings obey -w, -e moves
// messages to a file after Radiance's banner, and failures become Radiance's
// exit codes (rterror.h: user 1, system 2, internal 3). State lives in the
// object, not in globals, so tests run programs in process.
//
//   ProgramShell shell("rvimage", err);
//   return shell.Run([&] {
//       CommandLine cl = ParseCommandLine(args, shell.Warn());
//       shell.SetWarnings(cl.options.warnings);
//       ...
//       return 0;
//   });
#pragma once

#include <fstream>
#include <ostream>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/diagnostics.h"
#include "core/function_ref.h"

namespace rt {

class ProgramShell {
public:
    /// `name` starts every message; `err` receives them until -e names a file.
    ProgramShell(std::string name, std::ostream& err);
    ProgramShell(const ProgramShell&) = delete;
    ProgramShell& operator=(const ProgramShell&) = delete;

    const std::string& Name() const { return name_; }
    void SetName(std::string name) { name_ = std::move(name); }

    /// Prints "<prog>: warning - <text>". Warnings given before SetWarnings()
    /// (while the command line is parsed, before -w is known) are held: printed
    /// by SetWarnings(true), dropped by SetWarnings(false), and printed before
    /// the message of a failure that comes first. The sink refers to this shell.
    const WarningSink& Warn() const { return warn_; }
    void SetWarnings(bool on);

    /// Radiance's -e: messages are appended to `path` from now on, after the
    /// banner "**************\n*** PID <pid>: <args, quoted>\n\n". An empty
    /// path keeps them where they are. False when the file cannot be opened;
    /// Radiance then quits with status 2 and prints nothing.
    [[nodiscard]] bool OpenErrorFile(const std::string& path, int pid,
                                     std::span<const std::string> args);

    /// Where messages go: the -e file once opened, otherwise `err`.
    std::ostream& Messages() { return *messages_; }
    /// Writes "<prog>: <text>\n" to Messages() and flushes it.
    void Say(std::string_view text);

    /// Runs `body` and returns its exit status. What it throws is reported as
    /// Radiance's error() reports it and becomes Radiance's exit code: an
    /// rt::Error as "fatal", "system" or "internal" by its kind (1, 2, 3),
    /// anything else as "internal" (3).
    int Run(FunctionRef<int()> body);

private:
    void Print(std::string_view kind, std::string_view text);

    std::string name_;
    std::ostream* messages_;
    std::ofstream errorFile_;
    bool warningsKnown_ = false;
    bool warningsOn_ = true;
    std::vector<std::string> heldWarnings_;  // given before SetWarnings()
    WarningSink warn_;
};

}  // namespace rt
