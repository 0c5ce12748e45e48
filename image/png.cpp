// SPDX-License-Identifier: MIT
#include "image/png.h"

#include <png.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include "core/error.h"

namespace rt {
namespace {

struct FileCloser {
    void operator()(std::FILE* f) const { std::fclose(f); }
};
using FilePtr = std::unique_ptr<std::FILE, FileCloser>;

// libpng reports errors through a callback that must not return; it longjmps
// back to the setjmp in the caller, which then throws. No C++ object with a
// destructor may be created between setjmp and the libpng calls.
[[noreturn]] void PngError(png_structp png, png_const_charp message) {
    auto* text = static_cast<std::string*>(png_get_error_ptr(png));
    if (text) *text = message;
    png_longjmp(png, 1);
}
void PngWarning(png_structp, png_const_charp) {}

// The setjmp lives in these two functions, which modify no local after it, so
// nothing can be clobbered by the longjmp.
bool WriteRows(png_structp png, png_infop info, std::FILE* file, int width, int height,
               double gamma, png_bytep* rows) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_init_io(png, file);
    png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), 8,
                 PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    png_set_gAMA(png, info, 1.0 / gamma);
    png_write_info(png, info);
    png_write_image(png, rows);
    png_write_end(png, nullptr);
    return true;
}

bool ReadRows(png_structp png, png_infop info, std::FILE* file, std::vector<std::uint8_t>* out,
              std::vector<png_bytep>* rows, int* width, int* height) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_init_io(png, file);
    png_read_info(png, info);
    png_set_expand(png);
    png_set_strip_16(png);
    png_set_strip_alpha(png);
    png_set_gray_to_rgb(png);
    png_read_update_info(png, info);
    *width = static_cast<int>(png_get_image_width(png, info));
    *height = static_cast<int>(png_get_image_height(png, info));
    out->resize(3 * static_cast<std::size_t>(*width) * static_cast<std::size_t>(*height));
    rows->resize(static_cast<std::size_t>(*height));
    for (int y = 0; y < *height; ++y) {
        (*rows)[static_cast<std::size_t>(y)] =
            out->data() + 3 * static_cast<std::size_t>(y) * static_cast<std::size_t>(*width);
    }
    png_read_image(png, rows->data());
    png_read_end(png, nullptr);
    return true;
}

}  // namespace

double AutoExposure(const Image& image) {
    std::vector<double> lum;
    lum.reserve(image.PixelCount());
    for (std::size_t i = 0; i < image.PixelCount(); ++i) {
        const Rgb c(image.rgb[3 * i], image.rgb[3 * i + 1], image.rgb[3 * i + 2]);
        const double y = Bright(c);
        if (std::isfinite(y)) lum.push_back(std::max(y, 0.0));
    }
    if (lum.empty()) return 1.0;
    std::sort(lum.begin(), lum.end());
    const std::size_t keep = std::max<std::size_t>(1, lum.size() * 98 / 100);
    double sum = 0;
    for (std::size_t i = 0; i < keep; ++i) sum += lum[i];
    const double mean = sum / static_cast<double>(keep);
    return mean > 1e-30 ? 0.5 / mean : 1.0;
}

std::vector<std::uint8_t> ToneMap(const Image& image, double exposure, double gamma) {
    std::vector<std::uint8_t> out(image.rgb.size());
    const double inv = 1.0 / gamma;
    for (std::size_t i = 0; i < image.rgb.size(); ++i) {
        double v = exposure * static_cast<double>(image.rgb[i]);
        if (!(v > 0)) v = 0;  // also NaN
        v = std::pow(std::min(v, 1.0), inv);
        out[i] = static_cast<std::uint8_t>(std::lround(255.0 * v));
    }
    return out;
}

void WritePng(const std::string& path, const Image& image, double exposure, double gamma) {
    if (image.width <= 0 || image.height <= 0)
        ThrowUserError(FileLoc{path}, "cannot write an empty image");
    const std::vector<std::uint8_t> bytes = ToneMap(image, exposure, gamma);
    std::vector<png_bytep> rows(static_cast<std::size_t>(image.height));
    for (int y = 0; y < image.height; ++y) {
        rows[static_cast<std::size_t>(y)] = const_cast<png_bytep>(
            bytes.data() + 3 * static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width));
    }
    FilePtr file(std::fopen(path.c_str(), "wb"));
    if (!file) ThrowSystemError("cannot open '" + path + "' for writing");
    std::string message;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &message, PngError, PngWarning);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!info) {
        png_destroy_write_struct(&png, nullptr);
        throw Error(Error::Kind::System, "out of memory writing '" + path + "'");
    }
    const bool failed = !WriteRows(png, info, file.get(), image.width, image.height, gamma,
                                   rows.data());
    png_destroy_write_struct(&png, &info);
    if (failed || std::fflush(file.get()) != 0)
        ThrowSystemError("cannot write '" + path + "'" + (message.empty() ? "" : ": " + message));
}

std::vector<std::uint8_t> ReadPng(const std::string& path, int& width, int& height) {
    FilePtr file(std::fopen(path.c_str(), "rb"));
    if (!file) ThrowSystemError("cannot open '" + path + "'");
    std::string message;
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &message, PngError, PngWarning);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!info) {
        png_destroy_read_struct(&png, nullptr, nullptr);
        throw Error(Error::Kind::System, "out of memory reading '" + path + "'");
    }
    std::vector<std::uint8_t> out;
    std::vector<png_bytep> rows;
    const bool failed = !ReadRows(png, info, file.get(), &out, &rows, &width, &height);
    png_destroy_read_struct(&png, &info, nullptr);
    if (failed) ThrowUserError(FileLoc{path}, "not a readable PNG file: " + message);
    return out;
}

}  // namespace rt
