// SPDX-License-Identifier: MIT
#include "rvimage/picture.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <vector>

#include "core/conventions.h"
#include "core/error.h"
#include "core/random.h"

namespace rt {
namespace {

/// Uniform in [0, 1) from the top 53 bits.
double Unit(std::uint64_t bits) { return static_cast<double>(bits >> 11) * 0x1.0p-53; }

std::size_t AddLayerIndex(Image& image, const std::string& name) {
    if (!image.FindLayer(name)) image.AddLayer(name);
    for (std::size_t i = 0; i < image.layers.size(); ++i)
        if (image.layers[i].name == name) return i;
    return image.layers.size();  // unreachable
}

}  // namespace

Rgb RecordLevelColour(int level) {
    switch (level) {
        case 0: return {1, 0, 0};
        case 1: return {0, 1, 0};
        case 2: return {0, 0.3, 1};
        case 3: return {1, 1, 0};
        case 4: return {1, 0, 1};
        default: return {0, 1, 1};
    }
}

std::optional<Vec3> ProjectToView(const PreparedView& pv, const Vec3& p) {
    const View& v = pv.view;
    Vec3 disp = p - v.vp;
    const double depth = Dot(disp, v.vd);
    if (v.type == ViewType::Perspective) {
        if (depth <= 1e-9) return std::nullopt;
        disp = disp / depth;
    } else if (v.type != ViewType::Parallel) {
        return std::nullopt;
    }
    return Vec3(Dot(disp, pv.hvec) / pv.hn2 + 0.5 - v.vs, Dot(disp, pv.vvec) / pv.vn2 + 0.5 - v.vl,
                depth);
}

std::size_t DrawRecords(Image& image, const PreparedView& view,
                        std::span<const AmbientRecord> records, double accuracy,
                        double scale, std::span<const Vec3> hitPoints,
                        const WarningSink& warn) {
    const std::size_t li[3] = {AddLayerIndex(image, "records.R"), AddLayerIndex(image, "records.G"),
                               AddLayerIndex(image, "records.B")};
    const ViewType type = view.view.type;
    if (type != ViewType::Perspective && type != ViewType::Parallel) {
        if (warn && !records.empty())
            warn("records layer: only perspective (-vtv) and parallel (-vtl) views; left black");
        return 0;
    }
    const int w = image.width, h = image.height;
    if (hitPoints.size() != image.PixelCount())
        throw Error(Error::Kind::Internal, "DrawRecords: hit points do not match the image");
    const double a = (accuracy > 0 ? accuracy : 1.0) * std::max(scale, 0.0);

    std::vector<std::size_t> order(records.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) {
        return records[x].level > records[y].level;
    });

    auto index = [w](int x, int y) {
        return static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x);
    };
    auto paint = [&](std::size_t p, const Rgb& c) {
        image.layers[li[0]].values[p] = static_cast<float>(c.r);
        image.layers[li[1]].values[p] = static_cast<float>(c.g);
        image.layers[li[2]].values[p] = static_cast<float>(c.b);
    };

    std::size_t drawn = 0;
    for (std::size_t k : order) {
        const AmbientRecord& r = records[k];
        const double rho0 = a * r.radius[0], rho1 = a * r.radius[1];
        const double reach = std::max(rho0, rho1);
        const std::optional<Vec3> centre = ProjectToView(view, r.position);
        if (!centre) continue;
        // The pixel sees the record's surface when its hit point lies in the
        // record's plane: a relative tolerance of 2e-4 of the viewing distance
        // (1.6 mm at 8 m) keeps a lamp 1 cm below the ceiling from showing
        // the ceiling's records.
        const double tolerance = 2e-4 * Length(r.position - view.view.vp) + 1e-6;
        auto onSurface = [&](std::size_t p, Vec3* offset) {
            const Vec3 e = hitPoints[p] - r.position;
            if (!std::isfinite(e.x) || std::abs(Dot(e, r.normal)) > tolerance) return false;
            *offset = e;
            return true;
        };
        // Pixel box of the disc: project the corners of its bounding cube.
        double x0 = centre->x, x1 = centre->x, y0 = centre->y, y1 = centre->y;
        bool whole = false;
        for (int c = 0; c < 8 && reach > 0; ++c) {
            const Vec3 corner = r.position + Vec3(c & 1 ? reach : -reach, c & 2 ? reach : -reach,
                                                  c & 4 ? reach : -reach);
            const std::optional<Vec3> q = ProjectToView(view, corner);
            if (!q) {
                whole = true;
                break;
            }
            x0 = std::min(x0, q->x), x1 = std::max(x1, q->x);
            y0 = std::min(y0, q->y), y1 = std::max(y1, q->y);
        }
        int px0 = 0, px1 = w - 1, py0 = 0, py1 = h - 1;
        if (!whole) {
            if (x1 < 0 || x0 > 1 || y1 < 0 || y0 > 1) continue;
            px0 = std::max(0, static_cast<int>(std::floor(x0 * w)) - 1);
            px1 = std::min(w - 1, static_cast<int>(std::ceil(x1 * w)) + 1);
            py0 = std::max(0, static_cast<int>(std::floor((1 - y1) * h)) - 1);
            py1 = std::min(h - 1, static_cast<int>(std::ceil((1 - y0) * h)) + 1);
        }
        const bool anisotropic = Dot(r.uAxis, r.uAxis) > 0.5;
        const Vec3 u = r.uAxis, v = anisotropic ? r.VAxis() : Vec3();
        const Rgb colour = RecordLevelColour(r.level);
        bool any = false;
        for (int y = py0; y <= py1 && reach > 0; ++y) {
            for (int x = px0; x <= px1; ++x) {
                Vec3 e;
                if (!onSurface(index(x, y), &e)) continue;
                double d2;
                if (anisotropic) {
                    const double eu = Dot(e, u) / rho0, ev = Dot(e, v) / rho1;
                    d2 = eu * eu + ev * ev;
                } else {
                    d2 = Dot(e, e) / (rho0 * rho0);
                }
                if (d2 > 1.0) continue;
                paint(index(x, y), colour);
                any = true;
            }
        }
        if (!any) {
            // Smaller than a pixel: a dot where the centre falls, if that
            // pixel sees the record's surface.
            const int cx = static_cast<int>(std::floor(centre->x * w));
            const int cy = static_cast<int>(std::floor((1 - centre->y) * h));
            Vec3 e;
            if (cx >= 0 && cx < w && cy >= 0 && cy < h && onSurface(index(cx, cy), &e)) {
                paint(index(cx, cy), colour);
                any = true;
            }
        }
        if (any) ++drawn;
    }
    return drawn;
}

Image RenderView(RayEvaluator& evaluator, const PreparedView& view, int width, int height,
                 const PictureSettings& settings, unsigned seed, double accuracy,
                 std::size_t batchSize, const PictureProgress& progress, const WarningSink& warn) {
    Image image(width, height);
    const std::size_t total = image.PixelCount();
    std::size_t indirect[3] = {0, 0, 0}, outcome = 0;
    if (settings.indirectLayer) {
        indirect[0] = AddLayerIndex(image, "indirect.R");
        indirect[1] = AddLayerIndex(image, "indirect.G");
        indirect[2] = AddLayerIndex(image, "indirect.B");
    }
    if (settings.outcomeLayer) outcome = AddLayerIndex(image, "outcome");
    // Where each pixel's ray first hit a surface (infinite on a miss), for the records layer.
    constexpr double kInf = std::numeric_limits<double>::infinity();
    std::vector<Vec3> hit(settings.recordsLayer ? total : 0, Vec3(kInf, kInf, kInf));

    batchSize = std::max<std::size_t>(1, batchSize);
    std::vector<RayQuery> batch;
    std::vector<std::size_t> pixelOf;
    std::vector<RayResult> results;
    batch.reserve(batchSize);
    auto flush = [&](std::size_t done) {
        results.resize(batch.size());
        evaluator.TraceBatch(batch, results);
        for (std::size_t i = 0; i < batch.size(); ++i) {
            const std::size_t p = pixelOf[i];
            const RayResult& r = results[i];
            image.rgb[3 * p] = static_cast<float>(r.value.r);
            image.rgb[3 * p + 1] = static_cast<float>(r.value.g);
            image.rgb[3 * p + 2] = static_cast<float>(r.value.b);
            if (settings.recordsLayer && r.firstLength < kFhuge) hit[p] = r.point;
            if (settings.indirectLayer) {
                image.layers[indirect[0]].values[p] = static_cast<float>(r.indirectIrradiance.r);
                image.layers[indirect[1]].values[p] = static_cast<float>(r.indirectIrradiance.g);
                image.layers[indirect[2]].values[p] = static_cast<float>(r.indirectIrradiance.b);
            }
            if (settings.outcomeLayer)
                image.layers[outcome].values[p] = static_cast<float>(static_cast<int>(r.ambientOutcome));
        }
        batch.clear();
        pixelOf.clear();
        if (progress) progress(done, total);
    };

    const double jitter = settings.jitter;
    for (std::size_t p = 0; p < total; ++p) {
        const int x = static_cast<int>(p % static_cast<std::size_t>(width));
        const int y = static_cast<int>(p / static_cast<std::size_t>(width));
        double px = x + 0.5, py = (height - 1 - y) + 0.5;  // view y points up
        if (jitter > 0) {
            // A pixel's jitter depends only on -seed and the pixel, so -n N
            // and repeated runs place every ray identically.
            const std::uint64_t bits = MixSeed((static_cast<std::uint64_t>(seed) << 40) ^ p, 0);
            px += jitter * (Unit(bits) - 0.5);
            py += jitter * (Unit(MixSeed(bits, 0)) - 0.5);
        }
        const std::optional<CameraRay> ray = ViewRay(view, px / width, py / height);
        if (!ray) continue;
        batch.push_back({ray->origin, ray->direction, ray->maxDistance > 0 ? ray->maxDistance : 0.0,
                         static_cast<std::uint64_t>(p)});
        pixelOf.push_back(p);
        if (batch.size() >= batchSize) flush(p + 1);
    }
    flush(total);

    if (settings.recordsLayer) {
        const std::vector<AmbientRecord> records = evaluator.CacheRecords();
        DrawRecords(image, view, records, accuracy, settings.recordScale, hit, warn);
    }
    return image;
}

Image RecordsPicture(const Image& rendered, double exposure) {
    const ImageLayer* layer[3] = {rendered.FindLayer("records.R"), rendered.FindLayer("records.G"),
                                  rendered.FindLayer("records.B")};
    if (!layer[0] || !layer[1] || !layer[2])
        throw Error(Error::Kind::Internal, "RecordsPicture: no records layers");
    Image out(rendered.width, rendered.height);
    for (std::size_t p = 0; p < rendered.PixelCount(); ++p) {
        const Rgb c(rendered.rgb[3 * p], rendered.rgb[3 * p + 1], rendered.rgb[3 * p + 2]);
        const double y = std::clamp(exposure * Bright(c), 0.0, 1.0);
        const double grey = 0.35 * (std::isfinite(y) ? y : 0.0);
        const Rgb over(layer[0]->values[p], layer[1]->values[p], layer[2]->values[p]);
        const bool marked = over.r > 0 || over.g > 0 || over.b > 0;
        const double keep = marked ? 0.25 : 1.0, add = marked ? 0.75 : 0.0;
        out.rgb[3 * p] = static_cast<float>(keep * grey + add * over.r);
        out.rgb[3 * p + 1] = static_cast<float>(keep * grey + add * over.g);
        out.rgb[3 * p + 2] = static_cast<float>(keep * grey + add * over.b);
    }
    return out;
}

}  // namespace rt
