// SPDX-License-Identifier: MIT
//
// Runs a shell command for end-to-end tests (the built programs in
// build/bin/) and returns its standard output and exit status.
#pragma once

#include <cstdio>
#include <string>
#include <sys/wait.h>

namespace rt::testing {

struct ShellResult {
    std::string out;
    int status = -1;  // exit status, or -1 if the command could not run
};

inline ShellResult RunShell(const std::string& command) {
    ShellResult r;
    FILE* p = popen(command.c_str(), "r");
    if (!p) return r;
    char buf[65536];
    size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, p)) > 0) r.out.append(buf, n);
    const int st = pclose(p);
    r.status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
    return r;
}

}  // namespace rt::testing
