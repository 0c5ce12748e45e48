// SPDX-License-Identifier: MIT
//
// Fuzz target: rtrace's ray input. The first byte picks the format (a, f or d),
// the rest is the stream; reads until the end or rt::Error (BadRayError). Every
// returned ray must be finite (the reader rejects NaN/Inf).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>

#include "core/error.h"
#include "rtrace/ray_input.h"
#include "tests/fuzz/fuzz_entry.h"

namespace {

bool Finite(const rt::Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace

extern "C" int RT_FUZZ_ENTRY(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    static constexpr char kFormats[3] = {'a', 'f', 'd'};
    const char format = kFormats[data[0] % 3];
    const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
    std::istringstream in(text);
    try {
        rt::RayReader reader(in, format);
        for (std::size_t n = 0; n <= text.size(); ++n) {  // each record consumes input
            const std::optional<rt::InputRay> ray = reader.Next();
            if (!ray) return 0;
            if (!Finite(ray->origin) || !Finite(ray->direction)) {
                std::fprintf(stderr, "fuzz_rays: non-finite ray returned (format %c)\n", format);
                std::abort();
            }
        }
        std::fprintf(stderr, "fuzz_rays: more records than input bytes (format %c)\n", format);
        std::abort();
    } catch (const rt::Error& e) {
        rt::fuzz::ExpectRefusal(e);
        // Rejected input: expected.
    }
    return 0;
}
