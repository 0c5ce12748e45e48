// SPDX-License-Identifier: MIT
//
// Fuzz target: arbitrary bytes as a Radiance picture (.hdr) through
// PictureFileAsData, colorpict's reader (ReadHdr, the header's PIXASPECT=,
// PictureAsData), then looked up at points inside, on the edge of and far
// outside the picture (NaN and infinities included). The reader gets a limit
// of 2^20 pixels here instead of colorpict's 2^28, so that a legal but large
// picture stays within the fuzzer's memory; the limit's own check is in
// tests/image/hdr_test.cpp. rt::Error is the expected way to reject input;
// any other exception, a crash, UB, a hang or memory out of proportion to the
// input is a finding.
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <string>

#include "core/error.h"
#include "scene/data_file.h"
#include "tests/fuzz/fuzz_entry.h"

extern "C" int RT_FUZZ_ENTRY(const std::uint8_t* data, std::size_t size) {
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    try {
        const auto channels = rt::PictureFileAsData(in, "fuzz.hdr", "fuzz.hdr", "", 1LL << 20);
        for (const auto& channel : channels) {
            // A picture accepted holds its declared pixels, in both axes.
            if (channel->dimensions() != 2) std::abort();
        }
        constexpr double kProbes[] = {0.0, 0.5, 1.0, -0.25, 7.5, 1e9, -1e30,
                                      std::numeric_limits<double>::infinity(),
                                      std::numeric_limits<double>::quiet_NaN()};
        for (std::size_t p = 0; p < std::size(kProbes); ++p) {
            const double point[2] = {kProbes[p], kProbes[(p + 3) % std::size(kProbes)]};
            for (const auto& channel : channels) static_cast<void>(channel->Value(point));
        }
    } catch (const rt::Error& e) {
        rt::fuzz::ExpectRefusal(e);
        // Rejected input: expected.
    }
    return 0;
}
