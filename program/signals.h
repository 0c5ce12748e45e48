// SPDX-License-Identifier: MIT
//
// Fatal signals as Radiance's rtmain.c onsig() reports them: a hang-up,
// interrupt, termination, broken pipe, alarm or CPU/file-size limit prints
// "<prog>: signal - <what>" on standard error (or the -e file) and ends the
// program with exit status 3 (Radiance's quit(3)); a second signal during
// that ends it at once.
// For the programs' main() only: it changes the whole process's handling, so
// tests that run a program in process do not call it.
#pragma once

#include <string>
#include <string_view>

namespace rt {

/// Installs the handlers; `program` starts each message (rt::ProgramName()).
void ReportFatalSignals(std::string_view program);

/// Sends the messages to the end of file `path` instead of standard error,
/// as Radiance's do after `-e path`. Does nothing when ReportFatalSignals()
/// has not run (as in a test's process) or the file cannot be opened.
void ReportFatalSignalsTo(const std::string& path);

}  // namespace rt
