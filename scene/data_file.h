// SPDX-License-Identifier: MIT
//
// Radiance's interpolated data (src/rt/data.c; radiance-functions.md §11.6,
// §11.7): N-dimensional arrays from `.dat` text files and Radiance pictures
// read as three 2-D arrays, with Radiance's interpolation and extrapolation
// (datavalue). Used by brightdata and colordata, and colorpict; shaped so that
// texdata, mixdata and mixpict can share it (DataLookup).
//
//   const DataArray d = ParseDataFile(text, "lib/x.dat", "x.dat");
//   double v = d.Value(std::array{theta, phi});
//
// Parsing is a pure function over the file's text. Arrays are immutable once
// built and shared read-only between threads.
#pragma once

#include <array>
#include <cstdint>
#include <iosfwd>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "cal/program.h"
#include "cal/search.h"

namespace rt {

struct Image;

/// Radiance's MAXDDIM: a data file has 1 to this many dimensions.
inline constexpr int kMaxDataDimensions = 5;

/// One axis of a data array (Radiance's struct dadim). Coordinates are single
/// precision as in Radiance, and its arithmetic on them stays single precision
/// where Radiance's does (the span, the step between irregular coordinates).
struct DataAxis {
    float origin = 0;         // first coordinate (regular: begin; irregular: p[0])
    float span = 0;           // last coordinate minus the first; negative when descending
    int count = 0;            // number of grid points, >= 2 (1: a picture one pixel high or wide)
    std::vector<float> points;  // irregular axes: every coordinate; empty when regular
};

class DataArray {
  public:
    /// `axes` outermost first; `values` has the product of their counts,
    /// the last axis varying fastest.
    DataArray(std::vector<DataAxis> axes, std::vector<float> values);

    int dimensions() const { return static_cast<int>(axes_.size()); }
    const std::vector<DataAxis>& axes() const { return axes_; }
    const std::vector<float>& values() const { return values_; }

    /// Radiance's datavalue(): multilinear interpolation at `point`
    /// (dimensions() coordinates), linear extrapolation up to one division
    /// beyond either end, then a harmonic decay (discontinuous at the upper
    /// side, radiance-functions.md §15 item 10).
    double Value(std::span<const double> point) const;

  private:
    double Value(std::span<const double> point, int axis, std::size_t offset) const;

    std::vector<DataAxis> axes_;
    std::vector<float> values_;
    std::vector<std::size_t> strides_;  // values per step along each axis
};

/// Parses a `.dat` file's text. `path` (the file opened) and the line number
/// start error messages; `name` (as the scene wrote it) is quoted in them as
/// Radiance does: "path:3: bad format in data file \"name\": ...",
/// "unexpected EOF in data file", "bad number of dimensions for". Throws
/// rt::Error (User); never allocates more than the text can fill.
DataArray ParseDataFile(std::string_view text, const std::string& path, const std::string& name);

/// A Radiance picture as data (getpict): red, green and blue arrays with axis
/// 0 vertical (row 0 at the bottom) and axis 1 horizontal, both from 0, the
/// shorter side spanning 1 and the first and last pixel centres on the range
/// ends. `pixelAspect` is the product of the header's PIXASPECT values.
std::array<std::shared_ptr<const DataArray>, 3> PictureAsData(const Image& image,
                                                              double pixelAspect);

/// A picture file's bytes as colorpict reads them: ReadHdr (at most
/// `maxPixels` pixels), the product of the header's PIXASPECT= values, then
/// PictureAsData. Throws rt::Error (User) `<prefix>bad picture file "name"
/// (<the reader's message>)`, and `(pixel aspect ratio or size)` for an
/// aspect that is not a positive finite number.
std::array<std::shared_ptr<const DataArray>, 3> PictureFileAsData(
    std::istream& in, const std::string& path, const std::string& name,
    const std::string& prefix, long long maxPixels);

/// Data files and pictures of one scene, each loaded once (keyed by the name
/// as written, as Radiance's table is) and found on RAYPATH. Loading is not
/// thread-safe; the arrays it hands out are immutable.
class DataFileCache {
  public:
    explicit DataFileCache(cal::SearchPath path) : path_(std::move(path)) {}

    /// Throws rt::Error: System `cannot find data file "name"` (prefixed by
    /// `requestedBy`), or the parse errors of ParseDataFile.
    std::shared_ptr<const DataArray> Data(const std::string& name, const std::string& requestedBy);
    /// Throws rt::Error: `cannot find picture file "name"`, `bad picture
    /// file "path": ...`.
    std::array<std::shared_ptr<const DataArray>, 3> Picture(const std::string& name,
                                                            const std::string& requestedBy);

  private:
    cal::SearchPath path_;
    std::vector<std::pair<std::string, std::shared_ptr<const DataArray>>> data_;
    std::vector<std::pair<std::string, std::array<std::shared_ptr<const DataArray>, 3>>> pictures_;
};

/// The data side of the *data and *pict modifiers (radiance-functions.md
/// §11.2): the arrays interpolated at the modifier's coordinates and the
/// named functions applied to the results. brightdata and mixdata: one array,
/// one function of one argument. colordata: three arrays and three
/// functions; colorpict: a picture's three channels and three functions.
/// Each function takes either all three interpolated values (argCounts 3:
/// texdata, mixpict, and colordata/colorpict functions of >= 3 parameters)
/// or only its own channel's value.
struct DataLookup {
    std::vector<std::shared_ptr<const DataArray>> arrays;  // 1 or 3
    std::vector<cal::Function> functions;                  // 1 or 3
    std::vector<int> argCounts;                            // per function: 1 or 3
    /// The arrays are a picture's: the coordinates come as (u, v), the
    /// arrays' axes are (vertical, horizontal).
    bool picture = false;
};

/// Interpolates every array at `point` and applies the functions: result k
/// is function k's value (unused entries are 1). Math errors set the
/// context's flag as any evaluation does.
std::array<double, 3> EvaluateDataLookup(const DataLookup& lookup, std::span<const double> point,
                                         const cal::Program& program, cal::Context& context);

}  // namespace rt
