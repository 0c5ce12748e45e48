// SPDX-License-Identifier: MIT
//
// Fuzz target: arbitrary bytes as a Radiance data file (.dat) through
// ParseDataFile, then interpolation at points inside, between and far outside
// the grid (including non-finite ones), as brightdata would look it up.
// rt::Error is the expected way to reject input; any other exception, a
// crash, UB, a hang or memory out of proportion to the input is a finding.
#include <cmath>
#include <limits>
#include <string>
#include <string_view>

#include "core/error.h"
#include "scene/data_file.h"
#include "tests/fuzz/fuzz_entry.h"

extern "C" int RT_FUZZ_ENTRY(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        const rt::DataArray array = rt::ParseDataFile(text, "fuzz.dat", "fuzz.dat");
        constexpr double kProbes[] = {0.0, 0.5, -1.5, 3.25, 1e9, -1e30,
                                      std::numeric_limits<double>::infinity(),
                                      std::numeric_limits<double>::quiet_NaN()};
        double point[rt::kMaxDataDimensions];
        for (std::size_t p = 0; p < std::size(kProbes); ++p) {
            for (int k = 0; k < array.dimensions(); ++k) {
                point[k] = kProbes[(p + static_cast<std::size_t>(k)) % std::size(kProbes)];
            }
            static_cast<void>(array.Value(std::span<const double>(
                point, static_cast<std::size_t>(array.dimensions()))));
        }
    } catch (const rt::Error& e) {
        rt::fuzz::ExpectRefusal(e);
        // Rejected input: expected.
    }
    return 0;
}
