// SPDX-License-Identifier: MIT
//
// rvimage's picture: a Radiance view rendered with the rtrace renderer, as
// Radiance's rpict does (one ray per pixel through its centre, optionally
// jittered; no adaptive sampling), plus layers that show what the irradiance
// cache did:
//   indirect  indirect.R/G/B: indirect irradiance at the first surface (W/m²)
//   outcome   one channel: 0 none, 1 interpolated, 2 extrapolated,
//             3 computed (new hemisphere), 4 fallback (-av)
//   records   records.R/G/B: every cache record's validity disc (radius × -aa)
//             drawn on its surface where visible, coloured by level
//
//   Image img = RenderView(*evaluator, SetupView(settings.view), w, h, settings, ...);
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <string>

#include "ambient/record.h"
#include "core/diagnostics.h"
#include "core/rgb.h"
#include "core/vecmath.h"
#include "image/image.h"
#include "rtrace/ray_evaluator.h"
#include "view/view.h"

namespace rt {

/// Values of the "outcome" layer (RayResult::AmbientOutcome as a float).
inline constexpr float kOutcomeNone = 0, kOutcomeInterpolated = 1, kOutcomeExtrapolated = 2,
                       kOutcomeComputed = 3, kOutcomeFallback = 4;

/// What rvimage adds to rtrace's options.
struct PictureSettings {
    View view;                  // -vf -vt? -vp -vd -vu -vh -vv -vo -va -vs -vl
    int xResolution = 512;      // -x: maximum width in pixels (rpict's default)
    int yResolution = 512;      // -y: maximum height
    double pixelAspect = 1.0;   // -pa: pixel height/width; 0 keeps -x and -y as given
    double jitter = 0.0;        // -pj: fraction of a pixel the ray may move, [0, 1]
    std::string outputPath;     // -o: .exr, .hdr/.pic or .png (chosen by extension)
    bool indirectLayer = false;  // -layers indirect
    bool recordsLayer = false;   // -layers records
    bool outcomeLayer = false;   // -layers outcome
    double recordScale = 1.0;    // -rscale: records drawn with radius scale × -aa × radius;
                                 // 1 is the disc where the record alone may be used, 0 dots
};

/// Called after each batch with pixels done and the total.
using PictureProgress = std::function<void(std::size_t done, std::size_t total)>;

/// Traces one ray per pixel (the pixel centre, moved by up to ±jitter/2 pixel
/// with a generator seeded from -seed and the pixel, so runs repeat) through
/// `evaluator` in batches of `batchSize` rays, top row first. Pixels outside
/// the projection stay black. Adds the layers `settings` asks for.
[[nodiscard]] Image RenderView(RayEvaluator& evaluator, const PreparedView& view, int width,
                               int height, const PictureSettings& settings, unsigned seed,
                               double accuracy, std::size_t batchSize,
                               const PictureProgress& progress, const WarningSink& warn);

/// Level colours of the records layer: 0 red, 1 green, 2 blue, 3 yellow,
/// 4 magenta, 5 and deeper cyan.
[[nodiscard]] Rgb RecordLevelColour(int level);

/// Radiance's viewloc() for perspective and parallel views: image coordinates
/// (x right, y up, [0,1] inside the picture) and the distance from the view
/// point along the view direction in z. std::nullopt behind the viewer or for
/// the other view types.
[[nodiscard]] std::optional<Vec3> ProjectToView(const PreparedView& view, const Vec3& p);

/// Draws each record's validity disc (the ellipse radius[0..1] × accuracy ×
/// scale around its position, in its plane) into layers records.R/G/B of
/// `image` (added if missing), on the pixels that see it: those whose first
/// hit point (`hitPoints`, top row first, non-finite on a miss) lies in the
/// record's plane (within 2e-4 of the viewing distance) and inside the disc.
/// A disc that covers no pixel is drawn as one pixel where its centre falls.
/// Deeper levels are drawn first, so level 0 is on top. Returns the number of
/// records that left at least one pixel; warns once for view types other than
/// perspective and parallel, and draws nothing then.
std::size_t DrawRecords(Image& image, const PreparedView& view,
                        std::span<const AmbientRecord> records, double accuracy,
                        double scale, std::span<const Vec3> hitPoints,
                        const WarningSink& warn);

/// The picture for documentation: the rendering tone-mapped to grey (×0.6),
/// with the records layer's colours laid over it; already display-linear, to
/// be written with exposure 1. Requires the records layers.
[[nodiscard]] Image RecordsPicture(const Image& rendered, double exposure);

}  // namespace rt
