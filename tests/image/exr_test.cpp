// SPDX-License-Identifier: MIT
#include "image/exr.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfMultiPartOutputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfOutputPart.h>
#include <OpenEXR/ImfPartType.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfTiledOutputFile.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>

#include "core/error.h"

namespace rt {
namespace {

std::string TempPath(const std::string& name) {
    return (std::filesystem::temp_directory_path() /
            ("lazyrad_image_" + std::to_string(::getpid()) + "_" + name))
        .string();
}

Image TestPattern(int w, int h) {
    Image img(w, h);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            img.Set(x, y, Rgb(x + 0.1 * y, 1e-30 * (x + 1), 3.0e7 / (y + 1)));
        }
    }
    // Values that are easy to lose: denormals, negatives, the largest float.
    img.rgb[0] = std::numeric_limits<float>::denorm_min();
    img.rgb[1] = -2.5f;
    img.rgb[2] = std::numeric_limits<float>::max();
    img.rgb[4] = 0.1f;
    return img;
}

TEST(Exr, RoundTripIsBitExactWithLayersAndMetadata) {
    Image img = TestPattern(7, 5);
    ImageLayer& z = img.AddLayer("Z");
    for (std::size_t i = 0; i < z.values.size(); ++i)
        z.values[i] = 0.5f * static_cast<float>(i);
    const ImageMetadata meta = {{"commandLine", "rtrace -ab 2 -x 7 -y 5 scene.rad"},
                                {"software", "lazyrad 0.1.0"}};
    const std::string path = TempPath("roundtrip.exr");
    WriteExr(path, img, meta);
    EXPECT_TRUE(IsExrFile(path));

    ImageMetadata readMeta;
    const Image back = ReadExr(path, &readMeta);
    ASSERT_EQ(back.width, 7);
    ASSERT_EQ(back.height, 5);
    ASSERT_EQ(back.rgb.size(), img.rgb.size());
    EXPECT_EQ(std::memcmp(back.rgb.data(), img.rgb.data(), img.rgb.size() * sizeof(float)), 0);
    ASSERT_EQ(back.layers.size(), 1u);
    EXPECT_EQ(back.layers[0], img.layers[0]);
    EXPECT_EQ(back, img);
    for (const auto& entry : meta) {
        EXPECT_NE(std::find(readMeta.begin(), readMeta.end(), entry), readMeta.end())
            << entry.first;
    }
    std::filesystem::remove(path);
}

TEST(Exr, MetadataIsVisibleToOpenExrItself) {
    const std::string path = TempPath("meta.exr");
    WriteExr(path, Image(4, 3), {{"software", "lazyrad test"}});
    Imf::InputFile file(path.c_str());
    const auto* attr = file.header().findTypedAttribute<Imf::StringAttribute>("software");
    ASSERT_NE(attr, nullptr);
    EXPECT_EQ(attr->value(), "lazyrad test");
    EXPECT_NE(file.header().channels().findChannel("R"), nullptr);
    EXPECT_EQ(file.header().channels().findChannel("R")->type, Imf::FLOAT);
    EXPECT_EQ(file.header().dataWindow().max.x, 3);
    EXPECT_EQ(file.header().dataWindow().max.y, 2);
    std::filesystem::remove(path);
}

TEST(Exr, ErrorsNameTheFile) {
    try {
        (void)ReadExr("/nonexistent/dir/missing.exr");
        FAIL() << "no exception";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("missing.exr"), std::string::npos) << e.what();
    }
    try {
        WriteExr("/nonexistent/dir/out.exr", Image(2, 2));
        FAIL() << "no exception";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("out.exr"), std::string::npos) << e.what();
    }
    EXPECT_THROW(WriteExr(TempPath("x.exr"), Image(2, 2), {{"channels", "x"}}), Error);
    EXPECT_THROW(WriteExr(TempPath("y.exr"), Image(0, 0)), Error);
}


std::string FileBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// What ReadExrBytes says of `bytes` with at most `maxPixels` pixels ("" if it reads them).
std::string ExrMessage(const std::string& bytes, long long maxPixels) {
    try {
        (void)ReadExrBytes(bytes, "big.exr", nullptr, maxPixels);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

/// Where the offset table of a one-chunk scanline file starts: its one entry is
/// the byte just after it (0 if not found). The header's closing null is the
/// byte before.
std::size_t OffsetTable(const std::string& bytes) {
    for (std::size_t p = 0; p + 8 <= bytes.size(); ++p) {
        std::uint64_t v;
        std::memcpy(&v, &bytes[p], 8);
        if (v == p + 8) return p;
    }
    return 0;
}

TEST(Exr, BytesInMemoryReadAsTheFile) {
    Image img = TestPattern(6, 4);
    img.AddLayer("Z").values.assign(img.PixelCount(), 2.5f);
    const std::string path = TempPath("bytes.exr");
    WriteExr(path, img, {{"software", "lazyrad test"}});
    ImageMetadata fromFile, fromBytes;
    const Image file = ReadExr(path, &fromFile);
    const std::string bytes = FileBytes(path);
    EXPECT_EQ(ReadExrBytes(bytes, "bytes.exr", &fromBytes), file);
    EXPECT_EQ(fromBytes, fromFile);
    // Cut short anywhere, the bytes are refused with a message, not read past.
    for (std::size_t n : {std::size_t{0}, std::size_t{3}, std::size_t{40}, bytes.size() / 2,
                          bytes.size() - 1}) {
        EXPECT_NE(ExrMessage(bytes.substr(0, n), kMaxPicturePixels), "") << n;
    }
    std::filesystem::remove(path);
}

TEST(Exr, RefusesPicturesAboveThePixelLimitBeforeReadingThem) {
    const std::string path = TempPath("limit.exr");
    WriteExr(path, TestPattern(4, 4));
    const std::string rgb = FileBytes(path);
    Image layered = TestPattern(4, 4);
    layered.AddLayer("Z");
    WriteExr(path, layered);
    const std::string withLayer = FileBytes(path);
    std::filesystem::remove(path);

    EXPECT_EQ(ExrMessage(rgb, 16), "");
    EXPECT_EQ(ExrMessage(rgb, 15),
              "big.exr: byte 112: bad OpenEXR file: 4 x 4 pixels, more than the 15 lazyrad reads");
    // Every channel counts: R, G, B and Z are 64 values, more than 3 x 16.
    EXPECT_EQ(ExrMessage(withLayer, 16),
              "big.exr: bad OpenEXR file: 4 x 4 pixels in 4 values each, more than the 48 "
              "lazyrad reads");
    EXPECT_EQ(ExrMessage(withLayer, 22), "");

    // A 17 kB file declaring 32768 x 32768 pixels, with the table of line
    // offsets OpenEXR reads before any pixel: without the limit, 12.9 GB
    // allocated before the first scanline fails.
    std::string big = rgb;
    const std::string window = std::string("dataWindow\0box2i\0", 17);
    const std::size_t at = big.find(window);
    ASSERT_NE(at, std::string::npos);
    const std::int32_t box[4] = {0, 0, 32767, 32767};
    std::memcpy(&big[at + window.size() + 4], box, sizeof box);  // after the size
    // The offset table of a 4-line ZIP file is one entry.
    const std::size_t table = OffsetTable(rgb);
    ASSERT_NE(table, 0u);
    const std::size_t entries = 32768 / 16;  // ZIP: 16 scanlines a chunk
    std::string offsets;
    for (std::size_t i = 0; i < entries; ++i) {
        const std::uint64_t v = table + 8 * entries;
        offsets.append(reinterpret_cast<const char*>(&v), 8);
    }
    big = big.substr(0, table) + offsets + big.substr(table + 8);
    EXPECT_EQ(ExrMessage(big, kMaxPicturePixels),
              "big.exr: byte 112: bad OpenEXR file: 32768 x 32768 pixels, more than the "
              "268435456 lazyrad reads");
}

/// Writes a w x h float RGB picture (R = x + 100 y, G = 1, B = -y) as OpenEXR,
/// scanline or tiled, with the given compression, through OpenEXR itself.
void WriteWithOpenExr(const std::string& path, int w, int h, Imf::Compression compression,
                      const Imf::TileDescription* tiles) {
    std::vector<float> rgb(3 * static_cast<std::size_t>(w) * h);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            float* p = &rgb[3 * (static_cast<std::size_t>(y) * w + x)];
            p[0] = static_cast<float>(x + 100 * y);
            p[1] = 1.0f;
            p[2] = static_cast<float>(-y);
        }
    }
    Imf::Header header(w, h);
    header.compression() = compression;
    Imf::FrameBuffer frame;
    const char* names[] = {"R", "G", "B"};
    for (int c = 0; c < 3; ++c) {
        header.channels().insert(names[c], Imf::Channel(Imf::FLOAT));
        frame.insert(names[c], Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(&rgb[c]),
                                          3 * sizeof(float), 3 * sizeof(float) * w));
    }
    if (tiles) {
        header.setTileDescription(*tiles);
        Imf::TiledOutputFile out(path.c_str(), header);
        out.setFrameBuffer(frame);
        for (int ly = 0; ly < out.numYLevels(); ++ly) {
            for (int lx = 0; lx < out.numXLevels(); ++lx) {
                if (tiles->mode != Imf::RIPMAP_LEVELS && lx != ly) continue;
                out.writeTiles(0, out.numXTiles(lx) - 1, 0, out.numYTiles(ly) - 1, lx, ly);
            }
        }
    } else {
        Imf::OutputFile out(path.c_str(), header);
        out.setFrameBuffer(frame);
        out.writePixels(h);
    }
}

// The header check before OpenEXR (the offset tables' size by compression,
// tiles and levels) must not refuse any file OpenEXR writes.
TEST(Exr, ReadsEveryCompressionTilingAndLevelModeOpenExrWrites) {
    const std::string path = TempPath("kinds.exr");
    auto check = [&](const std::string& what) {
        const Image img = ReadExr(path);
        ASSERT_EQ(img.width, 37) << what;
        ASSERT_EQ(img.height, 23) << what;
        EXPECT_EQ(img.Get(36, 22).r, 36.0 + 2200.0) << what;  // lossless or exact in half
        EXPECT_EQ(img.Get(5, 7).b, -7.0) << what;
    };
    for (int c = Imf::NO_COMPRESSION; c < Imf::NUM_COMPRESSION_METHODS; ++c) {
        // The lossy methods round 2236 in half precision or DCT: only the
        // lossless ones are checked value for value.
        const auto method = static_cast<Imf::Compression>(c);
        WriteWithOpenExr(path, 37, 23, method, nullptr);
        if (c == Imf::PXR24_COMPRESSION || c >= Imf::B44_COMPRESSION) {
            EXPECT_EQ(ReadExr(path).width, 37) << "compression " << c;
        } else {
            check("compression " + std::to_string(c));
        }
    }
    for (Imf::LevelMode mode : {Imf::ONE_LEVEL, Imf::MIPMAP_LEVELS, Imf::RIPMAP_LEVELS}) {
        for (Imf::LevelRoundingMode rounding : {Imf::ROUND_DOWN, Imf::ROUND_UP}) {
            const Imf::TileDescription tiles(8, 4, mode, rounding);
            WriteWithOpenExr(path, 37, 23, Imf::ZIP_COMPRESSION, &tiles);
            check("level mode " + std::to_string(mode) + ", rounding " + std::to_string(rounding));
        }
    }
    // Two parts: the first is read.
    {
        std::vector<Imf::Header> headers(2, Imf::Header(37, 23));
        std::vector<float> plane(37 * 23, 4.0f);
        for (int i = 0; i < 2; ++i) {
            headers[i].setName("part" + std::to_string(i));
            headers[i].setType(Imf::SCANLINEIMAGE);
            for (const char* c : {"R", "G", "B"}) {
                headers[i].channels().insert(c, Imf::Channel(Imf::FLOAT));
            }
        }
        Imf::MultiPartOutputFile out(path.c_str(), headers.data(), 2);
        for (int i = 0; i < 2; ++i) {
            Imf::OutputPart part(out, i);
            Imf::FrameBuffer frame;
            for (const char* c : {"R", "G", "B"}) {
                frame.insert(c, Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(plane.data()),
                                           sizeof(float), sizeof(float) * 37));
            }
            part.setFrameBuffer(frame);
            part.writePixels(23);
        }
    }
    EXPECT_EQ(ReadExr(path).Get(3, 3).g, 4.0);
    std::filesystem::remove(path);
}

TEST(Exr, RefusesHeadersThatDeclareMoreThanTheFileHolds) {
    const std::string path = TempPath("header.exr");
    WriteExr(path, TestPattern(4, 4), {{"software", "lazyrad test"}});
    const std::string good = FileBytes(path);
    std::filesystem::remove(path);
    // The size of an attribute's value follows its name and type.
    auto sizeAt = [&](const std::string& nameAndType) {
        const std::size_t at = good.find(nameAndType);
        EXPECT_NE(at, std::string::npos) << nameAndType;
        return at + nameAndType.size();
    };
    // A string attribute declaring 1.8 GB (what fuzz_exr found: OpenEXR 3.1
    // allocated it before reading).
    std::string s = good;
    const std::int32_t huge = 0x6e914700;
    const std::size_t software = sizeAt(std::string("software\0string\0", 16));
    std::memcpy(&s[software], &huge, 4);
    const std::size_t attributeStart = software - 16;
    EXPECT_EQ(ExrMessage(s, kMaxPicturePixels),
              "big.exr: byte " + std::to_string(attributeStart) +
                  ": bad OpenEXR file: attribute \"software\" of 1855014656 bytes, more than the " +
                  std::to_string(good.size() - software - 4) + " bytes left");
    // The same with the channel list's declared size 1: OpenEXR reads a
    // channel list up to its empty name whatever the size says (a fixed-size
    // type its own length), and so must the check, to find the same string.
    const std::size_t chlist = sizeAt(std::string("channels\0chlist\0", 16));
    const std::int32_t one = 1;
    std::memcpy(&s[chlist], &one, 4);
    EXPECT_EQ(ExrMessage(s, kMaxPicturePixels),
              "big.exr: byte " + std::to_string(attributeStart) +
                  ": bad OpenEXR file: attribute \"software\" of 1855014656 bytes, more than the " +
                  std::to_string(good.size() - software - 4) + " bytes left");
    // A data window of 4 x 4096 pixels in a file holding the offsets of 4 lines:
    // 256 chunks of 16 lines, 2048 bytes of offsets.
    s = good;
    const std::size_t window = sizeAt(std::string("dataWindow\0box2i\0", 17)) + 4;
    const std::int32_t box[4] = {0, 0, 3, 4095};
    std::memcpy(&s[window], box, sizeof box);
    const std::string message = ExrMessage(s, kMaxPicturePixels);
    EXPECT_NE(
        message.find(": bad OpenEXR file: 256 chunks, whose offsets alone take more than the "),
        std::string::npos)
        << message;
    // Tiles of 8192 x 8192 pixels over a 37 x 23 picture: OpenEXR's own limit
    // (4096, set by lazyrad) refuses them before allocating a tile's buffer.
    {
        const std::string tiledPath = TempPath("tiles.exr");
        const Imf::TileDescription tiles(8, 4);
        WriteWithOpenExr(tiledPath, 37, 23, Imf::ZIP_COMPRESSION, &tiles);
        std::string t = FileBytes(tiledPath);
        std::filesystem::remove(tiledPath);
        const std::size_t desc = t.find(std::string("tiles\0tiledesc\0", 15));
        ASSERT_NE(desc, std::string::npos);
        const std::uint32_t side[2] = {8192, 8192};
        std::memcpy(&t[desc + 15 + 4], side, sizeof side);
        EXPECT_EQ(ExrMessage(t, kMaxPicturePixels),
                  "big.exr: cannot read OpenEXR file: Cannot read image file \"big.exr\". The "
                  "width of the tiles exceeds the maximum width of 4096pixels.");
    }
    // One attribute added at the header's end (before its closing null, just
    // ahead of the offset table), for the other refusals.
    const std::size_t headerEnd = OffsetTable(good) - 1;
    ASSERT_NE(headerEnd + 1, 0u);
    auto withAttribute = [&](const std::string& attribute) {
        return good.substr(0, headerEnd) + attribute + good.substr(headerEnd);
    };
    auto le32 = [](std::uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
    const std::string start = "big.exr: byte " + std::to_string(headerEnd) + ": bad OpenEXR file: ";
    // A preview image of 65536 x 65536 pixels in 8 bytes.
    EXPECT_EQ(ExrMessage(withAttribute(std::string("preview\0preview\0", 16) + le32(8) +
                                       le32(65536) + le32(65536)),
                         kMaxPicturePixels),
              start +
                  "preview image \"preview\" of 65536 x 65536 pixels, more than the bytes left");
    // A stringvector whose one string claims 1000 bytes of its 8.
    EXPECT_EQ(ExrMessage(withAttribute(std::string("sv\0stringvector\0", 16) + le32(8) +
                                       le32(1000) + "abcd"),
                         kMaxPicturePixels),
              start + "stringvector \"sv\" overruns the file");
    // A name of 40 characters without the long-names flag; a negative size.
    EXPECT_EQ(ExrMessage(withAttribute(std::string(40, 'n') + std::string("\0int\0", 5) +
                                       le32(4) + le32(0)),
                         kMaxPicturePixels),
              start + "name longer than 31 characters");
    EXPECT_EQ(ExrMessage(withAttribute(std::string("x\0string\0", 9) + le32(0xffffffffu)),
                         kMaxPicturePixels),
              start + "attribute \"x\" of negative size");
    // Cut inside the header.
    EXPECT_EQ(ExrMessage(good.substr(0, software + 2), kMaxPicturePixels),
              "big.exr: byte " + std::to_string(software) + ": bad OpenEXR file: header cut short");
}

}  // namespace
}  // namespace rt
