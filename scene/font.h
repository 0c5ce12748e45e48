// SPDX-License-Identifier: MIT
//
// Radiance's polygonal fonts and text layout, for the text patterns
// brighttext, colortext and mixtext (radiance-functions.md §11.10; Radiance's
// font.c and text.c): font files (`helvet.fnt` and the like, found on
// RAYPATH), the three ways of spacing a line, and whether a point of the
// text's plane falls inside a glyph.
//
//   const Font font = ParseFont(text, "/lib/ray/helvet.fnt", "helvet.fnt");
//   const TextBlock block(font, {"Exit"}, frame, spacing, hasSpacing);
//   bool ink = block.Foreground(p - anchor);
//
// Glyph coordinates are integers 0-255 with y up; a character cell is 255
// units wide and high. Everything here is integer arithmetic where Radiance's
// is, so that the layout, and hence which points are ink, is Radiance's to
// the unit. Fonts and blocks are immutable once built and shared read-only
// between threads.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cal/search.h"
#include "core/vecmath.h"

namespace rt {

/// One character's outline: a closed polygon (even-odd filled; holes are
/// joined to the outside by doubled edges). No vertices: a space.
struct Glyph {
    std::vector<std::uint8_t> xy;  // x0 y0 x1 y1 ..., each 0-255
    /// The outline's extent as Radiance keeps it: always including 128 (its
    /// starting value), so a glyph in the left half still reaches 128. Only
    /// a quick rejection test and the squeezed and proportional spacing use
    /// it, so its quirk shows in where characters are placed.
    int left = 128, right = 128, bottom = 128, top = 128;

    int VertexCount() const { return static_cast<int>(xy.size() / 2); }
};

struct Font {
    std::array<std::optional<Glyph>, 256> glyphs;  // by character code; 0 never set
    /// Mean extents over glyphs with both a width and a height (integer
    /// division, as Radiance's mwidth and mheight); 0 if there is none.
    int meanWidth = 0, meanHeight = 0;

    const Glyph* Find(unsigned char code) const {
        return glyphs[code] ? &*glyphs[code] : nullptr;
    }
};

/// Parses a font file's text: records `code nverts x1 y1 ... xn yn`, words
/// separated by white space, `#` to the end of the line a comment, code
/// 1-255, nverts 0-32000, coordinates 0-255. `path` (the file opened) and
/// the line start error messages, `name` (as the scene wrote it) is quoted
/// in them: "path:3: bad vertex for character (65) in font file \"name\"";
/// also "non-integer in font file", "illegal character (N)", "duplicate
/// character (N)", "bad # vertices for character (N)". Throws rt::Error
/// (User).
Font ParseFont(std::string_view text, const std::string& path, const std::string& name);

/// Whether the point (x, y) of a glyph's cell (font units, 0 <= x, y < 256)
/// is ink: inside the outline by the even-odd rule, the crossings counted
/// along +x from the point moved half a unit up and right of its integer
/// corner, except where an edge crosses that line beside the point, which is
/// decided at the point itself (Radiance's inglyph()).
bool InGlyph(const Glyph& glyph, double x, double y);

/// A line of text as laid out: where each character starts. offsets[0] is
/// the space before the first character, offsets[k] (k >= 1) the advance
/// from character k-1 to character k; the last entry, past the last
/// character, closes the line. So character k starts at offsets[0] + ... +
/// offsets[k], and width is the sum of all. Font units; 64-bit, as a long
/// line at a huge spacing overflows Radiance's short and int sums.
struct TextLine {
    std::string chars;
    std::vector<std::int64_t> offsets;  // chars.size() + 1 entries
    std::int64_t width = 0;
};

/// Every character with a glyph takes 255 units, others none.
TextLine UniformLine(std::string_view chars, const Font& font);
/// Each glyph from its left to its right edge, `gap` units apart (half
/// before the first and after the last); a space takes the font's mean
/// width; characters without glyph take nothing.
TextLine SqueezedLine(std::string_view chars, const Font& font, int gap);
/// Squeezed, then each run of characters spread so that it takes its
/// number of characters times (mean width + `gap`); a glyph followed by
/// three or more spaces ends a run, so indented columns line up.
TextLine ProportionalLine(std::string_view chars, const Font& font, int gap);

/// A text pattern's lines on its plane. The frame is the anchor (upper left
/// corner of the first character), the vector one character cell to the
/// right and the one one line down; the latter two need not be
/// orthogonal nor unit.
class TextBlock {
  public:
    /// `spacing` is the optional last real argument: 0 (or absent) uniform
    /// cells, > 0 proportional, < 0 squeezed, its magnitude times 255 the
    /// gap in font units. Throws rt::Error (User) "illegal motion vector"
    /// when the right and down vectors do not span a plane.
    TextBlock(std::shared_ptr<const Font> font, const std::vector<std::string>& lines,
              const Vec3& right, const Vec3& down, std::optional<double> spacing);

    /// Whether the point at `offset` from the anchor is ink (Radiance's
    /// intext()): its coordinates along the right and down vectors, measured
    /// in the basis they make (the part normal to both ignored), pick the
    /// line and the place in it.
    bool Foreground(const Vec3& offset) const;

    /// Whether `right` and `down` make a frame (Radiance's test: the part of
    /// `right` normal to `down`, times |down|², not vanishingly small).
    static bool SpansPlane(const Vec3& right, const Vec3& down);

    const std::vector<TextLine>& lines() const { return lines_; }

  private:
    std::shared_ptr<const Font> font_;
    std::vector<TextLine> lines_;
    Vec3 right_, down_;   // dual basis: Dot(offset, right_) is the cell coordinate
    double unitsPerCell_;  // font units per cell along the line
};

/// The lines of a text file as Radiance reads them (fgets into 512 bytes):
/// split at '\n', which is dropped, and longer lines cut into pieces of 511
/// bytes; a last line without '\n' counts.
std::vector<std::string> SplitTextLines(std::string_view text);

/// Fonts of one scene, each loaded once (keyed by the name as written) and
/// found on RAYPATH. Loading is not thread-safe; the fonts it hands out are
/// immutable.
class FontCache {
  public:
    explicit FontCache(cal::SearchPath path) : path_(std::move(path)) {}

    /// Throws rt::Error (User): `cannot find font file "name"`, or the parse
    /// errors of ParseFont.
    std::shared_ptr<const Font> Get(const std::string& name);

  private:
    cal::SearchPath path_;
    std::vector<std::pair<std::string, std::shared_ptr<const Font>>> fonts_;
};

}  // namespace rt
