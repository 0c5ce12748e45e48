// SPDX-License-Identifier: MIT
//
// Radiance's font files and text layout (font.c: getfont, uniftext,
// squeeztext, proptext; text.c: gettext, intext, inglyph), as
// radiance-functions.md §11.10 describes them and real Radiance 5.4a
// behaves (tests/scene/font_test.cpp, tests/data/text/).
#include "scene/font.h"

#include <cmath>

#include "core/conventions.h"
#include "core/error.h"
#include "scene/fgetval.h"

namespace rt {
namespace {

/// getfont()'s limit on a glyph's vertices.
constexpr int kMaxGlyphVertices = 32000;

/// fgetval's 'i' reads: a word that is an integer, or why not.
enum class ReadResult { kValue, kEnd, kNotInteger };

ReadResult ReadInt(fgetval::Words& words, int& value) {
    std::string_view w;
    switch (words.Next(w)) {
        case fgetval::Words::Status::kEnd: return ReadResult::kEnd;
        case fgetval::Words::Status::kTooLong: return ReadResult::kNotInteger;
        case fgetval::Words::Status::kWord: break;
    }
    if (!fgetval::IsIntegerWord(w)) return ReadResult::kNotInteger;
    value = fgetval::Atoi(w);
    return ReadResult::kValue;
}

}  // namespace

Font ParseFont(std::string_view text, const std::string& path, const std::string& name) {
    fgetval::Words words(text);
    Font font;
    const auto fail = [&](const std::string& what) {
        ThrowUserError(FileLoc{path, words.line()}, what + " in font file \"" + name + "\"");
    };
    const auto failFor = [&](const char* what, int code) {
        fail(std::string(what) + " character (" + std::to_string(code) + ")");
    };
    unsigned widthSum = 0, heightSum = 0, counted = 0;
    for (;;) {
        int code = 0;
        const ReadResult r = ReadInt(words, code);
        if (r == ReadResult::kEnd) break;
        if (r == ReadResult::kNotInteger) fail("non-integer");
        if (code < 1 || code > 255) failFor("illegal", code);
        if (font.glyphs[static_cast<std::size_t>(code)]) failFor("duplicate", code);
        int vertices = 0;
        if (ReadInt(words, vertices) != ReadResult::kValue || vertices < 0 ||
            vertices > kMaxGlyphVertices) {
            failFor("bad # vertices for", code);
        }
        Glyph g;
        g.xy.resize(2 * static_cast<std::size_t>(vertices));
        for (std::size_t k = 0; k < g.xy.size(); ++k) {
            int v = 0;
            if (ReadInt(words, v) != ReadResult::kValue || v < 0 || v > 255) {
                failFor("bad vertex for", code);
            }
            g.xy[k] = static_cast<std::uint8_t>(v);
            // The extent starts at 128 (see Glyph).
            int& low = k % 2 == 0 ? g.left : g.bottom;
            int& high = k % 2 == 0 ? g.right : g.top;
            low = std::min(low, v);
            high = std::max(high, v);
        }
        if (g.right != g.left && g.top != g.bottom) {
            ++counted;
            widthSum += static_cast<unsigned>(g.right - g.left);
            heightSum += static_cast<unsigned>(g.top - g.bottom);
        }
        font.glyphs[static_cast<std::size_t>(code)] = std::move(g);
    }
    if (counted > 0) {
        font.meanWidth = static_cast<int>(widthSum / counted);
        font.meanHeight = static_cast<int>(heightSum / counted);
    }
    return font;
}

bool InGlyph(const Glyph& glyph, double x, double y) {
    // Callers keep 0 <= x, y <= 256, so the truncations are defined.
    const int xi = static_cast<int>(x), yi = static_cast<int>(y);
    if (glyph.left > xi || glyph.right <= xi || glyph.bottom > yi || glyph.top <= yi) return false;
    // The test line runs from the cell's centre, (2xi+1)/2, (2yi+1)/2, in
    // half units, so that no vertex lies on it.
    const int hx = 2 * xi + 1, hy = 2 * yi + 1;
    const int n = glyph.VertexCount();
    int crossings = 0;
    for (int k = 0, prev = n - 1; k < n; prev = k++) {
        const int x0 = glyph.xy[2 * prev], y0 = glyph.xy[2 * prev + 1];
        const int x1 = glyph.xy[2 * k], y1 = glyph.xy[2 * k + 1];
        if ((2 * y0 > hy) == (2 * y1 > hy)) continue;  // the edge does not cross the line
        const bool right0 = 2 * x0 > hx, right1 = 2 * x1 > hx;
        if (right0 && right1) {
            ++crossings;
        } else if (right0 || right1) {
            // Which side of the edge the point itself lies on, by the sign
            // of a cross product, read with the edge's direction.
            const bool upward = y1 > y0;
            const bool clockwise = (y0 - y) * (x1 - x) > (x0 - x) * (y1 - y);
            crossings += upward != clockwise ? 1 : 0;
        }
    }
    return crossings % 2 == 1;
}

TextLine UniformLine(std::string_view chars, const Font& font) {
    TextLine line;
    line.chars = std::string(chars);
    line.offsets.reserve(chars.size() + 1);
    line.offsets.push_back(0);
    for (const char c : chars) {
        const std::int64_t advance = font.Find(static_cast<unsigned char>(c)) ? 255 : 0;
        line.offsets.push_back(advance);
        line.width += advance;
    }
    return line;
}

TextLine SqueezedLine(std::string_view chars, const Font& font, int gap) {
    // Each character's entry is first its own start (left edge less half a
    // gap) and then, added to it, what the previous one still needs: its
    // right edge plus half a gap. Characters without glyph take nothing of
    // their own and pass the pending advance on.
    TextLine line;
    line.chars = std::string(chars);
    line.offsets.assign(chars.size() + 1, 0);
    const std::int64_t half = gap / 2;
    std::size_t k = 0;
    while (k < chars.size() && !font.Find(static_cast<unsigned char>(chars[k]))) ++k;
    std::int64_t pending = half;  // before the first glyph
    for (; k < chars.size(); ++k) {
        const Glyph* g = font.Find(static_cast<unsigned char>(chars[k]));
        if (g == nullptr) {
            line.offsets[k] = pending;
            line.width += pending;
            pending = 0;
        } else if (g->VertexCount() > 0) {
            line.offsets[k] = pending + half - g->left;
            line.width += line.offsets[k];
            pending = g->right + half;
        } else {  // a space
            line.offsets[k] = pending;
            line.width += pending;
            pending = font.meanWidth;
        }
    }
    line.offsets[chars.size()] = pending + half;
    line.width += pending + half;
    return line;
}

TextLine ProportionalLine(std::string_view chars, const Font& font, int gap) {
    // A glyph followed by this many spaces or more ends a run (proptext's
    // nsi, always 3 in text.c, which breaks when the glyph and its spaces
    // are more than nsi characters).
    constexpr std::size_t kIndentSpaces = 3;
    TextLine line = SqueezedLine(chars, font, gap);
    const auto glyph = [&](std::size_t k) {
        return k < chars.size() ? font.Find(static_cast<unsigned char>(chars[k])) : nullptr;
    };
    std::int64_t width = line.offsets[0];
    std::size_t start = 0;  // first character of the run
    while (start < chars.size()) {
        // The run: its characters' squeezed advances (`taken`) and how many
        // cells it should fill (`cells`: its glyphs and their spaces).
        std::int64_t taken = 0, cells = 0;
        std::size_t end = start, next = start;
        while (end < chars.size()) {
            next = end + 1;
            taken += line.offsets[end + 1];
            if (glyph(end)) {
                while (glyph(next) && glyph(next)->VertexCount() == 0) {
                    taken += line.offsets[next + 1];
                    ++next;
                }
                cells += static_cast<std::int64_t>(next - end);
            }
            if (next - end > kIndentSpaces) break;
            end = next;
        }
        const std::int64_t target = cells * (font.meanWidth + std::int64_t{gap});
        width += target;
        // Spread the difference over the run's entries, each taking its
        // share of what is left (integer division toward zero, as C's).
        std::int64_t adjust = target - taken;
        for (std::size_t k = start + 1; k <= next; ++k) {
            const std::int64_t share = adjust / static_cast<std::int64_t>(next + 1 - k);
            line.offsets[k] += share;
            adjust -= share;
        }
        start = next;
    }
    line.width = width;
    return line;
}

TextBlock::TextBlock(std::shared_ptr<const Font> font, const std::vector<std::string>& lines,
                     const Vec3& right, const Vec3& down, std::optional<double> spacing)
    : font_(std::move(font)) {
    // The dual basis of (right, down) in their plane: R⊥/|R⊥|² and D⊥/|D⊥|²,
    // R⊥ the part of `right` normal to `down` and D⊥ the reverse.
    if (!SpansPlane(right, down)) ThrowUserError("illegal motion vector");
    const Vec3 normal = Cross(down, right);
    right_ = Cross(normal, down);
    right_ *= Dot(down, down) / Dot(right_, right_);
    down_ = Cross(right, normal);
    down_ *= Dot(right, right) / Dot(down_, down_);
    // gettext(): the gap in font units, truncated toward zero.
    const double s = spacing.value_or(0.0);
    const double units = std::clamp(s * 255.0, -1e9, 1e9);
    const int gap = static_cast<int>(units);
    lines_.reserve(lines.size());
    for (const std::string& l : lines) {
        lines_.push_back(gap < 0   ? SqueezedLine(l, *font_, -gap)
                         : gap > 0 ? ProportionalLine(l, *font_, gap)
                                   : UniformLine(l, *font_));
    }
    // With a spacing argument, even 0, a cell is the mean width plus the gap
    // (intext()); without, 255.
    unitsPerCell_ = spacing ? font_->meanWidth + 255.0 * std::fabs(s) : 255.0;
}

bool TextBlock::SpansPlane(const Vec3& right, const Vec3& down) {
    const Vec3 r = Cross(Cross(down, right), down);
    // gettext()'s test, FTINY to the fourth: |R⊥|²·|D|⁴ must exceed it.
    return !(Dot(r, r) <= kFtiny * kFtiny * kFtiny * kFtiny);
}

bool TextBlock::Foreground(const Vec3& offset) const {
    const double x = Dot(offset, right_) * unitsPerCell_;
    const double y = Dot(offset, down_);
    // Negative or beyond any line (and NaN): background. The bound keeps
    // the truncations below defined; no line is that long.
    if (!(x >= 0.0 && y >= 0.0) || x >= 2e9 || y >= 2e9) return false;
    const auto line = static_cast<std::size_t>(y);
    if (line >= lines_.size()) return false;
    const TextLine& l = lines_[line];
    auto h = static_cast<std::int64_t>(x);
    if (h >= l.width) return false;
    const double fraction = x - h;
    // Glyph coordinates: 255 at the top of the line, 0 at its bottom.
    const double gy = (static_cast<double>(line) + 1.0 - y) * 255.0;
    for (std::size_t k = 0; k < l.offsets.size(); ++k) {
        h -= l.offsets[k];
        if (h < 0) break;
        if (h >= 255 || k >= l.chars.size()) continue;
        const Glyph* g = font_->Find(static_cast<unsigned char>(l.chars[k]));
        if (g != nullptr && InGlyph(*g, static_cast<double>(h) + fraction, gy)) return true;
    }
    return false;
}

std::vector<std::string> SplitTextLines(std::string_view text) {
    // fgets into 512 bytes: at most 511 characters a piece.
    constexpr std::size_t kPiece = 511;
    std::vector<std::string> lines;
    std::size_t pos = 0;
    while (pos < text.size()) {
        const std::size_t newline = text.find('\n', pos);
        const std::size_t end = newline == std::string_view::npos ? text.size() : newline + 1;
        const std::size_t take = std::min(end - pos, kPiece);
        std::string piece(text.substr(pos, take));
        if (!piece.empty() && piece.back() == '\n') piece.pop_back();
        lines.push_back(std::move(piece));
        pos += take;
    }
    return lines;
}

std::shared_ptr<const Font> FontCache::Get(const std::string& name) {
    for (const auto& [key, font] : fonts_) {
        if (key == name) return font;
    }
    const std::optional<cal::SourceText> file = cal::FindFunctionFile(name, path_);
    if (!file) {
        ThrowUserError("cannot find font file \"" + name + "\"");
    }
    auto font = std::make_shared<const Font>(ParseFont(file->text, file->name, name));
    fonts_.emplace_back(name, font);
    return font;
}

}  // namespace rt
