// SPDX-License-Identifier: MIT
#include "program/signals.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <array>
#include <csignal>
#include <cstddef>
#include <cstring>

namespace rt {
namespace {

struct FatalSignal {
    int number;
    const char* what;  // Radiance's sigerr[] words (BSD's), not strsignal()'s
};

constexpr std::array<FatalSignal, 7> kFatalSignals{{
    {SIGHUP, "Hangup"},
    {SIGINT, "Interrupt"},
    {SIGTERM, "Terminate"},
    {SIGPIPE, "Broken pipe"},
    {SIGALRM, "Alarm clock"},
    {SIGXCPU, "Cputime limit exceeded"},
    {SIGXFSZ, "Filesize limit exceeded"},
}};

// Each message is made before any signal can come: the handler may only
// write(2) and _exit(2), which are async-signal-safe.
constexpr std::size_t kLineBytes = 256;
char g_lines[kFatalSignals.size()][kLineBytes];
std::size_t g_lengths[kFatalSignals.size()];
volatile std::sig_atomic_t g_caught = 0;
bool g_installed = false;
volatile std::sig_atomic_t g_fd = STDERR_FILENO;

extern "C" void OnFatalSignal(int number) {
    if (g_caught) _exit(number);  // two signals and we're gone (Radiance's words)
    g_caught = 1;
    for (std::size_t i = 0; i < kFatalSignals.size(); ++i) {
        if (kFatalSignals[i].number == number) {
            // Nothing is left to do if standard error is gone too.
            [[maybe_unused]] const ssize_t written = write(g_fd, g_lines[i], g_lengths[i]);
            break;
        }
    }
    _exit(3);
}

}  // namespace

void ReportFatalSignals(std::string_view program) {
    for (std::size_t i = 0; i < kFatalSignals.size(); ++i) {
        char* line = g_lines[i];
        std::size_t n = 0;
        const auto append = [&](std::string_view text) {
            const std::size_t room = kLineBytes - 1 - n;
            const std::size_t take = text.size() < room ? text.size() : room;
            std::memcpy(line + n, text.data(), take);
            n += take;
        };
        append(program);
        append(": signal - ");
        append(kFatalSignals[i].what);
        append("\n");
        g_lengths[i] = n;
        struct sigaction action = {};
        action.sa_handler = OnFatalSignal;
        sigemptyset(&action.sa_mask);
        sigaction(kFatalSignals[i].number, &action, nullptr);
    }
    g_installed = true;
}

void ReportFatalSignalsTo(const std::string& path) {
    if (!g_installed) return;
    const int fd = open(path.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
    if (fd >= 0) g_fd = fd;  // kept open to the end: the handler may need it any time
}

}  // namespace rt
