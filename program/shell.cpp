// SPDX-License-Identifier: MIT
#include "program/shell.h"

#include <cstdio>
#include <exception>

#include "core/error.h"
#include "core/quote.h"
#include "program/signals.h"

namespace rt {

ProgramShell::ProgramShell(std::string name, std::ostream& err)
    : name_(std::move(name)), messages_(&err) {
    warn_ = [this](const std::string& text) {
        if (!warningsKnown_) {
            heldWarnings_.push_back(text);
        } else if (warningsOn_) {
            Print("warning - ", text);
        }
    };
}

void ProgramShell::SetWarnings(bool on) {
    warningsKnown_ = true;
    warningsOn_ = on;
    if (on)
        for (const std::string& text : heldWarnings_) Print("warning - ", text);
    heldWarnings_.clear();
}

bool ProgramShell::OpenErrorFile(const std::string& path, int pid,
                                 std::span<const std::string> args) {
    if (path.empty()) return true;
    errorFile_.open(path, std::ios::app);
    if (!errorFile_) return false;
    char pidText[32];
    std::snprintf(pidText, sizeof pidText, "%5d", pid);
    errorFile_ << "**************\n*** PID " << pidText << ": " << QuoteWords(args) << "\n\n";
    errorFile_.flush();
    messages_ = &errorFile_;
    ReportFatalSignalsTo(path);
    return true;
}

void ProgramShell::Say(std::string_view text) { Print("", text); }

void ProgramShell::Print(std::string_view kind, std::string_view text) {
    *messages_ << name_ << ": " << kind << text << '\n';
    messages_->flush();
}

int ProgramShell::Run(FunctionRef<int()> body) {
    auto fail = [this](std::string_view kind, std::string_view text) {
        if (!warningsKnown_) SetWarnings(true);  // held warnings come before the message
        Print(kind, text);
    };
    try {
        return body();
    } catch (const Error& e) {
        fail(e.kind() == Error::Kind::User     ? "fatal - "
             : e.kind() == Error::Kind::System ? "system - "
                                               : "internal - ",
             e.what());
        return e.ExitCode();
    } catch (const std::exception& e) {
        fail("internal - ", e.what());
        return 3;
    }
}

}  // namespace rt
