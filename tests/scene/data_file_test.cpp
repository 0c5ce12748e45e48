// SPDX-License-Identifier: MIT
//
// Radiance data files and pictures as data (scene/data_file.h) against the
// values real Radiance 5.4a prints for the same look-ups
// (radiance-functions.md §11.14 items 2-8; whole scenes in
// tests/data/datafiles/), and the reader's handling of bad input.
#include "scene/data_file.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <fstream>
#include <limits>
#include <string>

#include <unistd.h>

#include "core/error.h"
#include "core/rgbe.h"
#include "image/image.h"

namespace rt {
namespace {

double At(const DataArray& d, std::initializer_list<double> p) {
    return d.Value(std::span<const double>(p.begin(), p.size()));
}

/// Radiance prints 7 significant digits.
void ExpectPrinted(double got, double radiance) {
    EXPECT_NEAR(got, radiance, 1e-6 * std::max(1.0, std::fabs(radiance)));
}

std::string ErrorOf(std::string_view text) {
    try {
        static_cast<void>(ParseDataFile(text, "dir/t.dat", "t.dat"));
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

TEST(DataFile, RegularOneDimension) {
    const DataArray d = ParseDataFile("1\n0 4 5\n10 20 30 40 80\n", "d1.dat", "d1.dat");
    ASSERT_EQ(d.dimensions(), 1);
    // Inside, on the ends, one division beyond them (linear), and further.
    const std::pair<double, double> cases[] = {
        {0, 10}, {0.5, 15}, {2.5, 35}, {4, 80}, {4.5, 100}, {5, 120}, {6, 30},
        {-0.5, 5}, {-1, 0}, {-1.0001, 0}, {-3, 0}};
    for (const auto& [x, want] : cases) {
        SCOPED_TRACE(x);
        ExpectPrinted(At(d, {x}), want);
    }
    // The upper discontinuity: 2*y1 - y0 at one division beyond, a third
    // of it just after (Radiance: 120, then 39.99866).
    EXPECT_DOUBLE_EQ(At(d, {5}), 120);
    EXPECT_NEAR(At(d, {5.0001}), 120 / 3.0001, 1e-9);
}

TEST(DataFile, IndexTruncatesTowardZeroAndHugeIndicesAsX86Does) {
    const DataArray d = ParseDataFile("1\n0 4 5\n10 20 30 40 80\n", "d1.dat", "d1.dat");
    EXPECT_DOUBLE_EQ(At(d, {-0.5}), 5);  // i = 0, linear below: not floor(-0.5) = -1
    // Beyond int range C's conversion gives INT_MIN on x86-64, clamped to
    // index 0: the decay uses the first two values, not the last two.
    EXPECT_DOUBLE_EQ(At(d, {1e12}), (2 * 20.0 - 10) / (1e12 + 1));
    EXPECT_TRUE(std::isnan(At(d, {std::numeric_limits<double>::quiet_NaN()})));
}

TEST(DataFile, TwoDimensions) {
    const DataArray d = ParseDataFile("2\n0 1 2\n0 2 3\n1 2 3\n4 5 6\n", "d.dat", "d.dat");
    ExpectPrinted(At(d, {0, 0}), 1);
    ExpectPrinted(At(d, {0.5, 1}), 3.5);
    ExpectPrinted(At(d, {1, 2}), 6);
    ExpectPrinted(At(d, {0.25, 0.5}), 2.25);
    ExpectPrinted(At(d, {2, 1}), 8);
    ExpectPrinted(At(d, {-1, 1}), -1);
}

TEST(DataFile, IrregularAxes) {
    const DataArray d =
        ParseDataFile("1\n0 0 4 0 1 3 10\n# comment\n0 10 20 30\n", "i.dat", "i.dat");
    const std::pair<double, double> cases[] = {{2, 15},  {6.5, 25}, {-1, -10}, {20, 11.66667},
                                               {10, 30}, {0, 0},    {0.5, 5}};
    for (const auto& [x, want] : cases) {
        SCOPED_TRACE(x);
        ExpectPrinted(At(d, {x}), want);
    }
    const DataArray low = ParseDataFile("1 0 4 5 50 40 30 20 10", "l.dat", "l.dat");
    ExpectPrinted(At(low, {-1}), 60);
    ExpectPrinted(At(low, {-2}), 30);
    ExpectPrinted(At(low, {-5}), 12);
}

TEST(DataFile, DescendingAxes) {
    const DataArray regular = ParseDataFile("1 10 0 5 0 10 20 30 40", "r.dat", "r.dat");
    ExpectPrinted(At(regular, {0}), 40);
    ExpectPrinted(At(regular, {2.5}), 30);
    ExpectPrinted(At(regular, {10}), 0);
    ExpectPrinted(At(regular, {-2.5}), 50);
    const DataArray irregular = ParseDataFile("1 0 0 4 3 1 0 -2 30 10 0 -20", "i.dat", "i.dat");
    const std::pair<double, double> cases[] = {{2, 20}, {0.5, 5},   {-1, -10}, {3, 30},
                                               {-2, -20}, {4, 40}, {-3, -30}};
    for (const auto& [x, want] : cases) {
        SCOPED_TRACE(x);
        ExpectPrinted(At(irregular, {x}), want);
    }
    // Equal neighbours pass Radiance's monotonicity test in a descending
    // run; between them the step is 0 and the value NaN, as Radiance's.
    const DataArray equal = ParseDataFile("1 0 0 3 3 3 2 3 7 8", "e.dat", "e.dat");
    ExpectPrinted(At(equal, {2.5}), 7.5);
    EXPECT_TRUE(std::isnan(At(equal, {3})));
}

TEST(DataFile, WordsAsFgetvalReadsThem) {
    // '#' starts a comment even inside a word; numbers in every float form
    // Radiance's isflt() accepts; CR, tab, form feed and vertical tab are
    // white space.
    const DataArray d =
        ParseDataFile("1 # dims\n+0 4.e0 05#points\n\t10 2.0e1 +30.\r\n.4e2\f8E1\v", "f.dat", "f.dat");
    ExpectPrinted(At(d, {4}), 80);
    EXPECT_EQ(ErrorOf("1\n0 4 2\n3 " + std::string(63, '7') + "\n"), "");
    EXPECT_NE(ErrorOf("1\n0 4 2\n3 " + std::string(64, '7') + "\n"), "");
}

TEST(DataFile, ErrorsNameTheFileLineAndRadiancePhrase) {
    EXPECT_EQ(ErrorOf("1\n0 0 4 0 2 1 3\n1 2 3 4\n"),
              "dir/t.dat:2: bad format in data file \"t.dat\": irregular coordinates not monotonic");
    EXPECT_EQ(ErrorOf("1\n0 4 1\n5\n"),
              "dir/t.dat:2: bad format in data file \"t.dat\": an axis needs at least 2 points");
    EXPECT_EQ(ErrorOf("6\n"),
              "dir/t.dat:1: bad number of dimensions for \"t.dat\" (6, must be 1 to 5)");
    EXPECT_EQ(ErrorOf("0\n"),
              "dir/t.dat:1: bad number of dimensions for \"t.dat\" (0, must be 1 to 5)");
    EXPECT_EQ(ErrorOf("1\n0 4 5\n1 2 3\n"), "dir/t.dat:3: unexpected EOF in data file \"t.dat\"");
    EXPECT_EQ(ErrorOf(""), "dir/t.dat:1: unexpected EOF in data file \"t.dat\"");
    EXPECT_EQ(ErrorOf("1\n0 4 5\n1 2 x 4 5\n"),
              "dir/t.dat:3: bad format in data file \"t.dat\": expected a number (data value), "
              "not \"x\"");
    EXPECT_EQ(ErrorOf("1\n0 4 5.0\n1 2\n"),
              "dir/t.dat:2: bad format in data file \"t.dat\": expected an integer (axis point "
              "count), not \"5.0\"");
    // A bad last word that runs into the end of the file is "unexpected
    // EOF" in Radiance (feof is set), and so here.
    EXPECT_EQ(ErrorOf("1\n0 4 5\n1 2 3 4 5x"), "dir/t.dat:3: unexpected EOF in data file \"t.dat\"");
    // '#' ends the word "3" and comments out the rest of the line.
    EXPECT_EQ(ErrorOf("1\n0 4 2\n3#x 7\n"), "dir/t.dat:3: unexpected EOF in data file \"t.dat\"");
    // Counts whose product overflows: Radiance runs out of memory (or worse,
    // its int product wraps); here the words run out first.
    EXPECT_EQ(ErrorOf("5\n0 1 99999\n0 1 99999\n0 1 99999\n0 1 99999\n0 1 99999\n1 2\n"),
              "dir/t.dat:7: unexpected EOF in data file \"t.dat\"");
    EXPECT_EQ(ErrorOf("2\n0 1 8888888888888888888\n0 1 -1\n"),
              "dir/t.dat:3: bad format in data file \"t.dat\": an axis needs at least 2 points");
}

TEST(DataFile, PictureIsBilinearBetweenPixelCentres) {
    // Spec item 8: 4x2, red = column + 1, green = 1 bottom row / 2 top row,
    // blue = 1, each as RGBE decodes it.
    Image image(4, 2);
    for (int x = 0; x < 4; ++x) {
        for (int y = 0; y < 2; ++y) {  // y = 0 is the top row
            image.Set(x, y, DecodeRgbe(EncodeRgbe(Rgb(x + 1, y == 0 ? 2 : 1, 1))));
        }
    }
    const auto rgb = PictureAsData(image, 1.0);
    // (u, v) -> arrays' (v, u). u in [0, 2], v in [0, 1].
    ExpectPrinted(At(*rgb[0], {0, 0}), 1.003906);
    ExpectPrinted(At(*rgb[0], {1, 2}), 4.015625);
    ExpectPrinted(At(*rgb[1], {1, 2}), 2.015625);
    ExpectPrinted(At(*rgb[0], {0, 2}), 4.015625);
    ExpectPrinted(At(*rgb[1], {0, 2}), 1.015625);
    ExpectPrinted(At(*rgb[0], {0, 3}), 1.435268);  // beyond one pixel step: harmonic decay
    ExpectPrinted(At(*rgb[1], {0, 3}), 0.2924107);
}

// A picture one pixel high: along v every coordinate, far ones included,
// reads the one row (Radiance's weights 0 and 1, no fall-off); along u it is
// interpolated as usual; a NaN coordinate on the one-pixel axis gives NaN.
// One pixel in all: that pixel everywhere. (Matched to real Radiance in
// tests/data/datafiles, "colorpict row", "column" and "pixel".)
TEST(DataFile, PicturesOnePixelHighOrWideAreConstantAlongThatAxis) {
    Image row(3, 1);
    for (int x = 0; x < 3; ++x) row.Set(x, 0, DecodeRgbe(EncodeRgbe(Rgb(x + 1, 1, 1))));
    const auto r = PictureAsData(row, 1.0);  // u in [0, 3], v in [0, 1]
    ASSERT_EQ(r[0]->axes()[0].count, 1);
    for (double v : {0.0, 0.5, 1.0, -7.0, 1e9}) {
        ExpectPrinted(At(*r[0], {v, 0}), 1.003906);
        ExpectPrinted(At(*r[0], {v, 1.5}), 2.007812);  // halfway between pixels 1 and 2
    }
    EXPECT_TRUE(std::isnan(At(*r[0], {std::numeric_limits<double>::quiet_NaN(), 1.0})));
    Image pixel(1, 1);
    pixel.Set(0, 0, DecodeRgbe(EncodeRgbe(Rgb(3, 2, 1))));
    const auto p = PictureAsData(pixel, 1.0);
    // Green 2 beside red 3 in one RGBE pixel: mantissa 128 at red's exponent.
    for (double u : {0.0, 0.7, -3.0, 50.0}) ExpectPrinted(At(*p[1], {0.25, u}), 2.007812);
}

TEST(DataFileCache, LoadsEachFileOnceAndSearchesThePath) {
    const std::string dir = ::testing::TempDir() + "datacache_" + std::to_string(getpid());
    ASSERT_EQ(std::system(("mkdir -p " + dir).c_str()), 0);
    std::ofstream(dir + "/c.dat") << "1 0 1 2 5 7\n";
    cal::SearchPath path;
    path.entries = {"/nonexistent", dir};
    DataFileCache cache(path);
    const auto a = cache.Data("c.dat", "s.rad:1: brightdata \"b\"");
    EXPECT_EQ(a, cache.Data("c.dat", "s.rad:9: brightdata \"c\""));
    ExpectPrinted(At(*a, {0.5}), 6);
    try {
        static_cast<void>(cache.Data("missing.dat", "s.rad:3: brightdata \"b\""));
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), Error::Kind::System);
        EXPECT_EQ(std::string(e.what()),
                  "s.rad:3: brightdata \"b\": cannot find data file \"missing.dat\"");
    }
    std::system(("rm -rf " + dir).c_str());
}

}  // namespace
}  // namespace rt
