// SPDX-License-Identifier: MIT
#include "image/exr.h"

#include <OpenEXR/Iex.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <exception>
#include <fstream>
#include <iterator>
#include <mutex>
#include <set>

#include "core/error.h"
#include "image/hdr.h"

namespace rt {
namespace {

// Attributes every OpenEXR header must carry; user metadata may not replace them.
const std::set<std::string> kReservedAttributes = {"channels",
                                                   "compression",
                                                   "dataWindow",
                                                   "displayWindow",
                                                   "lineOrder",
                                                   "pixelAspectRatio",
                                                   "screenWindowCenter",
                                                   "screenWindowWidth",
                                                   "tiles",
                                                   "type",
                                                   "name",
                                                   "version",
                                                   "chunkCount"};

/// An OpenEXR input stream over bytes in memory (ReadExrBytes). OpenEXR's
/// contract: read() throws when fewer than n bytes are left, and returns
/// false when it has read the last one.
class MemoryStream final : public Imf::IStream {
public:
    MemoryStream(std::string_view bytes, const std::string& name)
        : Imf::IStream(name.c_str()), bytes_(bytes) {}
    bool read(char c[], int n) override {
        if (n < 0 || pos_ > bytes_.size() || static_cast<std::uint64_t>(n) > bytes_.size() - pos_) {
            throw Iex::InputExc("Early end of file");
        }
        std::memcpy(c, bytes_.data() + pos_, static_cast<std::size_t>(n));
        pos_ += static_cast<std::uint64_t>(n);
        return pos_ < bytes_.size();
    }
    std::uint64_t tellg() override { return pos_; }
    void seekg(std::uint64_t pos) override { pos_ = pos; }  // a read beyond the end throws

private:
    std::string_view bytes_;
    std::uint64_t pos_ = 0;
};

/// Walks the headers of an OpenEXR file held in `b` before OpenEXR reads them.
/// OpenEXR 3.1 allocates what a header declares before checking it against the
/// file: a string attribute declaring 1.8 GB in a 700-byte file made it ask for
/// 1.8 GB (found by fuzz_exr), and so would a stringvector's strings, a preview
/// image's pixels and the chunk offset tables, whose size follows the data
/// window, the tiles and chunkCount. Here the attributes are taken as
/// OpenEXR's Header::readFrom takes them (ValueBytes), every value it would
/// allocate must fit in the bytes left, a part's data window in `maxPixels`,
/// and the offset tables (8 bytes a chunk) in what follows the headers. The
/// format: magic and version (8 bytes), then per part attributes (name\0
/// type\0 int32 size, value) up to an empty name, and for a multipart file an
/// empty header after the last part.
class ExrHeaderScan {
public:
    ExrHeaderScan(std::string_view bytes, const std::string& name, long long maxPixels)
        : b_(bytes), name_(name), maxPixels_(maxPixels) {}

    void Check() {
        if (b_.size() < 8) return;  // OpenEXR refuses it itself
        const std::uint32_t version = U32(4);
        const bool multipart = (version & 0x1000) != 0;
        const bool singleTiled = (version & 0x200) != 0;
        const std::size_t maxLength = (version & 0x400) != 0 ? 255 : 31;  // long names
        pos_ = 8;
        unsigned long long chunks = 0;
        do {
            chunks += Part(singleTiled, maxLength);
        } while (multipart && pos_ < b_.size() && b_[pos_] != '\0');
        if (multipart) ++pos_;  // the empty header that ends the list
        const std::size_t left = pos_ < b_.size() ? b_.size() - pos_ : 0;
        if (chunks > left / 8) {
            Fail(pos_, std::to_string(chunks) + " chunks, whose offsets alone take more than the " +
                           std::to_string(left) + " bytes left");
        }
    }

private:
    [[noreturn]] void Fail(std::size_t at, const std::string& what) const {
        FileLoc loc{name_};
        loc.byteOffset = static_cast<long long>(at);
        ThrowUserError(loc, "bad OpenEXR file: " + what);
    }
    std::uint32_t U32(std::size_t at) const {
        if (at > b_.size() || b_.size() - at < 4) Fail(at, "header cut short");
        std::uint32_t v = 0;
        for (int i = 3; i >= 0; --i) v = (v << 8) | static_cast<unsigned char>(b_[at + i]);
        return v;
    }
    std::int32_t I32(std::size_t at) const { return static_cast<std::int32_t>(U32(at)); }
    /// A name as OpenEXR's Xdr::read(is, maxLength, name) reads it: at most
    /// maxLength characters and the null after them; pos_ moves past it.
    std::string_view Name(std::size_t maxLength) {
        if (pos_ >= b_.size()) Fail(pos_, "header cut short");
        const std::size_t end = b_.find('\0', pos_);
        if (end == std::string_view::npos || end - pos_ > maxLength) {
            Fail(pos_, "name longer than " + std::to_string(maxLength) + " characters");
        }
        const std::string_view t = b_.substr(pos_, end - pos_);
        pos_ = end + 1;
        return t;
    }

    /// Bytes OpenEXR 3.1's reader of an attribute of `type` takes from a value
    /// declared `size` bytes long at pos_. The fixed-size types read their own
    /// length whatever the declared one; strings, vectors, opaque (unknown)
    /// types and ID manifests allocate and read `size` bytes; a channel list
    /// reads up to its empty name; a preview image its width × height pixels.
    std::size_t ValueBytes(std::string_view type, std::size_t size, std::size_t at,
                           std::string_view attribute) {
        static const std::pair<std::string_view, std::size_t> kFixed[] = {
            {"box2i", 16}, {"box2f", 16}, {"chromaticities", 32}, {"compression", 1},
            {"deepImageState", 1}, {"double", 8}, {"envmap", 1}, {"float", 4}, {"int", 4},
            {"keycode", 28}, {"lineOrder", 1}, {"m33f", 36}, {"m33d", 72}, {"m44f", 64},
            {"m44d", 128}, {"rational", 8}, {"tiledesc", 9}, {"timecode", 8}, {"v2i", 8},
            {"v2f", 8}, {"v2d", 16}, {"v3i", 12}, {"v3f", 12}, {"v3d", 24}};
        for (const auto& [name, bytes] : kFixed) {
            if (type == name) return bytes;
        }
        const std::size_t left = b_.size() - pos_;
        if (type == "chlist") {
            const std::size_t start = pos_;
            while (!Name(255).empty()) pos_ += 16;  // type, pLinear, 3 reserved, sampling
            const std::size_t taken = pos_ - start;
            pos_ = start;
            return taken;
        }
        if (type == "preview") {
            const unsigned long long w = U32(pos_), h = U32(pos_ + 4);
            if (w != 0 && h > (left - 8) / 4 / w) {
                Fail(at, "preview image \"" + std::string(attribute) + "\" of " +
                             std::to_string(w) + " x " + std::to_string(h) +
                             " pixels, more than the bytes left");
            }
            return 8 + 4 * w * h;
        }
        if (size > left) {
            Fail(at, "attribute \"" + std::string(attribute) + "\" of " + std::to_string(size) +
                         " bytes, more than the " + std::to_string(left) + " bytes left");
        }
        if (type == "stringvector") {
            for (std::size_t p = pos_; p < pos_ + size;) {
                const std::size_t room = pos_ + size - p;
                const std::int32_t n = room >= 4 ? I32(p) : 0;
                if (n < 0 || static_cast<std::size_t>(n) > left - (p + 4 - pos_)) {
                    Fail(at, "stringvector \"" + std::string(attribute) + "\" overruns the file");
                }
                p += 4 + static_cast<std::size_t>(n);
            }
        }
        return size;
    }

    /// One part's attributes, as OpenEXR's Header::readFrom reads them; returns
    /// the part's number of chunks (0 when unknown).
    unsigned long long Part(bool singleTiled, std::size_t maxLength) {
        long long width = 0, height = 0;
        int compression = -1;
        bool tiled = singleTiled;
        std::uint32_t tileX = 0, tileY = 0;
        int levelMode = 0, rounding = 0;
        long long chunkCount = -1;
        while (true) {
            const std::size_t at = pos_;
            const std::string_view attribute = Name(maxLength);
            if (attribute.empty()) break;
            const std::string_view type = Name(maxLength);
            const std::int32_t declared = I32(pos_);
            pos_ += 4;
            if (declared < 0) {
                Fail(at, "attribute \"" + std::string(attribute) + "\" of negative size");
            }
            const std::size_t size = static_cast<std::size_t>(declared);
            const std::size_t value = pos_;
            const std::size_t taken = ValueBytes(type, size, at, attribute);
            if (taken > b_.size() - value) Fail(at, "header cut short");
            if (attribute == "dataWindow" && type == "box2i") {
                width = static_cast<long long>(I32(value + 8)) - I32(value) + 1;
                height = static_cast<long long>(I32(value + 12)) - I32(value + 4) + 1;
                if (width > 0 && height > 0 && width > maxPixels_ / height) {
                    Fail(at, std::to_string(width) + " x " + std::to_string(height) +
                                 " pixels, more than the " + std::to_string(maxPixels_) +
                                 " lazyrad reads");
                }
            } else if (attribute == "compression" && type == "compression") {
                compression = static_cast<unsigned char>(b_[value]);
            } else if (attribute == "tiles" && type == "tiledesc") {
                tiled = true;
                tileX = U32(value);
                tileY = U32(value + 4);
                levelMode = static_cast<unsigned char>(b_[value + 8]) & 0xf;
                rounding = static_cast<unsigned char>(b_[value + 8]) >> 4;
            } else if (attribute == "chunkCount" && type == "int") {
                chunkCount = I32(value);
            } else if (attribute == "type" && type == "string") {
                const std::string_view kind = b_.substr(value, taken);
                tiled = kind == "tiledimage" || kind == "deeptile";
            }
            pos_ = value + taken;
        }
        if (chunkCount > 0) return static_cast<unsigned long long>(chunkCount);
        if (width <= 0 || height <= 0) return 0;  // OpenEXR refuses it
        if (tiled) {
            if (tileX == 0 || tileY == 0) return 0;  // OpenEXR refuses it
            return Tiles(width, height, tileX, tileY, levelMode, rounding);
        }
        // Scanlines a chunk holds, by compression method (ImfCompression.h).
        constexpr int kLines[] = {1, 1, 1, 16, 32, 16, 32, 32, 32, 256};
        if (compression < 0 || compression >= static_cast<int>(std::size(kLines))) return 0;
        return static_cast<unsigned long long>((height + kLines[compression] - 1) /
                                               kLines[compression]);
    }

    /// Tiles over every level (ImfTiledMisc.cpp's level sizes), saturating.
    static unsigned long long Tiles(long long w, long long h, std::uint32_t tx, std::uint32_t ty,
                                    int mode, int rounding) {
        auto levels = [&](long long n) {
            int l = 0;
            while ((1LL << (l + 1)) <= n) ++l;  // floor(log2 n)
            if (rounding == 1 && (1LL << l) < n) ++l;
            return l + 1;
        };
        auto size = [&](long long n, int l) {
            const long long s = rounding == 1 ? (n + (1LL << l) - 1) >> l : n >> l;
            return s < 1 ? 1 : s;
        };
        auto across = [](long long n, std::uint32_t t) {
            return static_cast<unsigned long long>((n + t - 1) / t);
        };
        unsigned long long total = 0;
        if (mode == 2) {  // ripmap: every pair of x and y levels
            for (int lx = 0; lx < levels(w); ++lx) {
                for (int ly = 0; ly < levels(h); ++ly) {
                    total += across(size(w, lx), tx) * across(size(h, ly), ty);
                }
            }
        } else {
            const int n = mode == 1 ? levels(std::max(w, h)) : 1;
            for (int l = 0; l < n; ++l) total += across(size(w, l), tx) * across(size(h, l), ty);
        }
        return total;
    }

    std::string_view b_;
    const std::string& name_;
    long long maxPixels_;
    std::size_t pos_ = 0;
};

/// OpenEXR's own header check, set once for the process: a tile larger than
/// this is refused before OpenEXR allocates its buffer, whatever the data
/// window (real files use tiles of 32 to 512 pixels; 4096 x 4096 float RGB is
/// 200 MB).
void LimitOpenExrTiles() {
    static std::once_flag once;
    std::call_once(once, [] { Imf::Header::setMaxTileSize(4096, 4096); });
}

/// Reads the open file `file` (named `name` in messages) into an Image,
/// refusing more than 3·maxPixels values over all channels before allocating
/// any.
Image ReadOpenExr(Imf::InputFile& file, const std::string& name, ImageMetadata* metadata,
                  long long maxPixels) {
    const Imf::Header& header = file.header();
    const Imath::Box2i window = header.dataWindow();
    // In 64 bits: a window from INT_MIN to INT_MAX is 2^32 wide.
    const long long width = static_cast<long long>(window.max.x) - window.min.x + 1;
    const long long height = static_cast<long long>(window.max.y) - window.min.y + 1;
    if (width <= 0 || height <= 0) {
        ThrowUserError(FileLoc{name}, "bad OpenEXR file: empty data window");
    }
    const Imf::ChannelList& channels = header.channels();
    const bool hasRgb =
        channels.findChannel("R") && channels.findChannel("G") && channels.findChannel("B");
    const bool hasY = channels.findChannel("Y") != nullptr;
    if (!hasRgb && !hasY) {
        ThrowUserError(FileLoc{name}, "OpenEXR file has neither R, G, B nor Y channels");
    }
    // Every channel but the colour's (R, G, B, or a lone Y) becomes a layer.
    std::vector<std::string> layerNames;
    for (auto it = channels.begin(); it != channels.end(); ++it) {
        const std::string channel = it.name();
        if (channel == "R" || channel == "G" || channel == "B") continue;
        if (channel == "Y" && !hasRgb) continue;
        layerNames.push_back(channel);
    }
    // A lone Y is read apart, then copied to the three colours.
    const long long valuesPerPixel =
        (hasRgb ? 3 : 4) + static_cast<long long>(layerNames.size());
    // The pixels are within maxPixels (ExrHeaderScan); every channel counts too.
    if (valuesPerPixel > 3 * maxPixels / (width * height)) {
        ThrowUserError(FileLoc{name}, "bad OpenEXR file: " + std::to_string(width) + " x " +
                                          std::to_string(height) + " pixels in " +
                                          std::to_string(valuesPerPixel) +
                                          " values each, more than the " +
                                          std::to_string(3 * maxPixels) + " lazyrad reads");
    }
    Image image(static_cast<int>(width), static_cast<int>(height));
    std::vector<float> luminance;
    const std::size_t pixelStride = 3 * sizeof(float);
    const std::size_t rowStride = pixelStride * static_cast<std::size_t>(width);
    Imf::FrameBuffer frame;
    if (hasRgb) {
        char* base = reinterpret_cast<char*>(image.rgb.data());
        frame.insert("R", Imf::Slice::Make(Imf::FLOAT, base, window, pixelStride, rowStride));
        frame.insert("G", Imf::Slice::Make(Imf::FLOAT, base + sizeof(float), window, pixelStride,
                                           rowStride));
        frame.insert("B", Imf::Slice::Make(Imf::FLOAT, base + 2 * sizeof(float), window,
                                           pixelStride, rowStride));
    } else {
        luminance.assign(image.PixelCount(), 0.0f);
        frame.insert("Y", Imf::Slice::Make(Imf::FLOAT, luminance.data(), window));
    }
    for (const std::string& channel : layerNames) {
        image.layers.push_back({channel, std::vector<float>(image.PixelCount(), 0.0f)});
    }
    for (ImageLayer& layer : image.layers) {
        frame.insert(layer.name, Imf::Slice::Make(Imf::FLOAT, layer.values.data(), window));
    }
    file.setFrameBuffer(frame);
    file.readPixels(window.min.y, window.max.y);
    if (!hasRgb) {
        for (std::size_t i = 0; i < luminance.size(); ++i) {
            image.rgb[3 * i] = image.rgb[3 * i + 1] = image.rgb[3 * i + 2] = luminance[i];
        }
    }
    if (metadata) {
        metadata->clear();
        for (auto it = header.begin(); it != header.end(); ++it) {
            if (const auto* s = dynamic_cast<const Imf::StringAttribute*>(&it.attribute())) {
                metadata->emplace_back(it.name(), s->value());
            }
        }
    }
    return image;
}

}  // namespace

void WriteExr(const std::string& path, const Image& image, const ImageMetadata& metadata) {
    if (image.width <= 0 || image.height <= 0) {
        ThrowUserError(FileLoc{path}, "cannot write an empty image (" +
                                          std::to_string(image.width) + "x" +
                                          std::to_string(image.height) + ")");
    }
    if (image.rgb.size() != 3 * image.PixelCount()) {
        throw Error(Error::Kind::Internal, FileLoc{path}, "image pixel buffer has wrong size");
    }
    for (const ImageLayer& layer : image.layers) {
        if (layer.values.size() != image.PixelCount() || layer.name.empty() || layer.name == "R" ||
            layer.name == "G" || layer.name == "B") {
            ThrowUserError(FileLoc{path}, "bad image layer '" + layer.name + "'");
        }
    }
    for (const auto& [name, value] : metadata) {
        if (name.empty() || kReservedAttributes.count(name)) {
            ThrowUserError(FileLoc{path}, "metadata name '" + name + "' is reserved by OpenEXR");
        }
    }
    try {
        Imf::Header header(image.width, image.height);
        header.compression() = Imf::ZIP_COMPRESSION;
        header.lineOrder() = Imf::INCREASING_Y;
        for (const char* c : {"R", "G", "B"}) {
            header.channels().insert(c, Imf::Channel(Imf::FLOAT));
        }
        for (const ImageLayer& layer : image.layers) {
            header.channels().insert(layer.name, Imf::Channel(Imf::FLOAT));
        }
        for (const auto& [name, value] : metadata) {
            header.insert(name, Imf::StringAttribute(value));
        }

        // OpenEXR only reads through the slices, but its API takes char*.
        char* rgbBase = const_cast<char*>(reinterpret_cast<const char*>(image.rgb.data()));
        const std::size_t pixelStride = 3 * sizeof(float);
        const std::size_t rowStride = pixelStride * static_cast<std::size_t>(image.width);
        Imf::FrameBuffer frame;
        frame.insert("R", Imf::Slice(Imf::FLOAT, rgbBase, pixelStride, rowStride));
        frame.insert("G", Imf::Slice(Imf::FLOAT, rgbBase + sizeof(float), pixelStride, rowStride));
        frame.insert("B",
                     Imf::Slice(Imf::FLOAT, rgbBase + 2 * sizeof(float), pixelStride, rowStride));
        for (const ImageLayer& layer : image.layers) {
            char* base = const_cast<char*>(reinterpret_cast<const char*>(layer.values.data()));
            frame.insert(layer.name,
                         Imf::Slice(Imf::FLOAT, base, sizeof(float),
                                    sizeof(float) * static_cast<std::size_t>(image.width)));
        }
        Imf::OutputFile file(path.c_str(), header);
        file.setFrameBuffer(frame);
        file.writePixels(image.height);
    } catch (const std::exception& e) {
        // Iex exceptions derive from std::exception; OpenEXR's text already says why.
        throw Error(Error::Kind::System, FileLoc{path},
                    std::string("cannot write OpenEXR file: ") + e.what());
    }
}

Image ReadExr(const std::string& path, ImageMetadata* metadata, long long maxPixels) {
    // Read whole, so that the headers can be checked against the file's size
    // before OpenEXR sees them (ExrHeaderScan).
    std::ifstream in(path, std::ios::binary);
    if (!in) ThrowUserError(FileLoc{path}, "cannot read OpenEXR file: cannot open");
    const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (in.bad()) ThrowUserError(FileLoc{path}, "cannot read OpenEXR file: read error");
    return ReadExrBytes(bytes, path, metadata, maxPixels);
}

Image ReadExrBytes(std::string_view bytes, const std::string& name, ImageMetadata* metadata,
                   long long maxPixels) {
    LimitOpenExrTiles();
    ExrHeaderScan(bytes, name, maxPixels).Check();
    try {
        MemoryStream stream(bytes, name);
        Imf::InputFile file(stream);
        return ReadOpenExr(file, name, metadata, maxPixels);
    } catch (const Error&) {
        throw;
    } catch (const std::exception& e) {
        ThrowUserError(FileLoc{name}, std::string("cannot read OpenEXR file: ") + e.what());
    }
}

bool IsExrFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::array<char, 4> magic{};
    if (!in.read(magic.data(), 4))
        return false;
    const std::array<char, 4> kMagic = {0x76, 0x2f, 0x31, 0x01};
    return magic == kMagic;
}

Image ReadImage(const std::string& path) {
    {
        std::ifstream probe(path, std::ios::binary);
        if (!probe)
            throw Error(Error::Kind::System, FileLoc{path}, "cannot open");
    }
    return IsExrFile(path) ? ReadExr(path) : ReadHdr(path);
}

}  // namespace rt
