// SPDX-License-Identifier: MIT
#include "image/hdr.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <sstream>

#include "core/error.h"
#include "image/exr.h"

namespace rt {
namespace {

std::string Bytes(std::initializer_list<int> bytes) {
    std::string s;
    for (int b : bytes)
        s.push_back(static_cast<char>(b));
    return s;
}

Image Gradient(int w, int h) {
    Image img(w, h);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            // Runs (constant blocks) mixed with noise-like changes, over a wide range.
            const double base = (x / 5) % 2 ? 0.25 : std::pow(10.0, (x * 7 + y * 3) % 11 - 5);
            img.Set(x, y, Rgb(base, base * 0.5 * (1 + y % 3), base * 0.125));
        }
    }
    img.Set(0, 0, Rgb());  // black
    return img;
}

void ExpectWithinRgbePrecision(const Image& a, const Image& b) {
    ASSERT_EQ(a.width, b.width);
    ASSERT_EQ(a.height, b.height);
    for (int y = 0; y < a.height; ++y) {
        for (int x = 0; x < a.width; ++x) {
            const Rgb p = a.Get(x, y), q = b.Get(x, y);
            const double mx = Intens(p);
            for (int c = 0; c < 3; ++c) {
                // 8-bit mantissa against the largest channel: error ≤ one step of 2^-8·2^e.
                EXPECT_LE(std::fabs(p[c] - q[c]), mx / 128.0 + 1e-30) << x << "," << y << " c" << c;
            }
        }
    }
}

TEST(Rgbe, EncodesLikeRadianceSetcolr) {
    EXPECT_EQ(EncodeRgbe(Rgb(0.3, 0.4, 0.5)), (Rgbe{0x4C, 0x66, 0x80, 0x80}));
    EXPECT_EQ(EncodeRgbe(Rgb::Grey(0.529138)), (Rgbe{135, 135, 135, 128}));
    EXPECT_EQ(EncodeRgbe(Rgb()), (Rgbe{0, 0, 0, 0}));
    EXPECT_EQ(EncodeRgbe(Rgb::Grey(1e-33)), (Rgbe{0, 0, 0, 0}));
    EXPECT_EQ(EncodeRgbe(Rgb(-1, 1, 0)), (Rgbe{0, 128, 0, 129}));
    EXPECT_NEAR(DecodeRgbe({135, 135, 135, 128}).r, 0.529297, 1e-6);
    EXPECT_EQ(DecodeRgbe({10, 20, 30, 0}), Rgb());
    EXPECT_EQ(DecodeRgbe({128, 0, 0, 129}).r, 128.5 / 128.0);
}

TEST(Hdr, RoundTripKeepsHeaderLinesAndRgbePrecision) {
    const Image img = Gradient(37, 9);
    const std::vector<std::string> header = {"rtrace -ffc -x 37 -y 9 scene.rad",
                                             "SOFTWARE= lazyrad 0.1.0", "VIEW= -vtv -vh 40"};
    for (HdrEncoding enc : {HdrEncoding::RunLength, HdrEncoding::Flat}) {
        std::stringstream buf;
        WriteHdr(buf, img, header, enc);
        const std::string bytes = buf.str();
        EXPECT_EQ(bytes.rfind("#?RADIANCE\nrtrace -ffc", 0), 0u);
        EXPECT_NE(bytes.find("\nFORMAT=32-bit_rle_rgbe\n\n-Y 9 +X 37\n"), std::string::npos);
        if (enc == HdrEncoding::Flat) {
            EXPECT_EQ(bytes.size() - bytes.find("+X 37\n") - 6, 37u * 9u * 4u);
        }
        std::vector<std::string> readHeader;
        const Image back = ReadHdr(buf, "buf", &readHeader);
        EXPECT_EQ(readHeader, header);
        ExpectWithinRgbePrecision(img, back);
        // Reading then writing again is exact: values already lie on the RGBE grid.
        std::stringstream again;
        WriteHdr(again, back, header, enc);
        EXPECT_EQ(again.str(), bytes);
    }
}

TEST(Hdr, RunLengthShrinksConstantPicturesAndMatchesFlat) {
    Image img(100, 4);
    for (int y = 0; y < 4; ++y) {
        for (int x = 0; x < 100; ++x)
            img.Set(x, y, Rgb(0.5, 0.25, 0.125));
    }
    std::stringstream rle, flat;
    WriteHdr(rle, img, {}, HdrEncoding::RunLength);
    WriteHdr(flat, img, {}, HdrEncoding::Flat);
    EXPECT_LT(rle.str().size(), flat.str().size() / 10);
    EXPECT_EQ(ReadHdr(rle, "rle"), ReadHdr(flat, "flat"));
}

TEST(Hdr, DecodesHandMadeRunLengthScanline) {
    // Width 8: each component is one literal of 2 bytes then a run of 6, or
    // a run of 8; exponent is a literal of 8 bytes.
    std::string pic = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 8\n";
    pic += Bytes({2, 2, 0, 8});
    pic += Bytes({2, 10, 20, 128 + 6, 30});                     // red: 10 20 30 30 30 30 30 30
    pic += Bytes({128 + 8, 64});                                // green: 64 × 8
    pic += Bytes({128 + 4, 0, 4, 1, 2, 3, 4});                  // blue: 0 0 0 0 1 2 3 4
    pic += Bytes({8, 129, 129, 129, 129, 129, 129, 129, 130});  // exponents
    std::istringstream in(pic);
    const Image img = ReadHdr(in, "hand.hdr");
    ASSERT_EQ(img.width, 8);
    ASSERT_EQ(img.height, 1);
    EXPECT_EQ(img.Get(0, 0), DecodeRgbe({10, 64, 0, 129}));
    EXPECT_EQ(img.Get(1, 0), DecodeRgbe({20, 64, 0, 129}));
    EXPECT_EQ(img.Get(5, 0), DecodeRgbe({30, 64, 2, 129}));
    EXPECT_EQ(img.Get(7, 0), DecodeRgbe({30, 64, 4, 130}));
}

TEST(Hdr, DecodesOldStyleRepeatsAndOtherOrientations) {
    // Old-style run: pixel, then (1,1,1,3) repeats it three times.
    std::string pic = "#?RADIANCE\n\n-Y 1 +X 4\n";
    pic += Bytes({100, 50, 25, 129, 1, 1, 1, 3});
    std::istringstream in(pic);
    const Image img = ReadHdr(in, "old.hdr");
    for (int x = 0; x < 4; ++x)
        EXPECT_EQ(img.Get(x, 0), DecodeRgbe({100, 50, 25, 129}));

    // "+Y 2 +X 1": bottom scanline first.
    std::string up = "#?RADIANCE\n\n+Y 2 +X 1\n" + Bytes({128, 0, 0, 129, 0, 128, 0, 129});
    std::istringstream upIn(up);
    const Image flipped = ReadHdr(upIn, "up.hdr");
    EXPECT_GT(flipped.Get(0, 1).r, 0.5);  // first scan is the bottom row
    EXPECT_GT(flipped.Get(0, 0).g, 0.5);
}

TEST(Hdr, ErrorsNameTheInput) {
    auto message = [](const std::string& text) -> std::string {
        std::istringstream in(text);
        try {
            (void)ReadHdr(in, "bad.hdr");
        } catch (const Error& e) {
            return e.what();
        }
        return "";
    };
    EXPECT_NE(message("P6\n").find("bad.hdr"), std::string::npos);
    EXPECT_NE(message("#?RADIANCE\nFORMAT=32-bit_rle_xyze\n\n").find("xyze"), std::string::npos);
    EXPECT_NE(message("#?RADIANCE\n\n-Y 2 +X 2\n").find("end of file"), std::string::npos);
    EXPECT_NE(message("#?RADIANCE\n\nbogus\n").find("resolution"), std::string::npos);
    // Run longer than the scanline.
    std::string overrun = "#?RADIANCE\n\n-Y 1 +X 8\n" + Bytes({2, 2, 0, 8, 128 + 9, 1});
    EXPECT_NE(message(overrun).find("overruns"), std::string::npos);
    try {
        (void)ReadHdr(std::string("/nonexistent/x.hdr"));
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("/nonexistent/x.hdr"), std::string::npos);
    }
}

// A picture's size is checked against the limit before any pixel is read,
// and a short file that declares a large picture stops at its end: memory
// follows the data, not the header (the fuzzer's rule).
TEST(Hdr, RefusesPicturesAboveThePixelLimitBeforeReadingThem) {
    auto message = [](const std::string& text, long long limit) -> std::string {
        std::istringstream in(text);
        try {
            (void)ReadHdr(in, "big.hdr", nullptr, limit);
        } catch (const Error& e) {
            return e.what();
        }
        return "";
    };
    const std::string twoByThree =
        "#?RADIANCE\n\n-Y 2 +X 3\n" + Bytes({1, 2, 3, 128, 1, 2, 3, 128, 1, 2, 3, 128,
                                                4, 5, 6, 128, 4, 5, 6, 128, 4, 5, 6, 128});
    EXPECT_EQ(message(twoByThree, 6), "");
    EXPECT_EQ(message(twoByThree, 5),
              "big.hdr: byte 22: bad Radiance picture: 3 x 2 pixels, more than the 5 lazyrad "
              "reads");
    // The default limit: 2^20 x 2^20 in a 30-byte file.
    EXPECT_EQ(message("#?RADIANCE\n\n-Y 1048576 +X 1048576\n", kMaxPicturePixels),
              "big.hdr: byte 34: bad Radiance picture: 1048576 x 1048576 pixels, more than the "
              "268435456 lazyrad reads");
    EXPECT_NE(message("#?RADIANCE\n\n-Y 16384 +X 16384\n", kMaxPicturePixels)
                  .find("unexpected end of file"),
              std::string::npos);
}

TEST(Hdr, FileRoundTripAndReadImageDispatch) {
    const std::string path = (std::filesystem::temp_directory_path() /
                              ("lazyrad_hdr_" + std::to_string(::getpid()) + ".hdr"))
                                 .string();
    const Image img = Gradient(16, 3);
    WriteHdr(path, img, {"test"});
    std::vector<std::string> header;
    const Image back = ReadHdr(path, &header);
    EXPECT_EQ(header, std::vector<std::string>{"test"});
    EXPECT_EQ(ReadImage(path), back);
    std::filesystem::remove(path);
}

}  // namespace
}  // namespace rt
