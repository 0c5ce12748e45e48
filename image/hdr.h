// SPDX-License-Identifier: MIT
//
// Radiance pictures (.hdr/.pic): the "#?RADIANCE" text header, a blank line,
// the resolution string ("-Y h +X w" for the standard top-down orientation) and
// RGBE scanlines, flat or run-length encoded. Replaces Radiance's color.c
// (setcolr/colr_color, fwritecolrs/freadcolrs) and resolu.c; see
// radiance-notes.md §1.7, §1.8 and §5.4.
#pragma once

#include <array>
#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include "core/rgb.h"
#include "core/rgbe.h"
#include "image/image.h"

namespace rt {

enum class HdrEncoding {
    RunLength,  // Radiance's new-style per-component RLE (fwritecolrs), flat when
                // width < 8 or > 32767 as Radiance does
    Flat,       // 4 bytes per pixel, what rtrace -ffc writes
};

/// Writes `#?RADIANCE`, `headerLines` (one per line, no '\n' inside; any FORMAT=
/// or "#?" lines among them are dropped), `FORMAT=32-bit_rle_rgbe`, a blank line,
/// `-Y height +X width` and the scanlines. Layers are not stored. Throws rt::Error.
void WriteHdr(std::ostream& out, const Image& image,
              const std::vector<std::string>& headerLines = {},
              HdrEncoding encoding = HdrEncoding::RunLength);
void WriteHdr(const std::string& path, const Image& image,
              const std::vector<std::string>& headerLines = {},
              HdrEncoding encoding = HdrEncoding::RunLength);

/// Reads a Radiance RGBE picture in any of the 8 orientations, scanlines flat,
/// new-style RLE or old-style (1,1,1,n) repeats. Pixel values are returned as
/// stored: EXPOSURE= lines are not divided out. The header lines between the
/// magic line and the blank line, except FORMAT=, are returned in
/// `headerLines` when non-null. Errors name `name` (a file or "<stdin>"),
/// with the byte offset for a damaged body. A picture of more than
/// `maxPixels` pixels is refused before any pixel is read (Radiance would try
/// to allocate it; a 30-byte file can declare 2^40 pixels).
inline constexpr long long kMaxPicturePixels = 1LL << 28;  // 16384 x 16384: 3 GiB as floats
[[nodiscard]] Image ReadHdr(std::istream& in, const std::string& name,
                            std::vector<std::string>* headerLines = nullptr,
                            long long maxPixels = kMaxPicturePixels);
[[nodiscard]] Image ReadHdr(const std::string& path,
                            std::vector<std::string>* headerLines = nullptr,
                            long long maxPixels = kMaxPicturePixels);

}  // namespace rt
