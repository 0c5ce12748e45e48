// SPDX-License-Identifier: MIT
//
// A plain float RGB picture plus optional extra float layers (depth, sample
// counts, ...). Row-major, top row first, as Radiance pictures and OpenEXR's
// INCREASING_Y line order store them, so the two formats map one to one.
//
//   rt::Image img(64, 48);
//   img.Set(x, y, rt::Rgb(1, 0.5, 0.25));   // y = 0 is the top row
#pragma once

#include <string>
#include <vector>

#include "core/rgb.h"

namespace rt {

/// One extra scalar channel, e.g. "Z" for ray length. values.size() == width·height.
struct ImageLayer {
    std::string name;           // channel name in EXR; must not be R, G or B
    std::vector<float> values;  // row-major, top row first

    bool operator==(const ImageLayer&) const = default;
};

struct Image {
    int width = 0;
    int height = 0;
    std::vector<float> rgb;  // 3·width·height floats, (r,g,b) per pixel, top row first
    std::vector<ImageLayer> layers;

    Image() = default;
    /// A black picture of the given size (both ≥ 0).
    Image(int width_, int height_);

    std::size_t PixelCount() const {
        return static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    }
    /// x in [0,width), y in [0,height) with y = 0 the top row. Unchecked.
    Rgb Get(int x, int y) const;
    void Set(int x, int y, const Rgb& c);

    /// Adds a zero-filled layer and returns it; throws rt::Error if the name is taken.
    ImageLayer& AddLayer(const std::string& name);
    /// nullptr when absent.
    const ImageLayer* FindLayer(const std::string& name) const;

    bool operator==(const Image&) const = default;
};

}  // namespace rt
