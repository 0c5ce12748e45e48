// SPDX-License-Identifier: MIT
//
// Golden images: rvimage renders of the shared scenes at small sizes with
// fixed settings and -seed 0, compared with tests/data/golden/*.exr by
// CompareImages (image/compare.h: relative luminance difference per pixel,
// floor 1 % of the mean). The references change only through
// scripts/render-docs.sh, which runs this test with RT_REGENERATE_GOLDEN=1.
//
// Tolerances:
// - -ab 0 is deterministic (no random numbers reach a pixel but the light
//   source sampling, which -seed fixes), so the limits only absorb compiler
//   and libm differences: RMS 1e-4, max 1e-3.
// - With bounces, -seed 0 repeats exactly on one machine, but a different
//   compiler or CPU may change the record placement, which acts like another
//   seed. The limits are about twice the largest difference measured between
//   seed 0 and seeds 1-4 at these settings (2026-11-22):
//     cornell_ab1      RMS 0.047-0.054, max 0.47-0.67, mean shift ≤ 0.018 %
//                      -> limits RMS 0.11, max 1.35, mean 0.2 %
//     daylit_room_ab2  RMS 0.114-0.160, max 1.0-1.67, mean shift ≤ 0.74 %
//                      -> limits RMS 0.32, mean 1.5 %; max not checked (2.0 is
//                         the measure's bound: single pixels differ completely)
//   The mean shift catches a bias that per-pixel noise would hide.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "core/rgb.h"
#include "image/compare.h"
#include "image/exr.h"
#include "rtrace/render.h"
#include "rtrace/scene_evaluator.h"

namespace rt {
namespace {

struct GoldenCase {
    const char* name;   // tests/data/golden/<name>.exr
    const char* scene;  // scenes/<scene>/<scene>.rad and .vf
    std::vector<std::string> options;
    double maxRms;       // limit on CompareResult::rmsRelative
    double maxMax;       // limit on CompareResult::maxRelative (the measure is at most 2)
    double maxMeanShift;  // limit on |mean luminance / golden mean luminance − 1|
};

double MeanLuminance(const Image& img) {
    double sum = 0;
    for (std::size_t p = 0; p < img.PixelCount(); ++p)
        sum += Bright(Rgb(img.rgb[3 * p], img.rgb[3 * p + 1], img.rgb[3 * p + 2]));
    return sum / static_cast<double>(img.PixelCount());
}

std::vector<GoldenCase> Cases() {
    return {
        {"cornell_ab0", "cornell", {"-x", "64", "-y", "64", "-ab", "0"}, 1e-4, 1e-3, 1e-5},
        {"daylit_room_ab0", "daylit_room", {"-x", "64", "-y", "64", "-ab", "0"}, 1e-4, 1e-3, 1e-5},
        {"cornell_ab1",
         "cornell",
         {"-x", "64", "-y", "64", "-ab", "1", "-ad", "256", "-as", "128", "-aa", ".15", "-ar", "64"},
         0.11, 1.35, 0.002},
        {"daylit_room_ab2",
         "daylit_room",
         {"-x", "64", "-y", "64", "-ab", "2", "-ad", "256", "-as", "128", "-aa", ".15", "-ar",
          "64"},
         0.32, 2.0, 0.015},
    };
}

Image RenderCase(const GoldenCase& c, const std::string& path) {
    const std::string dir = std::string(RT_SOURCE_DIR) + "/scenes/" + c.scene + "/";
    std::vector<std::string> args = {"rvimage", "-seed", "0", "-vf", dir + c.scene + ".vf"};
    args.insert(args.end(), c.options.begin(), c.options.end());
    args.insert(args.end(), {"-o", path, dir + c.scene + ".rad"});
    RunEnvironment env;
    env.makeEvaluator = [](const std::vector<std::string>& files, const RtraceOptions& options,
                           const WarningSink& warn) {
        return MakeSceneEvaluator(files, options, warn, "");
    };
    std::ostringstream out, err;
    EXPECT_EQ(RunRender(args, out, err, env, false), 0) << err.str();
    return ReadExr(path);
}

class GoldenImage : public ::testing::TestWithParam<GoldenCase> {};

TEST_P(GoldenImage, MatchesReference) {
    const GoldenCase& c = GetParam();
    const std::string golden = std::string(RT_SOURCE_DIR) + "/tests/data/golden/" + c.name + ".exr";
    const std::string path = (std::filesystem::temp_directory_path() /
                              ("golden_" + std::to_string(getpid()) + "_" + c.name + ".exr"))
                                 .string();
    const Image img = RenderCase(c, path);
    if (const char* regen = std::getenv("RT_REGENERATE_GOLDEN"); regen && *regen == '1') {
        std::filesystem::copy_file(path, golden, std::filesystem::copy_options::overwrite_existing);
        std::filesystem::remove(path);
        GTEST_SKIP() << "regenerated " << golden;
    }
    std::filesystem::remove(path);
    ASSERT_TRUE(std::filesystem::exists(golden)) << golden << " missing: run scripts/render-docs.sh";
    const Image reference = ReadExr(golden);
    const CompareResult r = CompareImages(img, reference);
    const double shift = MeanLuminance(img) / MeanLuminance(reference) - 1.0;
    std::printf("%s: rms %.3g max %.3g at %d %d, mean shift %.3g (limits %.3g, %.3g, %.3g)\n",
                c.name, r.rmsRelative, r.maxRelative, r.maxX, r.maxY, shift, c.maxRms, c.maxMax,
                c.maxMeanShift);
    EXPECT_LE(r.rmsRelative, c.maxRms);
    EXPECT_LE(r.maxRelative, c.maxMax);
    EXPECT_LE(std::abs(shift), c.maxMeanShift);
}

INSTANTIATE_TEST_SUITE_P(Scenes, GoldenImage, ::testing::ValuesIn(Cases()),
                         [](const ::testing::TestParamInfo<GoldenCase>& p) {
                             std::string n = p.param.name;
                             std::erase(n, '_');
                             return n;
                         });

}  // namespace
}  // namespace rt
