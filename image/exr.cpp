// SPDX-License-Identifier: MIT
#include "image/exr.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>

#include <array>
#include <cstring>
#include <exception>
#include <fstream>
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

Image ReadExr(const std::string& path, ImageMetadata* metadata) {
    Image image;
    try {
        Imf::InputFile file(path.c_str());
        const Imf::Header& header = file.header();
        const Imath::Box2i window = header.dataWindow();
        const int width = window.max.x - window.min.x + 1;
        const int height = window.max.y - window.min.y + 1;
        image = Image(width, height);

        const Imf::ChannelList& channels = header.channels();
        const bool hasRgb =
            channels.findChannel("R") && channels.findChannel("G") && channels.findChannel("B");
        const bool hasY = channels.findChannel("Y") != nullptr;
        if (!hasRgb && !hasY) {
            ThrowUserError(FileLoc{path}, "OpenEXR file has neither R, G, B nor Y channels");
        }
        std::vector<float> luminance;
        const std::size_t pixelStride = 3 * sizeof(float);
        const std::size_t rowStride = pixelStride * static_cast<std::size_t>(width);
        Imf::FrameBuffer frame;
        if (hasRgb) {
            char* base = reinterpret_cast<char*>(image.rgb.data());
            frame.insert("R", Imf::Slice::Make(Imf::FLOAT, base, window, pixelStride, rowStride));
            frame.insert("G", Imf::Slice::Make(Imf::FLOAT, base + sizeof(float), window,
                                               pixelStride, rowStride));
            frame.insert("B", Imf::Slice::Make(Imf::FLOAT, base + 2 * sizeof(float), window,
                                               pixelStride, rowStride));
        } else {
            luminance.assign(image.PixelCount(), 0.0f);
            frame.insert("Y", Imf::Slice::Make(Imf::FLOAT, luminance.data(), window));
        }
        for (auto it = channels.begin(); it != channels.end(); ++it) {
            const std::string name = it.name();
            if (name == "R" || name == "G" || name == "B")
                continue;
            if (name == "Y" && !hasRgb)
                continue;
            image.layers.push_back({name, std::vector<float>(image.PixelCount(), 0.0f)});
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
    } catch (const Error&) {
        throw;
    } catch (const std::exception& e) {
        ThrowUserError(FileLoc{path}, std::string("cannot read OpenEXR file: ") + e.what());
    }
    return image;
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
