// SPDX-License-Identifier: MIT
#include "image/compare.h"

#include <cmath>
#include <limits>

#include "core/error.h"

namespace rt {

CompareResult CompareImages(const Image& a, const Image& b, const CompareOptions& options) {
    if (a.width != b.width || a.height != b.height) {
        ThrowUserError("cannot compare images of different sizes: " + std::to_string(a.width) +
                       "x" + std::to_string(a.height) + " and " + std::to_string(b.width) + "x" +
                       std::to_string(b.height));
    }
    CompareResult result;
    const std::size_t n = a.PixelCount();
    if (n == 0)
        return result;

    std::vector<double> ya(n), yb(n);
    double sumA = 0, sumB = 0;
    for (std::size_t i = 0; i < n; ++i) {
        ya[i] = Bright(Rgb(a.rgb[3 * i], a.rgb[3 * i + 1], a.rgb[3 * i + 2]));
        yb[i] = Bright(Rgb(b.rgb[3 * i], b.rgb[3 * i + 1], b.rgb[3 * i + 2]));
        if (std::isfinite(ya[i]))
            sumA += std::fabs(ya[i]);
        if (std::isfinite(yb[i]))
            sumB += std::fabs(yb[i]);
    }
    const double meanLevel = 0.5 * (sumA + sumB) / static_cast<double>(n);
    result.floor = std::max(options.floorFraction * meanLevel, 1e-30);

    double sumSq = 0;
    for (std::size_t i = 0; i < n; ++i) {
        double d;
        if (!std::isfinite(ya[i]) || !std::isfinite(yb[i])) {
            d = std::numeric_limits<double>::infinity();
        } else {
            const double level = 0.5 * (std::fabs(ya[i]) + std::fabs(yb[i]));
            d = std::fabs(ya[i] - yb[i]) / std::max(level, result.floor);
        }
        sumSq += d * d;
        if (d > result.maxRelative || (i == 0 && d >= result.maxRelative)) {
            result.maxRelative = d;
            result.maxX = static_cast<int>(i % static_cast<std::size_t>(a.width));
            result.maxY = static_cast<int>(i / static_cast<std::size_t>(a.width));
        }
    }
    result.rmsRelative = std::sqrt(sumSq / static_cast<double>(n));
    return result;
}

}  // namespace rt
