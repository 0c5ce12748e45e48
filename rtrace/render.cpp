// SPDX-License-Identifier: MIT
#include "rtrace/render.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <limits>
#include <numeric>
#include <ostream>

#include "core/conventions.h"
#include "core/error.h"
#include "image/exr.h"
#include "image/hdr.h"
#include "image/png.h"

namespace rt {
namespace {

constexpr const char* kProgram = "rvimage";

bool EndsWith(const std::string& s, std::string_view suffix) {
    return s.size() >= suffix.size() &&
           std::equal(suffix.rbegin(), suffix.rend(), s.rbegin(), [](char lower, char c) {
               return std::tolower(static_cast<unsigned char>(c)) == lower;
           });
}

enum class OutputKind { Exr, Hdr, Png };

std::optional<OutputKind> KindOf(const std::string& path) {
    if (EndsWith(path, ".exr")) return OutputKind::Exr;
    if (EndsWith(path, ".hdr") || EndsWith(path, ".pic")) return OutputKind::Hdr;
    if (EndsWith(path, ".png")) return OutputKind::Png;
    return std::nullopt;
}

int PositiveInt(const std::string& option, const std::string& word) {
    if (!IsIntArgument(word)) ThrowUserError("bad value '" + word + "' for " + option);
    const long v = std::strtol(word.c_str(), nullptr, 10);
    if (v <= 0 || v > 1 << 20) ThrowUserError("bad value '" + word + "' for " + option);
    return static_cast<int>(v);
}

double RealValue(const std::string& option, const std::string& word) {
    if (!IsRealArgument(word)) ThrowUserError("bad value '" + word + "' for " + option);
    return std::strtod(word.c_str(), nullptr);
}

void ParseLayers(const std::string& list, RenderSettings& s) {
    std::size_t start = 0;
    while (start <= list.size()) {
        std::size_t comma = list.find(',', start);
        if (comma == std::string::npos) comma = list.size();
        const std::string name = list.substr(start, comma - start);
        if (name == "indirect") {
            s.indirectLayer = true;
        } else if (name == "records") {
            s.recordsLayer = true;
        } else if (name == "outcome") {
            s.outcomeLayer = true;
        } else if (name == "all") {
            s.indirectLayer = s.recordsLayer = s.outcomeLayer = true;
        } else {
            ThrowUserError("unknown layer '" + name + "' (indirect, records, outcome, all)");
        }
        start = comma + 1;
    }
}

/// SplitMix64: a pixel's jitter depends only on -seed and the pixel, so
/// -n N and repeated runs place every ray identically.
std::uint64_t Mix(std::uint64_t z) {
    z += 0x9e3779b97f4a7c15ULL;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}
/// Radiance's printargs() without the newline: words quoted when they hold
/// blanks. (Not rtrace/output.h's FormatArgs: output.cpp and image/hdr.cpp
/// both define rt::EncodeRgbe, so a program may link only one of them.)
std::string JoinArgs(std::span<const std::string> words) {
    std::string s;
    for (const std::string& w : words) {
        if (!s.empty()) s += ' ';
        const bool blank = std::any_of(w.begin(), w.end(), [](char c) {
            return std::isspace(static_cast<unsigned char>(c)) != 0;
        });
        const bool dq = w.find('"') != std::string::npos;
        const bool sq = w.find('\'') != std::string::npos;
        if (!blank && !dq && !sq) {
            s += w;
        } else {
            const char q = dq ? '\'' : '"';
            s += q + w + q;
        }
    }
    return s;
}

double Unit(std::uint64_t bits) { return static_cast<double>(bits >> 11) * 0x1.0p-53; }

std::size_t AddLayerIndex(Image& image, const std::string& name) {
    if (!image.FindLayer(name)) image.AddLayer(name);
    for (std::size_t i = 0; i < image.layers.size(); ++i)
        if (image.layers[i].name == name) return i;
    return image.layers.size();  // unreachable
}

/// Progress on stderr: a carriage-return-updated bar on a terminal once the
/// render has run a second; with -t N a plain line every N seconds where no
/// bar is drawn.
class Progress {
public:
    Progress(std::ostream& err, std::ostream& msg, bool terminal, int reportSeconds)
        : err_(err), msg_(msg), terminal_(terminal), reportSeconds_(reportSeconds),
          start_(Clock::now()), nextReport_(start_ + std::chrono::seconds(reportSeconds)) {}

    double Seconds() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

    void Update(std::size_t done, std::size_t total) {
        const auto now = Clock::now();
        const double elapsed = Seconds();
        const double fraction = total ? static_cast<double>(done) / static_cast<double>(total) : 1.0;
        if (terminal_ && elapsed >= 1.0 && (now - lastDraw_ >= std::chrono::milliseconds(100))) {
            Draw(fraction, elapsed);
            lastDraw_ = now;
        }
        if (reportSeconds_ > 0 && !shown_ && now >= nextReport_) {
            char line[96];
            std::snprintf(line, sizeof line, "%s: %.1f%% done after %.1f s\n", kProgram,
                          100.0 * fraction, elapsed);
            msg_ << line;
            msg_.flush();
            nextReport_ = now + std::chrono::seconds(reportSeconds_);
        }
    }

    /// Completes the bar (100 %, a newline) if one was drawn.
    void Finish() {
        if (shown_) {
            Draw(1.0, Seconds());
            err_ << '\n';
            err_.flush();
        }
    }

private:
    using Clock = std::chrono::steady_clock;

    void Draw(double fraction, double elapsed) {
        constexpr int kWidth = 40;
        const int filled = static_cast<int>(fraction * kWidth);
        std::string bar(static_cast<std::size_t>(kWidth), '.');
        std::fill(bar.begin(), bar.begin() + std::clamp(filled, 0, kWidth), '#');
        char line[160];
        std::snprintf(line, sizeof line, "\r%s: [%s] %3d%%  %.1f s", kProgram, bar.c_str(),
                      static_cast<int>(100.0 * fraction), elapsed);
        err_ << line;
        err_.flush();
        shown_ = true;
    }

    std::ostream& err_;
    std::ostream& msg_;
    bool terminal_;
    int reportSeconds_;
    Clock::time_point start_;
    Clock::time_point nextReport_;
    Clock::time_point lastDraw_{};
    bool shown_ = false;
};

}  // namespace

RenderCommandLine ParseRenderCommandLine(std::span<const std::string> args,
                                         const WarningSink& warn) {
    if (args.empty()) ThrowUserError("no arguments");
    std::vector<std::string> words{args[0]};
    for (std::size_t i = 1; i < args.size(); ++i) {
        if (!args[i].empty() && (args[i][0] == '@' || args[i][0] == '$')) {
            for (std::string& w : ExpandArgument(args[i])) words.push_back(std::move(w));
        } else {
            words.push_back(args[i]);
        }
    }
    RenderCommandLine cl;
    RenderSettings& s = cl.settings;
    std::vector<std::string> rest{words[0]};
    const std::size_t n = words.size();
    for (std::size_t i = 1; i < n; ++i) {
        const std::string& a = words[i];
        auto value = [&]() -> const std::string& {
            if (i + 1 >= n) ThrowUserError("missing value for " + a);
            return words[++i];
        };
        if (a.size() >= 3 && a[0] == '-' && a[1] == 'v') {
            const std::optional<int> used =
                ParseViewOption(s.view, std::span<const std::string>(words).subspan(i));
            if (used) {
                i += static_cast<std::size_t>(*used);
                continue;
            }
        }
        if (a == "-x") {
            s.xResolution = PositiveInt(a, value());
        } else if (a == "-y") {
            s.yResolution = PositiveInt(a, value());
        } else if (a == "-pa") {
            s.pixelAspect = RealValue(a, value());
            if (s.pixelAspect < 0) ThrowUserError("bad value for -pa");
        } else if (a == "-pj") {
            s.jitter = RealValue(a, value());
            if (s.jitter < 0 || s.jitter > 1) ThrowUserError("-pj must be between 0 and 1");
        } else if (a == "-o") {
            s.outputPath = value();
        } else if (a == "-rscale") {
            s.recordScale = RealValue(a, value());
            if (s.recordScale < 0) ThrowUserError("-rscale must not be negative");
        } else if (a == "-layers") {
            ParseLayers(value(), s);
        } else {
            rest.push_back(a);
        }
    }
    cl.rtrace = ParseCommandLine(rest, warn);
    if (cl.rtrace.action != CommandLine::Action::Render) return cl;
    if (s.outputPath.empty()) ThrowUserError("no output picture (-o out.exr, .hdr or .png)");
    if (!KindOf(s.outputPath))
        ThrowUserError("output '" + s.outputPath + "' must end in .exr, .hdr, .pic or .png");
    if (cl.rtrace.options.outputSpec != "v" && warn)
        warn("-o" + cl.rtrace.options.outputSpec + " ignored: the picture holds values (-ov)");
    return cl;
}

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
                 const RenderSettings& settings, unsigned seed, double accuracy,
                 std::size_t batchSize, const RenderProgress& progress, const WarningSink& warn) {
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
            const std::uint64_t bits = Mix((static_cast<std::uint64_t>(seed) << 40) ^ p);
            px += jitter * (Unit(bits) - 0.5);
            py += jitter * (Unit(Mix(bits)) - 0.5);
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

int RunRender(std::span<const std::string> args, std::ostream& out, std::ostream& err,
              const RunEnvironment& env, bool errIsTerminal) {
    std::ostream* msg = &err;
    std::ofstream errorFile;
    bool warningsOn = true;
    const WarningSink warn = [&](const std::string& text) {
        if (warningsOn) {
            *msg << kProgram << ": warning - " << text << '\n';
            msg->flush();
        }
    };
    auto report = [&](const char* kind, const std::string& text) {
        *msg << kProgram << ": " << kind << " - " << text << '\n';
        msg->flush();
    };
    try {
        RenderCommandLine cl = ParseRenderCommandLine(args, warn);
        RtraceOptions& opt = cl.rtrace.options;
        warningsOn = opt.warnings;
        if (cl.rtrace.action == CommandLine::Action::PrintVersion) {
            out << kVersionString << '\n';
            return 0;
        }
        if (cl.rtrace.action == CommandLine::Action::PrintDefaults) {
            out << FormatDefaults(opt);
            return 0;
        }
        if (!opt.errorFile.empty()) {
            errorFile.open(opt.errorFile, std::ios::app);
            if (!errorFile) ThrowSystemError("cannot open error file '" + opt.errorFile + "'");
            msg = &errorFile;
        }
        opt.shading.seed = static_cast<unsigned long long>(static_cast<unsigned>(opt.seed));
        const RenderSettings& s = cl.settings;
        const PreparedView view = SetupView(s.view);
        int width = s.xResolution, height = s.yResolution;
        double aspect = s.pixelAspect;
        NormalizeAspect(ViewAspect(view), aspect, width, height);
        if (width <= 0 || height <= 0) ThrowUserError("picture resolution too small");
        const OutputKind kind = *KindOf(s.outputPath);
        if (kind == OutputKind::Hdr && (s.indirectLayer || s.outcomeLayer || s.recordsLayer))
            warn("layers are written only to OpenEXR (.exr) or, for records, PNG");

        if (!env.makeEvaluator) throw Error(Error::Kind::Internal, "no renderer configured");
        std::unique_ptr<RayEvaluator> evaluator = env.makeEvaluator(cl.rtrace.sceneFiles, opt, warn);
        Progress progress(err, *msg, errIsTerminal, opt.reportSeconds);
        const std::size_t batch = 1024 * static_cast<std::size_t>(std::max(1, opt.processes));
        const Image image = RenderView(
            *evaluator, view, width, height, s, static_cast<unsigned>(opt.seed),
            opt.ambient.accuracy, batch,
            [&](std::size_t done, std::size_t total) { progress.Update(done, total); }, warn);
        evaluator->Finish();
        progress.Finish();

        const std::string commandLine = JoinArgs(args);
        std::string viewText = FormatView(s.view);
        if (!viewText.empty() && viewText.front() == ' ') viewText.erase(0, 1);
        switch (kind) {
            case OutputKind::Exr:
                WriteExr(s.outputPath, image,
                         {{"commandLine", commandLine},
                          {"software", std::string(kLazyradVersion)},
                          {"view", viewText}});
                break;
            case OutputKind::Hdr:
                WriteHdr(s.outputPath, image,
                         {commandLine, "SOFTWARE= " + std::string(kLazyradVersion),
                          "VIEW= " + viewText});
                break;
            case OutputKind::Png: {
                const double exposure = AutoExposure(image);
                WritePng(s.outputPath, image, exposure);
                if (s.recordsLayer) {
                    std::string path = s.outputPath.substr(0, s.outputPath.size() - 4);
                    WritePng(path + "_records.png", RecordsPicture(image, exposure), 1.0);
                }
                break;
            }
        }
        if (opt.reportSeconds > 0) {
            const std::string summary = evaluator->Summary();
            char tail[96];
            std::snprintf(tail, sizeof tail, "%s%dx%d pixels in %.2f s", summary.empty() ? "" : ", ",
                          width, height, progress.Seconds());
            *msg << kProgram << ": " << summary << tail << '\n';
            msg->flush();
        }
    } catch (const Error& e) {
        report(e.kind() == Error::Kind::User     ? "fatal"
               : e.kind() == Error::Kind::System ? "system"
                                                 : "internal",
               e.what());
        return e.ExitCode();
    } catch (const std::exception& e) {
        report("internal", e.what());
        return 3;
    }
    return 0;
}

}  // namespace rt
