// SPDX-License-Identifier: MIT
//
// 8-bit PNG output of tone-mapped pictures, for documentation images (the
// HDR data itself goes to OpenEXR or Radiance RGBE). Tone mapping is a plain
// exposure and display gamma, like `pfilt -e` followed by a gamma-2.2 display:
//   byte = 255 · clamp(exposure · value, 0, 1)^(1/gamma)
// libpng stays private to image/png.cpp.
//
//   rt::WritePng("cornell.png", image, rt::AutoExposure(image));
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "image/image.h"

namespace rt {

/// The exposure that maps a robust mean luminance to 0.5: the mean over the
/// pixels below the 98th luminance percentile, so a few very bright pixels
/// (light sources, a window) do not darken the rest. 1 for a black image.
[[nodiscard]] double AutoExposure(const Image& image);

/// 3 bytes (r, g, b) per pixel, top row first, with the formula above.
[[nodiscard]] std::vector<std::uint8_t> ToneMap(const Image& image, double exposure,
                                                double gamma = 2.2);

/// Writes an 8-bit RGB PNG of ToneMap(image, exposure, gamma). Layers are not
/// stored. Throws rt::Error naming `path` when it cannot be written.
void WritePng(const std::string& path, const Image& image, double exposure, double gamma = 2.2);

/// Reads an 8-bit or 16-bit PNG back as bytes (3 per pixel, gamma not undone),
/// for tests. Throws rt::Error naming `path`.
[[nodiscard]] std::vector<std::uint8_t> ReadPng(const std::string& path, int& width, int& height);

}  // namespace rt
