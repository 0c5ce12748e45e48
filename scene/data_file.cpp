// SPDX-License-Identifier: MIT
//
// Radiance's data.c (getdata, getpict, datavalue) and the word reader of
// fgetval.c, as radiance-functions.md §11.6-11.7 describe them and real
// Radiance 5.4a behaves (tests/scene/data_file_test.cpp,
// tests/data/datafiles/).
#include "scene/data_file.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>

#include "core/error.h"
#include "scene/fgetval.h"
#include "image/hdr.h"

namespace rt {
namespace {

using fgetval::IsDigit;
using fgetval::IsIntegerWord;

/// Radiance's isflt(): sign, digits, an optional point and digits (at least
/// one digit in all), an optional exponent with at least one digit. No
/// "inf", "nan" or hexadecimal.
bool IsFloatWord(std::string_view w) {
    std::size_t k = 0;
    if (k < w.size() && (w[k] == '+' || w[k] == '-')) ++k;
    std::size_t digits = 0;
    while (k < w.size() && IsDigit(w[k])) ++k, ++digits;
    if (k < w.size() && w[k] == '.') {
        ++k;
        while (k < w.size() && IsDigit(w[k])) ++k, ++digits;
    }
    if (digits == 0) return false;
    if (k < w.size() && (w[k] == 'e' || w[k] == 'E')) {
        ++k;
        if (k < w.size() && (w[k] == '+' || w[k] == '-')) ++k;
        const std::size_t start = k;
        while (k < w.size() && IsDigit(w[k])) ++k;
        if (k == start) return false;
    }
    return k == w.size();
}

/// The words of a data file as fgetval() sees them (fgetval::Words), with
/// data.c's errors: "unexpected EOF" once the end has been read, else "bad
/// format".
class WordReader {
  public:
    WordReader(std::string_view text, const std::string& path, const std::string& name)
        : words_(text), path_(path), name_(name) {}

    int ReadInt(const char* what) {
        const std::string_view w = Next(what);
        if (!IsIntegerWord(w)) Fail(std::string("expected an integer ") + what, w);
        return fgetval::Atoi(w);
    }

    float ReadFloat(const char* what) {
        const std::string_view w = Next(what);
        if (!IsFloatWord(w)) Fail(std::string("expected a number ") + what, w);
        const std::string word(w);
        return static_cast<float>(std::strtod(word.c_str(), nullptr));
    }

    /// Radiance's scanerr: "unexpected EOF" once the end has been read, else
    /// "bad format".
    [[noreturn]] void Fail(const std::string& detail, std::string_view word = {}) const {
        std::string message = (words_.atEnd() ? "unexpected EOF" : "bad format") +
                              std::string(" in data file \"") + name_ + "\"";
        if (!words_.atEnd()) {
            message += ": " + detail;
            if (!word.empty()) message += ", not \"" + std::string(word.substr(0, 40)) + "\"";
        }
        ThrowUserError(FileLoc{path_, words_.line()}, message);
    }

    int line() const { return words_.line(); }

  private:
    std::string_view Next(const char* what) {
        std::string_view word;
        switch (words_.Next(word)) {
            case fgetval::Words::Status::kWord: return word;
            case fgetval::Words::Status::kTooLong:
                Fail(std::string("word longer than 63 characters ") + what);
            case fgetval::Words::Status::kEnd: break;
        }
        Fail(std::string("missing ") + what);
    }

    fgetval::Words words_;
    const std::string& path_;
    const std::string& name_;
};

/// More values than any text can hold: counts whose product reaches this only
/// end in "unexpected EOF".
constexpr std::uint64_t kMaxValues = std::uint64_t{1} << 62;

/// C's double-to-int conversion as x86-64 performs it: values out of int's
/// range (and NaN) give INT_MIN, which datavalue() then clamps to index 0.
int TruncateToInt(double x) {
    if (!(x > static_cast<double>(INT_MIN) - 1.0 && x < static_cast<double>(INT_MAX) + 1.0)) {
        return INT_MIN;
    }
    return static_cast<int>(x);
}

}  // namespace

DataArray::DataArray(std::vector<DataAxis> axes, std::vector<float> values)
    : axes_(std::move(axes)), values_(std::move(values)), strides_(axes_.size(), 1) {
    // Every index Value() can form must be inside `values`.
    std::uint64_t total = 1;
    bool valid = !axes_.empty() && axes_.size() <= kMaxDataDimensions;
    for (const DataAxis& a : axes_) {
        // One point only on a regular axis: a picture one pixel high or wide
        // (ParseDataFile refuses such axes in data files, as Radiance does).
        valid = valid && (a.count >= 2 || (a.count == 1 && a.points.empty())) &&
                (a.points.empty() || a.points.size() == static_cast<std::size_t>(a.count)) &&
                total <= kMaxValues / static_cast<std::uint64_t>(a.count);
        if (valid) total *= static_cast<std::uint64_t>(a.count);
    }
    if (!valid || total != values_.size()) {
        throw Error(Error::Kind::Internal, "data array of inconsistent size");
    }
    for (std::size_t k = axes_.size(); k-- > 1;) {
        strides_[k - 1] = strides_[k] * static_cast<std::size_t>(axes_[k].count);
    }
}

double DataArray::Value(std::span<const double> point) const {
    return Value(point, 0, 0);
}

double DataArray::Value(std::span<const double> point, int axis, std::size_t offset) const {
    const DataAxis& a = axes_[static_cast<std::size_t>(axis)];
    const double pt = point[static_cast<std::size_t>(axis)];
    if (a.count == 1) {
        // Radiance's arithmetic on a one-pixel axis: x = (pt - org)/siz·0 = 0,
        // i = 0 clamped to n - 2 = -1, so the slab at index -1 (outside the
        // array) gets weight 0 and slab 0 weight 1: the value is constant
        // along the axis, with no fall-off. A coordinate that is not finite
        // makes x NaN there, and the value NaN.
        if (std::isnan((pt - a.origin) / a.span * 0.0)) {
            return std::numeric_limits<double>::quiet_NaN();
        }
        return axis + 1 < dimensions() ? Value(point, axis + 1, offset) : values_[offset];
    }
    double x;
    int i;
    if (a.points.empty()) {
        x = (pt - a.origin) / a.span;
        x *= static_cast<double>(a.count - 1);
        i = TruncateToInt(x);  // toward zero: -0.5 gives 0
        if (i < 0) {
            i = 0;
        } else if (i > a.count - 2) {
            i = a.count - 2;
        }
    } else {
        // Radiance's bisection, for ascending and descending coordinates.
        int lower = 0, upper = a.count;
        if (!(a.span > 0)) std::swap(lower, upper);
        do {
            i = (lower + upper) >> 1;
            if (pt >= a.points[static_cast<std::size_t>(i)]) {
                lower = i;
            } else {
                upper = i;
            }
        } while (i != (lower + upper) >> 1);
        if (i > a.count - 2) i = a.count - 2;
        const float step = a.points[static_cast<std::size_t>(i) + 1] -
                           a.points[static_cast<std::size_t>(i)];  // single precision, as Radiance
        x = i + (pt - a.points[static_cast<std::size_t>(i)]) / step;
    }
    const std::size_t stride = strides_[static_cast<std::size_t>(axis)];
    const std::size_t at0 = offset + static_cast<std::size_t>(i) * stride;
    double y0, y1;
    if (axis + 1 < dimensions()) {
        y0 = Value(point, axis + 1, at0);
        y1 = Value(point, axis + 1, at0 + stride);
    } else {
        y0 = values_[at0];
        y1 = values_[at0 + 1];
    }
    // Linear up to one division beyond the ends, then decaying as 1/distance;
    // the upper branch is deliberately discontinuous, as Radiance's.
    if (x > i + 2) return (2 * y1 - y0) / (x - (i - 1));
    if (x < i - 1) return (2 * y0 - y1) / (i - x);
    return y0 * ((i + 1) - x) + y1 * (x - i);
}

DataArray ParseDataFile(std::string_view text, const std::string& path, const std::string& name) {
    WordReader in(text, path, name);
    const int dims = in.ReadInt("(number of dimensions)");
    if (dims <= 0 || dims > kMaxDataDimensions) {
        ThrowUserError(FileLoc{path, in.line()},
                       "bad number of dimensions for \"" + name + "\" (" + std::to_string(dims) +
                           ", must be 1 to 5)");
    }
    std::vector<DataAxis> axes(static_cast<std::size_t>(dims));
    // The number of values, saturating: a hostile count runs out of words
    // (unexpected EOF) long before anything that size is allocated.
    std::uint64_t total = 1;
    for (DataAxis& a : axes) {
        const float begin = in.ReadFloat("(axis begin)");
        const float end = in.ReadFloat("(axis end)");
        a.count = in.ReadInt("(axis point count)");
        if (a.count < 2) in.Fail("an axis needs at least 2 points");
        total = total > kMaxValues / static_cast<std::uint64_t>(a.count)
                    ? kMaxValues
                    : total * static_cast<std::uint64_t>(a.count);
        a.origin = begin;
        a.span = end - begin;  // float arithmetic, as Radiance's `siz -= org`
        if (a.span == 0) {
            // Irregular axis: the coordinates follow. Radiance requires each
            // consecutive pair to go the same way as the next one; equal
            // neighbours pass that test only in a descending run.
            for (int j = 0; j < a.count; ++j) a.points.push_back(in.ReadFloat("(axis coordinate)"));
            for (std::size_t j = 1; j + 1 < a.points.size(); ++j) {
                if ((a.points[j - 1] < a.points[j]) != (a.points[j] < a.points[j + 1])) {
                    in.Fail("irregular coordinates not monotonic");
                }
            }
            a.origin = a.points.front();
            a.span = a.points.back() - a.points.front();
        }
    }
    std::vector<float> values;
    for (std::uint64_t k = 0; k < total; ++k) values.push_back(in.ReadFloat("(data value)"));
    return DataArray(std::move(axes), std::move(values));
}

std::array<std::shared_ptr<const DataArray>, 3> PictureAsData(const Image& image,
                                                              double pixelAspect) {
    const int xr = image.width, yr = image.height;
    DataAxis v, u;
    v.count = yr;
    u.count = xr;
    if (xr <= yr * pixelAspect) {
        v.span = static_cast<float>(pixelAspect * static_cast<double>(yr) / xr);
        u.span = 1.0f;
    } else {
        v.span = 1.0f;
        u.span = static_cast<float>(static_cast<double>(xr) / yr / pixelAspect);
    }
    std::array<std::vector<float>, 3> channels;
    for (auto& c : channels) c.resize(image.PixelCount());
    for (int row = 0; row < yr; ++row) {      // row 0 at the bottom
        const int y = yr - 1 - row;           // Image: y = 0 is the top row
        for (int x = 0; x < xr; ++x) {
            const std::size_t from = 3 * (static_cast<std::size_t>(y) * xr + x);
            const std::size_t to = static_cast<std::size_t>(row) * xr + x;
            for (int c = 0; c < 3; ++c) channels[c][to] = image.rgb[from + c];
        }
    }
    std::array<std::shared_ptr<const DataArray>, 3> out;
    for (int c = 0; c < 3; ++c) {
        out[c] = std::make_shared<const DataArray>(std::vector<DataAxis>{v, u},
                                                   std::move(channels[c]));
    }
    return out;
}

std::shared_ptr<const DataArray> DataFileCache::Data(const std::string& name,
                                                     const std::string& requestedBy) {
    for (const auto& [key, array] : data_) {
        if (key == name) return array;
    }
    const std::optional<cal::SourceText> file = cal::FindFunctionFile(name, path_);
    if (!file) {
        throw Error(Error::Kind::System,
                    (requestedBy.empty() ? "" : requestedBy + ": ") + "cannot find data file \"" +
                        name + "\"");
    }
    auto array = std::make_shared<const DataArray>(ParseDataFile(file->text, file->name, name));
    data_.emplace_back(name, array);
    return array;
}

std::array<std::shared_ptr<const DataArray>, 3> PictureFileAsData(
    std::istream& in, const std::string& path, const std::string& name,
    const std::string& prefix, long long maxPixels) {
    std::vector<std::string> header;
    Image image;
    try {
        image = ReadHdr(in, path, &header, maxPixels);
    } catch (const Error& e) {
        ThrowUserError(prefix + "bad picture file \"" + name + "\" (" + e.what() + ")");
    }
    // PIXASPECT= lines multiply (Radiance's headaspect()).
    double aspect = 1.0;
    for (const std::string& line : header) {
        if (line.rfind("PIXASPECT=", 0) == 0) aspect *= std::strtod(line.c_str() + 10, nullptr);
    }
    if (!(aspect > 1e-6) || image.width <= 0 || image.height <= 0 ||
        !std::isfinite(aspect)) {
        ThrowUserError(prefix + "bad picture file \"" + name + "\" (pixel aspect ratio or size)");
    }
    return PictureAsData(image, aspect);
}

std::array<std::shared_ptr<const DataArray>, 3> DataFileCache::Picture(
    const std::string& name, const std::string& requestedBy) {
    for (const auto& [key, channels] : pictures_) {
        if (key == name) return channels;
    }
    const std::optional<cal::SourceText> file = cal::FindFunctionFile(name, path_);
    const std::string prefix = requestedBy.empty() ? "" : requestedBy + ": ";
    if (!file) {
        throw Error(Error::Kind::System, prefix + "cannot find picture file \"" + name + "\"");
    }
    std::istringstream in(file->text);
    auto channels = PictureFileAsData(in, file->name, name, prefix, kMaxPicturePixels);
    pictures_.emplace_back(name, channels);
    return channels;
}

std::array<double, 3> EvaluateDataLookup(const DataLookup& lookup, std::span<const double> point,
                                         const cal::Program& program, cal::Context& context) {
    std::array<double, 3> interpolated{0, 0, 0};
    const double vu[2] = {point.size() > 1 ? point[1] : 0.0, point.empty() ? 0.0 : point[0]};
    const std::span<const double> at = lookup.picture ? std::span<const double>(vu) : point;
    for (std::size_t k = 0; k < lookup.arrays.size() && k < 3; ++k) {
        interpolated[k] = lookup.arrays[k]->Value(at);
    }
    std::array<double, 3> result{1, 1, 1};
    for (std::size_t j = 0; j < lookup.functions.size() && j < 3; ++j) {
        const std::size_t own = lookup.arrays.size() == 1 ? 0 : j;
        const std::span<const double> args =
            lookup.argCounts[j] >= 3 ? std::span<const double>(interpolated)
                                     : std::span<const double>(&interpolated[own], 1);
        result[j] = program.Call(lookup.functions[j], args, context);
    }
    return result;
}

}  // namespace rt
