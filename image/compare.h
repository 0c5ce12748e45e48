// SPDX-License-Identifier: MIT
//
// Picture comparison for golden tests, in the spirit of Radiance's radcompare:
// per-pixel relative differences of luminance, summarised as an RMS and a maximum.
//
// Definition. For pixel i, Y = 0.265·R + 0.670·G + 0.065·B (Radiance's bright()),
//   dᵢ = |Ya,i − Yb,i| / max( (|Ya,i| + |Yb,i|)/2 , floor ),
//   floor = floorFraction · (mean|Ya| + mean|Yb|)/2   (but at least 1e-30),
// so the measure is symmetric in a and b, and black or nearly black pixels are
// judged against a fraction of the image's average level instead of against
// zero. rms = sqrt(mean dᵢ²), max = maxᵢ dᵢ. A non-finite value in either image
// makes that pixel's dᵢ infinite.
#pragma once

#include "image/image.h"

namespace rt {

struct CompareOptions {
    double floorFraction = 0.01;  // absolute floor, as a fraction of the mean luminance
};

struct CompareResult {
    double rmsRelative = 0;  // sqrt(mean dᵢ²), dimensionless
    double maxRelative = 0;  // max dᵢ
    int maxX = 0, maxY = 0;  // pixel of the maximum, y = 0 top row
    double floor = 0;        // the luminance floor that was used
};

/// Throws rt::Error when the sizes differ.
[[nodiscard]] CompareResult CompareImages(const Image& a, const Image& b,
                                          const CompareOptions& options = {});

}  // namespace rt
