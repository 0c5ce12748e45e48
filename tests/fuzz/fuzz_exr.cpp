// SPDX-License-Identifier: MIT
//
// Fuzz target: arbitrary bytes as an OpenEXR file through ReadExrBytes, the
// reader imgcmp uses (through ReadImage) for EXR pictures: OpenEXR's header and
// pixel decoding, then lazyrad's channel mapping (R, G, B, a lone Y, layers).
// The reader gets a limit of 2^14 pixels here instead of the default 2^28, so
// that a legal but large picture stays within the fuzzer's memory; the limit's
// own check is in tests/image/exr_test.cpp. rt::Error is the expected way to
// reject input; any other exception, a crash, UB, a hang or memory out of
// proportion to the input is a finding.
#include <cstdlib>
#include <string_view>

#include "core/error.h"
#include "image/exr.h"
#include "tests/fuzz/fuzz_entry.h"

extern "C" int RT_FUZZ_ENTRY(const std::uint8_t* data, std::size_t size) {
    try {
        rt::ImageMetadata metadata;
        const rt::Image image =
            rt::ReadExrBytes(std::string_view(reinterpret_cast<const char*>(data), size),
                             "fuzz.exr", &metadata, 1LL << 14);
        // A picture accepted holds its declared pixels, in the colour and in
        // every layer.
        if (image.width <= 0 || image.height <= 0 || image.rgb.size() != 3 * image.PixelCount()) {
            std::abort();
        }
        for (const rt::ImageLayer& layer : image.layers) {
            if (layer.values.size() != image.PixelCount()) std::abort();
        }
    } catch (const rt::Error& e) {
        rt::fuzz::ExpectRefusal(e);
        // Rejected input: expected.
    }
    return 0;
}
