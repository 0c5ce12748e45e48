// SPDX-License-Identifier: MIT
//
// Fuzz target: arbitrary bytes as a Radiance font file (.fnt) through
// ParseFont, then the bytes as text laid out with every kind of spacing
// (uniform, proportional, squeezed, with small and large gaps) and tested
// for ink at points on and around every line, as brighttext would. rt::Error
// is the expected way to reject input; any other exception, a crash, UB, a
// hang or memory out of proportion to the input is a finding.
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <string_view>

#include "core/error.h"
#include "scene/font.h"
#include "tests/fuzz/fuzz_entry.h"

extern "C" int RT_FUZZ_ENTRY(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    std::shared_ptr<const rt::Font> font;
    try {
        font = std::make_shared<const rt::Font>(rt::ParseFont(text, "fuzz.fnt", "fuzz.fnt"));
    } catch (const rt::Error& e) {
        rt::fuzz::ExpectRefusal(e);
        // Rejected input: expected. Lay the bytes out with a font of one
        // glyph all the same.
        font = std::make_shared<const rt::Font>(
            rt::ParseFont("65 3 0 0 255 0 128 255\n32 0\n", "a.fnt", "a.fnt"));
    }
    const std::vector<std::string> lines = rt::SplitTextLines(text.substr(0, 4096));
    constexpr double kSpacings[] = {0.0, 0.3, -0.2, 1e-3, -1e-3, 50.0, -50.0};
    for (const double spacing : kSpacings) {
        const rt::TextBlock block(font, lines, rt::Vec3(1, 0, 0), rt::Vec3(0.2, -1, 0),
                                  spacing == 0.0 ? std::optional<double>() : spacing);
        for (std::size_t l = 0; l < block.lines().size() && l < 64; ++l) {
            if (block.lines()[l].offsets.size() != block.lines()[l].chars.size() + 1) std::abort();
            for (int k = -2; k < 40; ++k) {
                const double x = 0.37 * k, y = static_cast<double>(l) + 0.01 * (k + 50);
                static_cast<void>(block.Foreground(rt::Vec3(x + 0.2 * y, -y, 0.3)));
            }
        }
        static_cast<void>(block.Foreground(rt::Vec3(std::numeric_limits<double>::quiet_NaN(), 0, 0)));
        static_cast<void>(block.Foreground(rt::Vec3(1e300, -1e300, 0)));
        static_cast<void>(block.Foreground(rt::Vec3(-1e-300, 0, 0)));
    }
    return 0;
}
