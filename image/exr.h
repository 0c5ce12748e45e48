// SPDX-License-Identifier: MIT
//
// OpenEXR output and input for rt::Image. Pictures are written as 32-bit float
// scanline files (ZIP, lossless), channels R, G, B plus one FLOAT channel per
// extra layer, with string metadata attributes recording provenance (command
// line, software version) as house style §4.13 asks. OpenEXR itself stays
// private to image/*.cpp.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "image/hdr.h"
#include "image/image.h"

namespace rt {

/// Ordered (name, value) pairs stored as OpenEXR string attributes, e.g.
/// {"software", "lazyrad 0.1.0"}, {"commandLine", "rtrace -ab 2 ..."}.
using ImageMetadata = std::vector<std::pair<std::string, std::string>>;

/// Throws rt::Error naming `path` when it cannot be written, or when a metadata
/// name collides with a required OpenEXR header attribute (channels, dataWindow, ...).
void WriteExr(const std::string& path, const Image& image, const ImageMetadata& metadata = {});

/// Reads any scanline or tiled OpenEXR file; channels are converted to float.
/// R, G, B become the colour (a lone Y channel is copied to all three); every other
/// channel becomes a layer. String attributes are returned in `metadata` when it is
/// non-null, in the file's (alphabetical) order. Throws rt::Error naming `path`,
/// also, before reading any pixel, for a picture of more than `maxPixels` pixels
/// or more than 3·maxPixels values over all its channels.
[[nodiscard]] Image ReadExr(const std::string& path, ImageMetadata* metadata = nullptr,
                            long long maxPixels = kMaxPicturePixels);

/// ReadExr on a file's bytes held in memory, `name` standing for the file in
/// messages (the fuzz target's way in).
[[nodiscard]] Image ReadExrBytes(std::string_view bytes, const std::string& name,
                                 ImageMetadata* metadata = nullptr,
                                 long long maxPixels = kMaxPicturePixels);

/// True when the file starts with the OpenEXR magic number (76 2f 31 01).
[[nodiscard]] bool IsExrFile(const std::string& path);

/// Reads an OpenEXR file or a Radiance picture, chosen by the file's magic number.
/// It lives here, not in hdr.h, so that a program reading only Radiance pictures
/// (rtrace's colorpict patterns) does not link OpenEXR.
[[nodiscard]] Image ReadImage(const std::string& path);

}  // namespace rt
