// SPDX-License-Identifier: MIT
//
// Fuzz target: arbitrary bytes as rvimage's command line. The bytes are split
// into words as an @file's are (SplitWords), "rvimage" put first, and parsed
// by ParseRvimageCommandLine (view, picture and layer options, the rest by
// rtrace's ParseCommandLine); a command line that asks for a picture is then
// planned as rvimage plans it (PlanPicture: the view set up, the resolution
// fitted to its aspect; the view's rays are fuzz_view's). Words are kept from
// naming files: a leading '@' becomes '-', and -vf becomes -vF (a view file's
// lines are fuzz_view's too). rt::Error is the expected way to refuse a
// command line; another exception, a crash, UB, a hang or a plan with no
// pixels is a finding.
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.h"
#include "program/arguments.h"
#include "rvimage/rvimage.h"
#include "tests/fuzz/fuzz_entry.h"

extern "C" int RT_FUZZ_ENTRY(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    std::vector<std::string> args{"rvimage"};
    for (std::string& word : rt::SplitWords(text)) {
        if (!word.empty() && word[0] == '@') word[0] = '-';
        if (word == "-vf") word = "-vF";
        args.push_back(std::move(word));
    }
    try {
        const rt::RvimageCommandLine cl =
            rt::ParseRvimageCommandLine(args, [](const std::string&) {});
        if (cl.rtrace.action != rt::CommandLine::Action::Render) return 0;
        const rt::PicturePlan plan = rt::PlanPicture(cl.settings);
        if (plan.width <= 0 || plan.height <= 0) std::abort();
    } catch (const rt::Error& e) {
        rt::fuzz::ExpectRefusal(e);
        // Refused command line: expected.
    }
    return 0;
}
