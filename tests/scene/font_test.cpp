// SPDX-License-Identifier: MIT
//
// Font files and text layout (scene/font.h) against hand-worked values of
// Radiance's font.c and text.c rules; tests/data/text/ checks the whole
// patterns against real Radiance 5.4a.
#include "scene/font.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "core/error.h"

namespace rt {
namespace {

// 'I' a bar from x 100 to 155; '.' a square in the lower left quarter, whose
// extent Radiance stretches to 128; 'A' a triangle; a space.
constexpr const char* kFont =
    "# test font\n"
    "73 4 100 0 155 0 155 255 100 255   # I\n"
    "46 4  40 0  90 0  90  50  40  50   # .\n"
    "65 3 0 0 255 0 128 255\n"
    "32 0\n";

Font TestFont() { return ParseFont(kFont, "dir/t.fnt", "t.fnt"); }

std::string ErrorOf(const std::string& text) {
    try {
        ParseFont(text, "dir/t.fnt", "t.fnt");
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), Error::Kind::User);
        return e.what();
    }
    return "(no error)";
}

TEST(Font, GlyphsAndRadiancesExtents) {
    const Font f = TestFont();
    const Glyph* bar = f.Find('I');
    ASSERT_NE(bar, nullptr);
    EXPECT_EQ(bar->VertexCount(), 4);
    EXPECT_EQ(bar->xy[2], 155);
    EXPECT_EQ(bar->left, 100);
    EXPECT_EQ(bar->right, 155);
    EXPECT_EQ(bar->bottom, 0);
    EXPECT_EQ(bar->top, 255);
    // The extent always includes 128, Radiance's starting value.
    const Glyph* dot = f.Find('.');
    ASSERT_NE(dot, nullptr);
    EXPECT_EQ(dot->left, 40);
    EXPECT_EQ(dot->right, 128);
    EXPECT_EQ(dot->top, 128);
    ASSERT_NE(f.Find(' '), nullptr);
    EXPECT_EQ(f.Find(' ')->VertexCount(), 0);
    EXPECT_EQ(f.Find('x'), nullptr);
    // Means over the glyphs with a width and a height (not the space), in
    // integers: widths 55, 88, 255; heights 255, 128, 255.
    EXPECT_EQ(f.meanWidth, (55 + 88 + 255) / 3);
    EXPECT_EQ(f.meanHeight, (255 + 128 + 255) / 3);
}

TEST(Font, ErrorsNameTheFileLineAndRadiancePhrase) {
    EXPECT_EQ(ErrorOf("73 1 5 5\nabc 0\n"), "dir/t.fnt:2: non-integer in font file \"t.fnt\"");
    EXPECT_EQ(ErrorOf("0 0\n"), "dir/t.fnt:1: illegal character (0) in font file \"t.fnt\"");
    EXPECT_EQ(ErrorOf("256 0\n"), "dir/t.fnt:1: illegal character (256) in font file \"t.fnt\"");
    EXPECT_EQ(ErrorOf("65 0\n\n65 0\n"),
              "dir/t.fnt:3: duplicate character (65) in font file \"t.fnt\"");
    EXPECT_EQ(ErrorOf("65 -1\n"),
              "dir/t.fnt:1: bad # vertices for character (65) in font file \"t.fnt\"");
    EXPECT_EQ(ErrorOf("65 32001\n"),
              "dir/t.fnt:1: bad # vertices for character (65) in font file \"t.fnt\"");
    EXPECT_EQ(ErrorOf("65\n"),
              "dir/t.fnt:1: bad # vertices for character (65) in font file \"t.fnt\"");
    EXPECT_EQ(ErrorOf("65 2 1 2\n3 256\n"),
              "dir/t.fnt:2: bad vertex for character (65) in font file \"t.fnt\"");
    EXPECT_EQ(ErrorOf("65 2 1 2 3\n"),
              "dir/t.fnt:1: bad vertex for character (65) in font file \"t.fnt\"");
    EXPECT_EQ(ErrorOf("65 1 1.5 2\n"),
              "dir/t.fnt:1: bad vertex for character (65) in font file \"t.fnt\"");
    // A word of 64 characters or more is not read as a number (fgetval).
    EXPECT_EQ(ErrorOf(std::string(64, '1') + " 0\n"),
              "dir/t.fnt:1: non-integer in font file \"t.fnt\"");
    // '#' ends a word and comments out the rest of the line.
    EXPECT_EQ(ErrorOf("65 1 1#2 3\n2\n"), "(no error)");
    EXPECT_EQ(ErrorOf(""), "(no error)");
}

TEST(Font, InGlyphByEvenOddCrossings) {
    const Font f = TestFont();
    const Glyph& bar = *f.Find('I');
    EXPECT_TRUE(InGlyph(bar, 120, 100));
    EXPECT_FALSE(InGlyph(bar, 99.9, 100));
    EXPECT_TRUE(InGlyph(bar, 100.0, 100));   // the cell 100..101 is inside
    EXPECT_TRUE(InGlyph(bar, 154.99, 100));
    EXPECT_FALSE(InGlyph(bar, 155.0, 100));
    EXPECT_TRUE(InGlyph(bar, 120, 254.9));
    EXPECT_FALSE(InGlyph(bar, 120, 255.0));  // the top edge belongs to no cell inside
    // The dot's extent reaches 128, but not its outline.
    EXPECT_TRUE(InGlyph(*f.Find('.'), 60, 20));
    EXPECT_FALSE(InGlyph(*f.Find('.'), 100, 20));
    EXPECT_FALSE(InGlyph(*f.Find(' '), 100, 20));
    // The triangle's left edge runs from (0, 0) to (128, 255): at y = 100 it
    // is at x = 50.196. A point beside a slanted edge is decided at the point.
    const Glyph& a = *f.Find('A');
    EXPECT_FALSE(InGlyph(a, 50.0, 100));
    EXPECT_TRUE(InGlyph(a, 50.3, 100));
    EXPECT_TRUE(InGlyph(a, 128, 200));
    EXPECT_FALSE(InGlyph(a, 250, 200));
    // Its right edge, from (255, 0) to (128, 255): x = 205.2 at y = 100.
    EXPECT_TRUE(InGlyph(a, 205.0, 100));
    EXPECT_FALSE(InGlyph(a, 205.4, 100));
}

TEST(Font, HoleJoinedByADoubledEdge) {
    const Font f = ParseFont(
        "79 10 20 0 235 0 235 255 20 255 20 0 80 60 80 200 175 200 175 60 80 60\n", "o", "o");
    const Glyph& o = *f.Find('O');
    EXPECT_TRUE(InGlyph(o, 40, 128));    // the ring, left
    EXPECT_FALSE(InGlyph(o, 128, 128));  // the hole
    EXPECT_TRUE(InGlyph(o, 200, 128));   // the ring, right
    EXPECT_TRUE(InGlyph(o, 128, 30));    // below the hole, across the doubled edge's line
    EXPECT_TRUE(InGlyph(o, 60, 30));
}

TEST(Font, UniformLineGivesEachGlyphACell) {
    const TextLine l = UniformLine("I.x I", TestFont());
    EXPECT_EQ(l.offsets, (std::vector<std::int64_t>{0, 255, 255, 0, 255, 255}));
    EXPECT_EQ(l.width, 4 * 255);
}

TEST(Font, SqueezedLineFromEdgeToEdge) {
    // Gap 20 (half 10), mean width 132: I from 100 to 155, '.' from 40 to
    // its extent's 128, x none, the space the mean width.
    const Font f = TestFont();
    const TextLine l = SqueezedLine("I.x I", f, 20);
    const int w = f.meanWidth;
    EXPECT_EQ(l.offsets, (std::vector<std::int64_t>{10 + 10 - 100, 155 + 10 + 10 - 40, 128 + 10, 0,
                                           w + 10 - 100, 155 + 10 + 10}));
    std::int64_t sum = 0;
    for (const std::int64_t o : l.offsets) sum += o;
    EXPECT_EQ(l.width, sum);
    // Nothing but characters without glyph: the two half gaps.
    EXPECT_EQ(SqueezedLine("xyz", f, 21).offsets, (std::vector<std::int64_t>{0, 0, 0, 20}));
}

TEST(Font, ProportionalLineSpreadsEachRun) {
    const Font f = TestFont();
    ASSERT_EQ(f.meanWidth, 132);
    const int cell = f.meanWidth + 20;
    // One run of four cells (x takes none). Squeezed: -80, 135, 138, 0, 42,
    // 175; the entries after the first, 490 in all, must make 4 cells (608):
    // 118 spread over five entries, each taking what is left divided by the
    // entries left (C's division): 23, 23, 24, 24, 24.
    const TextLine l = ProportionalLine("I.x I", f, 20);
    EXPECT_EQ(l.offsets, (std::vector<std::int64_t>{-80, 158, 161, 24, 66, 199}));
    EXPECT_EQ(l.width, -80 + 4 * cell);
    // A glyph followed by three spaces ends a run: "I" and its spaces fill
    // four cells, the last "I" one.
    const TextLine two = ProportionalLine("I   I", f, 20);
    std::int64_t firstRun = 0;
    for (std::size_t k = 1; k <= 4; ++k) firstRun += two.offsets[k];
    EXPECT_EQ(firstRun, 4 * cell);
    EXPECT_EQ(two.offsets[5], cell);
    EXPECT_EQ(two.width, two.offsets[0] + 5 * cell);
    // With two spaces, one run of four cells, spread over all its entries.
    const TextLine one = ProportionalLine("I  I", f, 20);
    const TextLine squeezed = SqueezedLine("I  I", f, 20);
    std::int64_t all = 0;
    for (std::size_t k = 1; k < one.offsets.size(); ++k) all += one.offsets[k];
    EXPECT_EQ(all, 4 * cell);
    EXPECT_NE(one.offsets[4], cell);
    EXPECT_EQ(one.offsets[0], squeezed.offsets[0]);
}

TEST(Font, SplitTextLinesAsFgetsReadsThem) {
    EXPECT_EQ(SplitTextLines("ab\n\ncd"), (std::vector<std::string>{"ab", "", "cd"}));
    EXPECT_EQ(SplitTextLines("ab\n"), (std::vector<std::string>{"ab"}));
    EXPECT_TRUE(SplitTextLines("").empty());
    const std::vector<std::string> long_ = SplitTextLines(std::string(1030, 'a') + "\nb\n");
    ASSERT_EQ(long_.size(), 4u);
    EXPECT_EQ(long_[0].size(), 511u);
    EXPECT_EQ(long_[1].size(), 511u);
    EXPECT_EQ(long_[2].size(), 8u);
    EXPECT_EQ(long_[3], "b");
}

TEST(Font, TextBlockMeasuresInItsFrame) {
    auto font = std::make_shared<const Font>(TestFont());
    // Cells 2 wide along (1, 1, 0)/sqrt(2)·2, lines 0.5 high along a skewed
    // down vector; a part along the normal is ignored.
    const Vec3 right(std::sqrt(2.0), std::sqrt(2.0), 0), down(0.3, -0.5, 0);
    const TextBlock b(font, {"II", "A"}, right, down, std::nullopt);
    const Vec3 normal(0, 0, 1);
    const auto at = [&](double cell, double line) {
        return right * cell + down * line + normal * 0.7;
    };
    EXPECT_TRUE(b.Foreground(at(0.5, 0.5)));    // the first I's bar: x 127.5 of 255
    EXPECT_FALSE(b.Foreground(at(0.2, 0.5)));   // left of it
    EXPECT_TRUE(b.Foreground(at(1.5, 0.5)));    // the second I
    EXPECT_FALSE(b.Foreground(at(2.5, 0.5)));   // beyond the line
    EXPECT_TRUE(b.Foreground(at(0.5, 1.5)));    // the A, second line
    EXPECT_FALSE(b.Foreground(at(0.5, 2.5)));   // no third line
    EXPECT_FALSE(b.Foreground(at(-0.5, 0.5)));
    EXPECT_FALSE(b.Foreground(at(0.5, -0.5)));
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_FALSE(b.Foreground(Vec3(nan, 0, 0)));
    EXPECT_FALSE(b.Foreground(Vec3(1e300, 1e300, 0)));
    // A spacing argument, even 0, makes a cell the mean width (132 units)
    // instead of 255: the first I's bar (100-155) is at 0.76-1.17 cells.
    const TextBlock zero(font, {"II"}, right, down, 0.0);
    EXPECT_FALSE(zero.Foreground(at(0.5, 0.5)));
    EXPECT_TRUE(zero.Foreground(at(1.0, 0.5)));
}

TEST(Font, FrameMustSpanAPlane) {
    EXPECT_TRUE(TextBlock::SpansPlane(Vec3(1, 0, 0), Vec3(0, -1, 0)));
    EXPECT_FALSE(TextBlock::SpansPlane(Vec3(1, 0, 0), Vec3(2, 0, 0)));
    EXPECT_FALSE(TextBlock::SpansPlane(Vec3(0, 0, 0), Vec3(0, -1, 0)));
    EXPECT_FALSE(TextBlock::SpansPlane(Vec3(1, 0, 0), Vec3(0, 0, 0)));
    // FTINY⁴ on |R⊥|²·|D|⁴: 1e-8 and 1e-6 give 1e-40.
    EXPECT_FALSE(TextBlock::SpansPlane(Vec3(1e-8, 0, 0), Vec3(0, 1e-6, 0)));
    auto font = std::make_shared<const Font>(TestFont());
    EXPECT_THROW(TextBlock(font, {"I"}, Vec3(1, 0, 0), Vec3(1, 0, 0), std::nullopt), Error);
}

}  // namespace
}  // namespace rt
