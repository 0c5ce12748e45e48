// SPDX-License-Identifier: MIT
#include "image/image.h"

#include "core/error.h"

namespace rt {

Image::Image(int width_, int height_) : width(width_), height(height_) {
    if (width_ < 0 || height_ < 0) {
        ThrowUserError("image size " + std::to_string(width_) + "x" + std::to_string(height_) +
                       " is negative");
    }
    rgb.assign(3 * PixelCount(), 0.0f);
}

Rgb Image::Get(int x, int y) const {
    const std::size_t i = 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                               static_cast<std::size_t>(x));
    return {rgb[i], rgb[i + 1], rgb[i + 2]};
}

void Image::Set(int x, int y, const Rgb& c) {
    const std::size_t i = 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                               static_cast<std::size_t>(x));
    rgb[i] = static_cast<float>(c.r);
    rgb[i + 1] = static_cast<float>(c.g);
    rgb[i + 2] = static_cast<float>(c.b);
}

ImageLayer& Image::AddLayer(const std::string& name) {
    if (name.empty() || name == "R" || name == "G" || name == "B" || FindLayer(name)) {
        ThrowUserError("image layer name '" + name + "' is empty, reserved or already used");
    }
    layers.push_back({name, std::vector<float>(PixelCount(), 0.0f)});
    return layers.back();
}

const ImageLayer* Image::FindLayer(const std::string& name) const {
    for (const ImageLayer& layer : layers) {
        if (layer.name == name)
            return &layer;
    }
    return nullptr;
}

}  // namespace rt
