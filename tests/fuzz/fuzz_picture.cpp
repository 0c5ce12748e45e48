// SPDX-License-Identifier: MIT
//
// Fuzz target: arbitrary bytes as a Radiance picture (.hdr) through ReadHdr,
// then, as colorpict uses one, through PictureAsData at a pixel aspect the
// header's PIXASPECT= lines set, and looked up at points inside, on the edge
// of and far outside the picture (NaN and infinities included). ReadHdr gets
// a limit of 2^20 pixels here instead of its 2^28, so that a legal but large
// picture stays within the fuzzer's memory; the limit's own check is in
// tests/image/hdr_test.cpp. rt::Error is the expected way to reject input;
// any other exception, a crash, UB, a hang or memory out of proportion to the
// input is a finding.
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "core/error.h"
#include "image/hdr.h"
#include "scene/data_file.h"
#include "tests/fuzz/fuzz_entry.h"

extern "C" int RT_FUZZ_ENTRY(const std::uint8_t* data, std::size_t size) {
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    try {
        std::vector<std::string> header;
        const rt::Image image = rt::ReadHdr(in, "fuzz.hdr", &header, 1LL << 20);
        if (image.width <= 0 || image.height <= 0 ||
            image.rgb.size() != 3 * image.PixelCount()) {
            std::abort();  // a picture returned must have its size
        }
        double aspect = 1.0;
        for (const std::string& line : header) {
            if (line.rfind("PIXASPECT=", 0) == 0) aspect *= std::strtod(line.c_str() + 10, nullptr);
        }
        // DataFileCache::Picture refuses these before PictureAsData.
        if (!(aspect > 1e-6) || !std::isfinite(aspect)) aspect = 1.0;
        const auto channels = rt::PictureAsData(image, aspect);
        constexpr double kProbes[] = {0.0, 0.5, 1.0, -0.25, 7.5, 1e9, -1e30,
                                      std::numeric_limits<double>::infinity(),
                                      std::numeric_limits<double>::quiet_NaN()};
        for (std::size_t p = 0; p < std::size(kProbes); ++p) {
            const double point[2] = {kProbes[p], kProbes[(p + 3) % std::size(kProbes)]};
            for (const auto& channel : channels) static_cast<void>(channel->Value(point));
        }
    } catch (const rt::Error&) {
        // Rejected input: expected.
    }
    return 0;
}
