// SPDX-License-Identifier: MIT
#include "rvimage/rvimage.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
#include <sstream>

#include "core/error.h"
#include "image/exr.h"
#include "image/hdr.h"
#include "image/png.h"
#include "rtrace/scene_evaluator.h"

namespace rt {
namespace {

const std::string kCornell = std::string(RT_SOURCE_DIR) + "/scenes/cornell/";

std::string TempPath(const std::string& name) {
    return (std::filesystem::temp_directory_path() /
            ("rvimage_test_" + std::to_string(getpid()) + "_" + name))
        .string();
}

RunEnvironment SceneEnvironment() {
    RunEnvironment env;
    env.makeEvaluator = [](const std::vector<std::string>& files, const RtraceOptions& options,
                           const WarningSink& warn) {
        return MakeSceneEvaluator(files, options, warn, "");
    };
    return env;
}

int Render(std::vector<std::string> args, std::string* errText = nullptr) {
    args.insert(args.begin(), "rvimage");
    std::ostringstream out, err;
    const int status = RunRvimage(args, out, err, SceneEnvironment(), false);
    if (errText) *errText = err.str();
    return status;
}

/// Answers every ray with its own pixel index as the value and direction.z as
/// the hit distance; remembers the rays.
class FakeEvaluator final : public RayEvaluator {
public:
    RayResult TraceInput(const Vec3& org, const Vec3& dir, double, std::uint64_t index) override {
        rays.push_back({org, dir, 0, index});
        RayResult r;
        r.value = Rgb(static_cast<double>(index), 0, 0);
        r.firstLength = 10;
        r.ambientOutcome = RayResult::AmbientOutcome::Extrapolated;
        r.indirectIrradiance = Rgb(1, 2, 3);
        return r;
    }
    void SetTraceCallback(std::function<void(const RayResult&)>, bool) override {}
    std::vector<RayQuery> rays;
};

TEST(RvimageCommandLine, PullsOutViewAndPictureOptions) {
    const std::vector<std::string> args = {"rvimage", "-ab",   "2",       "-vp",  "1", "2", "3",
                                           "-vh",     "30",    "-x",      "64",   "-y", "32",
                                           "-pj",     "0.5",   "-o",      "a.exr", "-layers",
                                           "indirect,outcome", "-n",      "2",    "scene.rad"};
    const RvimageCommandLine cl = ParseRvimageCommandLine(args, {});
    EXPECT_EQ(cl.settings.view.vp, Vec3(1, 2, 3));
    EXPECT_EQ(cl.settings.view.vh, 30);
    EXPECT_EQ(cl.settings.xResolution, 64);
    EXPECT_EQ(cl.settings.yResolution, 32);
    EXPECT_EQ(cl.settings.jitter, 0.5);
    EXPECT_EQ(cl.settings.outputPath, "a.exr");
    EXPECT_TRUE(cl.settings.indirectLayer);
    EXPECT_TRUE(cl.settings.outcomeLayer);
    EXPECT_FALSE(cl.settings.recordsLayer);
    EXPECT_EQ(cl.rtrace.options.ambient.bounces, 2);
    EXPECT_EQ(cl.rtrace.options.processes, 2);
    EXPECT_EQ(cl.rtrace.options.xResolution, 0);  // -x never reaches rtrace
    EXPECT_EQ(cl.rtrace.sceneFiles, std::vector<std::string>{"scene.rad"});
}

TEST(RvimageCommandLine, RejectsBadInput) {
    auto parse = [](std::vector<std::string> args) {
        args.insert(args.begin(), "rvimage");
        return ParseRvimageCommandLine(args, {});
    };
    EXPECT_THROW(parse({"s.rad"}), Error);                             // no -o
    EXPECT_THROW(parse({"-o", "a.tif", "s.rad"}), Error);              // unknown format
    EXPECT_THROW(parse({"-o", "a.exr", "-layers", "depth", "s.rad"}), Error);
    EXPECT_THROW(parse({"-o", "a.exr", "-x", "0", "s.rad"}), Error);
    EXPECT_THROW(parse({"-o", "a.exr", "-pj", "2", "s.rad"}), Error);
    EXPECT_THROW(parse({"-o", "a.exr"}), Error);                       // no scene
    EXPECT_NO_THROW(parse({"-o", "a.HDR", "s.rad"}));
}

TEST(PlanPicture, FitsTheViewAndNamesBadInput) {
    auto plan = [](std::vector<std::string> args) {
        args.insert(args.begin(), "rvimage");
        return PlanPicture(ParseRvimageCommandLine(args, {}).settings);
    };
    // Radiance's vwrays -vtv -vh 90 -vv 45 -x 100 -y 100 -d: -x 100 -y 41.
    const PicturePlan wide = plan({"-vh", "90", "-vv", "45", "-x", "100", "-y", "100", "-o",
                                   "a.png", "s.rad"});
    EXPECT_EQ(wide.width, 100);
    EXPECT_EQ(wide.height, 41);
    EXPECT_EQ(wide.kind, OutputKind::Png);
    EXPECT_EQ(plan({"-vh", "45", "-vv", "90", "-x", "100", "-y", "100", "-o", "a.pic", "s.rad"})
                  .width,
              41);
    auto message = [&](std::vector<std::string> args) -> std::string {
        try {
            static_cast<void>(plan(std::move(args)));
        } catch (const Error& e) {
            return e.what();
        }
        return "";
    };
    EXPECT_EQ(message({"-vh", "0", "-o", "a.exr", "s.rad"}),
              "bad view: illegal horizontal view size");
    EXPECT_EQ(message({"-o", "a.tif", "s.rad"}),
              "output 'a.tif' must end in .exr, .hdr, .pic or .png");
}

TEST(ProjectToView, InvertsViewRay) {
    for (ViewType type : {ViewType::Perspective, ViewType::Parallel}) {
        View v;
        v.type = type;
        v.vp = Vec3(1, -2, 0.5);
        v.vd = Vec3(0.2, 1, -0.1);
        v.vh = type == ViewType::Parallel ? 3 : 50;
        v.vv = type == ViewType::Parallel ? 2 : 35;
        v.vs = 0.1;
        v.vl = -0.2;
        const PreparedView pv = SetupView(v);
        for (double x : {0.1, 0.5, 0.93}) {
            for (double y : {0.05, 0.5, 0.7}) {
                const auto ray = ViewRay(pv, x, y);
                ASSERT_TRUE(ray);
                const Vec3 p = ray->origin + 4.0 * ray->direction;
                const auto q = ProjectToView(pv, p);
                ASSERT_TRUE(q);
                EXPECT_NEAR(q->x, x, 1e-12);
                EXPECT_NEAR(q->y, y, 1e-12);
            }
        }
    }
    View v;
    const PreparedView pv = SetupView(v);
    EXPECT_FALSE(ProjectToView(pv, v.vp - v.vd));  // behind the viewer
}

TEST(RenderView, OneRayPerPixelTopRowFirst) {
    PictureSettings s;
    s.outcomeLayer = s.indirectLayer = true;
    View v;
    const PreparedView pv = SetupView(v);
    FakeEvaluator fake;
    std::vector<std::size_t> progress;
    const Image img = RenderView(fake, pv, 4, 3, s, 0, 0.1, 5,
                                 [&](std::size_t done, std::size_t) { progress.push_back(done); }, {});
    ASSERT_EQ(fake.rays.size(), 12u);
    EXPECT_EQ(progress, (std::vector<std::size_t>{5, 10, 12}));
    // Pixel (x, y) got ray index y·width + x, and the top row looks up.
    EXPECT_EQ(img.Get(3, 2).r, 11);
    EXPECT_GT(fake.rays[0].dir.z, 0);
    EXPECT_LT(fake.rays[11].dir.z, 0);
    EXPECT_LT(fake.rays[0].dir.x, 0);
    const auto centre = ViewRay(pv, 2.5 / 4, 0.5 / 3);  // pixel (2, 2)
    EXPECT_NEAR(Dot(fake.rays[10].dir, centre->direction), 1.0, 1e-12);
    ASSERT_TRUE(img.FindLayer("outcome"));
    EXPECT_EQ(img.FindLayer("outcome")->values[7], kOutcomeExtrapolated);
    EXPECT_EQ(img.FindLayer("indirect.B")->values[7], 3.0f);
}

TEST(RenderView, JitterRepeatsAndStaysInThePixel) {
    PictureSettings s;
    s.jitter = 1.0;
    View v;
    const PreparedView pv = SetupView(v);
    FakeEvaluator a, b;
    (void)RenderView(a, pv, 8, 8, s, 7, 0.1, 1024, {}, {});
    (void)RenderView(b, pv, 8, 8, s, 7, 0.1, 1024, {}, {});
    ASSERT_EQ(a.rays.size(), 64u);
    for (std::size_t i = 0; i < 64; ++i) {
        EXPECT_EQ(a.rays[i].dir, b.rays[i].dir);
        const auto q = ProjectToView(pv, a.rays[i].org + a.rays[i].dir);
        const double px = q->x * 8, py = 8 - q->y * 8;
        EXPECT_EQ(static_cast<int>(px), static_cast<int>(i % 8));
        EXPECT_EQ(static_cast<int>(py), static_cast<int>(i / 8));
    }
    const auto centre = ViewRay(pv, 0.5 / 8, 7.5 / 8);
    EXPECT_NE(a.rays[0].dir, centre->direction);
}

TEST(RenderView, FisheyeCornersAreBlackAndNotTraced) {
    PictureSettings s;
    View v;
    v.type = ViewType::Angular;
    v.vh = v.vv = 360;  // the image circle touches the picture's edges
    const PreparedView pv = SetupView(v);
    FakeEvaluator fake;
    const Image img = RenderView(fake, pv, 16, 16, s, 0, 0.1, 1024, {}, {});
    EXPECT_LT(fake.rays.size(), 256u);
    EXPECT_GT(fake.rays.size(), 180u);  // π/4 of 256 ≈ 201
    EXPECT_EQ(img.Get(0, 0), Rgb());
}

TEST(DrawRecords, DrawsVisibleDiscsOnly) {
    // Looking down -z at the plane z = 0 from z = 10; a parallel view 2×2 wide.
    View v;
    v.type = ViewType::Parallel;
    v.vp = Vec3(0, 0, 10);
    v.vd = Vec3(0, 0, -1);
    v.vu = Vec3(0, 1, 0);
    v.vh = v.vv = 2;
    const PreparedView pv = SetupView(v);
    Image img(20, 20);
    std::vector<Vec3> hit;  // every pixel sees the plane
    for (int y = 0; y < 20; ++y) {
        for (int x = 0; x < 20; ++x) {
            const auto ray = ViewRay(pv, (x + 0.5) / 20, (19 - y + 0.5) / 20);
            hit.push_back(ray->origin + 10.0 * ray->direction);
        }
    }
    AmbientRecord near;
    near.position = Vec3(-0.5, 0.5, 0);
    near.normal = Vec3(0, 0, 1);
    near.uAxis = Vec3(1, 0, 0);
    near.radius[0] = near.radius[1] = 2.0;  // × accuracy 0.1: 0.2, two pixels
    near.level = 1;
    AmbientRecord hidden = near;
    hidden.position = Vec3(0.5, -0.5, -0.01);  // 1 cm under the plane
    hidden.level = 0;
    const std::vector<AmbientRecord> records = {near, hidden};
    EXPECT_EQ(DrawRecords(img, pv, records, 0.1, 1.0, hit, {}), 1u);
    const ImageLayer* g = img.FindLayer("records.G");
    const ImageLayer* r = img.FindLayer("records.R");
    ASSERT_TRUE(g && r);
    // (-0.5, 0.5) is pixel (5, 5); radius 2 pixels.
    EXPECT_EQ(g->values[5 * 20 + 5], 1.0f);
    EXPECT_EQ(g->values[5 * 20 + 6], 1.0f);
    EXPECT_EQ(g->values[5 * 20 + 8], 0.0f);
    float redSum = 0;
    for (float x : r->values) redSum += x;
    EXPECT_EQ(redSum, 0.0f);
    // Scale 0: a one-pixel dot.
    Image dots(20, 20);
    EXPECT_EQ(DrawRecords(dots, pv, records, 0.1, 0.0, hit, {}), 1u);
    float sum = 0;
    for (float x : dots.FindLayer("records.G")->values) sum += x;
    EXPECT_EQ(sum, 1.0f);
    // Other view types are refused with a warning.
    View fish;
    fish.type = ViewType::Angular;
    std::vector<std::string> warnings;
    Image f(20, 20);
    EXPECT_EQ(DrawRecords(f, SetupView(fish), records, 0.1, 1.0, hit,
                          [&](const std::string& w) { warnings.push_back(w); }),
              0u);
    EXPECT_EQ(warnings.size(), 1u);
}

TEST(RecordLevelColour, DistinctPerLevel) {
    std::set<std::tuple<double, double, double>> seen;
    for (int level = 0; level < 6; ++level) {
        const Rgb c = RecordLevelColour(level);
        seen.insert({c.r, c.g, c.b});
    }
    EXPECT_EQ(seen.size(), 6u);
    EXPECT_EQ(RecordLevelColour(0), Rgb(1, 0, 0));
    EXPECT_EQ(RecordLevelColour(9), RecordLevelColour(5));
}

// The EXR is read with OpenEXR itself, not with image/exr.h.
TEST(Rvimage, CornellExrOpensInOpenExr) {
    const std::string path = TempPath("cornell.exr");
    ASSERT_EQ(Render({"-vf", kCornell + "cornell.vf", "-x", "32", "-y", "32", "-ab", "0", "-o",
                      path, kCornell + "cornell.rad"}),
              0);
    Imf::InputFile file(path.c_str());
    const Imath::Box2i dw = file.header().dataWindow();
    EXPECT_EQ(dw.max.x - dw.min.x + 1, 32);
    EXPECT_EQ(dw.max.y - dw.min.y + 1, 32);
    std::set<std::string> channels;
    for (auto it = file.header().channels().begin(); it != file.header().channels().end(); ++it) {
        channels.insert(it.name());
        EXPECT_EQ(it.channel().type, Imf::FLOAT);
    }
    EXPECT_EQ(channels, (std::set<std::string>{"B", "G", "R"}));
    auto attribute = [&](const char* name) {
        const auto* a = file.header().findTypedAttribute<Imf::StringAttribute>(name);
        return a ? a->value() : std::string("<missing>");
    };
    EXPECT_EQ(attribute("software"), "lazyrad 0.1.0");
    EXPECT_EQ(attribute("commandLine"), "rvimage -vf " + kCornell + "cornell.vf -x 32 -y 32 -ab 0 -o " +
                                            path + " " + kCornell + "cornell.rad");
    EXPECT_EQ(attribute("view"),
              "-vtv -vp 2.78 -8 2.74 -vd 0 1 0 -vu 0 0 1 -vh 39 -vv 39 -vo 0 -va 0 -vs 0 -vl 0");
    // Pixel data, read with the library: finite, not negative, not all black.
    std::vector<float> red(32 * 32);
    Imf::FrameBuffer fb;
    fb.insert("R", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(red.data()), sizeof(float),
                              32 * sizeof(float)));
    file.setFrameBuffer(fb);
    file.readPixels(dw.min.y, dw.max.y);
    double sum = 0;
    for (float v : red) {
        EXPECT_TRUE(std::isfinite(v) && v >= 0);
        sum += v;
    }
    EXPECT_GT(sum, 0);
    std::filesystem::remove(path);
}

TEST(Rvimage, HdrAndExrHoldTheSamePicture) {
    const std::string exr = TempPath("same.exr"), hdr = TempPath("same.hdr");
    const std::vector<std::string> common = {"-vf", kCornell + "cornell.vf", "-x", "24", "-y", "24",
                                             "-ab", "0"};
    auto with = [&](const std::string& out) {
        std::vector<std::string> a = common;
        a.insert(a.end(), {"-o", out, kCornell + "cornell.rad"});
        return a;
    };
    ASSERT_EQ(Render(with(exr)), 0);
    ASSERT_EQ(Render(with(hdr)), 0);
    std::vector<std::string> header;
    const Image h = ReadHdr(hdr, &header);
    const Image e = ReadExr(exr);
    ASSERT_EQ(h.width, 24);
    ASSERT_EQ(h.height, 24);
    // RGBE keeps 8 bits of mantissa relative to the pixel's largest channel.
    for (std::size_t p = 0; p < e.PixelCount(); ++p) {
        const double top = std::max({e.rgb[3 * p], e.rgb[3 * p + 1], e.rgb[3 * p + 2]});
        for (std::size_t c = 0; c < 3; ++c)
            EXPECT_NEAR(h.rgb[3 * p + c], e.rgb[3 * p + c], top / 128 + 1e-9);
    }
    bool hasView = false;
    for (const std::string& line : header) hasView |= line.rfind("VIEW= -vtv", 0) == 0;
    EXPECT_TRUE(hasView);
    std::filesystem::remove(exr);
    std::filesystem::remove(hdr);
}

TEST(Rvimage, AmbientLayersHaveSensibleValues) {
    const std::string path = TempPath("layers.exr");
    ASSERT_EQ(Render({"-vf", kCornell + "cornell.vf", "-x", "32", "-y", "32", "-ab", "1", "-ad",
                      "128", "-as", "64", "-aa", "0.3", "-layers", "all", "-o", path,
                      kCornell + "cornell.rad"}),
              0);
    ImageMetadata meta;
    const Image img = ReadExr(path, &meta);
    for (const char* name : {"indirect.R", "indirect.G", "indirect.B", "outcome", "records.R",
                             "records.G", "records.B"})
        ASSERT_TRUE(img.FindLayer(name)) << name;
    int counts[5] = {0, 0, 0, 0, 0};
    for (float v : img.FindLayer("outcome")->values) {
        ASSERT_TRUE(v >= 0 && v <= 4 && v == std::floor(v)) << v;
        ++counts[static_cast<int>(v)];
    }
    EXPECT_GT(counts[1] + counts[2], 0);  // the cache answered some pixels
    EXPECT_GT(counts[3], 0);              // and made records for others
    EXPECT_GT(counts[0], 0);              // the lamp has no indirect calculation
    EXPECT_EQ(counts[4], 0);              // -av is 0 and never used with a cache
    double indirect = 0;
    for (const char* c : {"indirect.R", "indirect.G", "indirect.B"}) {
        for (float v : img.FindLayer(c)->values) {
            EXPECT_GE(v, 0.0f);
            indirect += v;
        }
    }
    EXPECT_GT(indirect, 0);
    int marked = 0;
    for (std::size_t p = 0; p < img.PixelCount(); ++p)
        marked += img.FindLayer("records.R")->values[p] > 0;  // -ab 1: level 0, red
    EXPECT_GT(marked, 10);
    std::filesystem::remove(path);
}

TEST(Rvimage, ThreadsGiveTheSameDirectImage) {
    const std::string one = TempPath("n1.exr"), two = TempPath("n2.exr");
    for (const auto& [n, out] : {std::pair{"1", one}, std::pair{"2", two}}) {
        ASSERT_EQ(Render({"-n", n, "-vf", kCornell + "cornell.vf", "-x", "40", "-y", "40", "-ab",
                          "0", "-pj", "0.7", "-o", out, kCornell + "cornell.rad"}),
                  0);
    }
    EXPECT_EQ(ReadExr(one).rgb, ReadExr(two).rgb);
    std::filesystem::remove(one);
    std::filesystem::remove(two);
}

TEST(Rvimage, PngAndRecordsPicture) {
    const std::string path = TempPath("pic.png");
    ASSERT_EQ(Render({"-vf", kCornell + "cornell.vf", "-x", "20", "-y", "20", "-ab", "1", "-ad",
                      "64", "-as", "0", "-layers", "records", "-o", path,
                      kCornell + "cornell.rad"}),
              0);
    int w = 0, h = 0;
    const std::vector<std::uint8_t> bytes = ReadPng(path, w, h);
    EXPECT_EQ(w, 20);
    EXPECT_EQ(h, 20);
    EXPECT_EQ(bytes.size(), 20u * 20u * 3u);
    const std::string records = path.substr(0, path.size() - 4) + "_records.png";
    EXPECT_EQ(ReadPng(records, w, h).size(), 20u * 20u * 3u);
    std::filesystem::remove(path);
    std::filesystem::remove(records);
}

TEST(Rvimage, ErrorsGiveRadianceExitCodes) {
    std::string err;
    EXPECT_EQ(Render({"-o", "x.exr", "-vh", "0", kCornell + "cornell.rad"}, &err), 1);
    EXPECT_NE(err.find("rvimage: fatal - bad view: illegal horizontal view size"), std::string::npos)
        << err;
    EXPECT_NE(Render({"-o", "/nonexistent/dir/x.exr", "-x", "4", "-y", "4", "-ab", "0",
                      kCornell + "cornell.rad"},
                     &err),
              0);
    EXPECT_NE(err.find("rvimage: "), std::string::npos) << err;
}

}  // namespace
}  // namespace rt
