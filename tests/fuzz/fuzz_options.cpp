// SPDX-License-Identifier: MIT
//
// Fuzz target: arbitrary bytes as rtrace's command line. The bytes are split
// into words as an @file's are (SplitWords: white space, quotes), "rtrace"
// put first, and parsed by ParseCommandLine as rtrace does (the scene checked
// later); a command line it accepts is then printed as -defaults prints it.
// Words starting with '@' are kept from naming files (the '@' becomes '-'),
// so that the fuzzer reads none; $VAR words expand from the environment as
// in rtrace. rt::Error is the expected way to refuse a command line; another
// exception, a crash, UB or a hang is a finding.
#include <string>
#include <string_view>
#include <vector>

#include "core/error.h"
#include "program/arguments.h"
#include "rtrace/command_line.h"
#include "tests/fuzz/fuzz_entry.h"

extern "C" int RT_FUZZ_ENTRY(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    std::vector<std::string> args{"rtrace"};
    for (std::string& word : rt::SplitWords(text)) {
        if (!word.empty() && word[0] == '@') word[0] = '-';
        args.push_back(std::move(word));
    }
    try {
        const rt::CommandLine cl =
            rt::ParseCommandLine(args, [](const std::string&) {}, rt::SceneArgument::CheckedLater);
        static_cast<void>(rt::FormatDefaults(cl.options));
        static_cast<void>(rt::InfoText(cl));
    } catch (const rt::Error& e) {
        rt::fuzz::ExpectRefusal(e);
        // Refused command line: expected.
    }
    return 0;
}
