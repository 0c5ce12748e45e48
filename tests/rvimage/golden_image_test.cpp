// SPDX-License-Identifier: MIT
//
// Golden images: rvimage renders of the shared scenes, 64 pixels across, with
// fixed settings and -seed 0, compared with pictures made by real Radiance 5.4a
// (tests/data/golden/*.hdr, made by tests/data/golden/make_refs.sh; each
// header records how). The pixels are the same rays: rvimage traces the pixel
// centres that vwrays generates, keeps square pixels as `vwrays -d` does (so
// daylit_room's 70° × 55° view is 64 × 48), and both pictures store the top
// scanline first. The measures are those of image/compare.h.
//
// - -ab 0: the reference is rtrace's picture of those rays. Both pictures are
//   RGBE, and rvimage's values agree with Radiance's to the 7th significant
//   digit, so the pixels should be identical. The limits leave room for a few
//   pixels where a 7th-digit difference crosses an RGBE mantissa boundary: one
//   step in one channel, at most 1/128 of that channel, which in luminance is
//   under 2 % for the colours of these scenes.
// - -ab 1 and 2: the reference is the converged answer (the mean of tens of
//   thousands of path-traced estimates per pixel), not Radiance's cached
//   picture, which is itself a noisy estimate of it. lazyrad's picture differs
//   from it by cache interpolation error and by noise that moves with the
//   seed (a different compiler or CPU acts like another seed), so a single
//   pixel is not judged. Instead:
//     - the RMS over pixels bounds the overall error;
//     - the largest difference between the means of 16 × 16-pixel blocks
//       catches a region that is wrong;
//     - the shift of the mean luminance catches a bias the noise would hide.
//   Each limit is about twice the largest value measured for seeds 0 to 19 at
//   these settings.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <sstream>

#include "core/rgb.h"
#include "image/compare.h"
#include "image/hdr.h"
#include "rtrace/scene_evaluator.h"
#include "rvimage/rvimage.h"

namespace rt {
namespace {

struct GoldenCase {
    const char* name;   // tests/data/golden/<name>.hdr
    const char* scene;  // scenes/<scene>/<scene>.rad and .vf
    std::vector<std::string> options;
    double maxRms;                   // limit on CompareResult::rmsRelative over pixels
    std::optional<double> maxPixel;  // limit on CompareResult::maxRelative over pixels, or none
    double maxBlock;      // limit on CompareResult::maxRelative over kBlock × kBlock block means
    double maxMeanShift;  // limit on |mean luminance / reference mean luminance − 1|
};

// Pixels per block side: 4 × 4 blocks on cornell's 64 × 64, 4 × 3 on daylit_room's 64 × 48.
constexpr int kBlock = 16;

void PrintTo(const GoldenCase& c, std::ostream* os) { *os << c.name; }

double MeanLuminance(const Image& img) {
    double sum = 0;
    for (std::size_t p = 0; p < img.PixelCount(); ++p)
        sum += Bright(Rgb(img.rgb[3 * p], img.rgb[3 * p + 1], img.rgb[3 * p + 2]));
    return sum / static_cast<double>(img.PixelCount());
}

/// The mean of each block × block tile; the sides must be multiples of block.
Image BlockMeans(const Image& img, int block) {
    EXPECT_EQ(img.width % block, 0);
    EXPECT_EQ(img.height % block, 0);
    Image out(img.width / block, img.height / block);
    const double area = static_cast<double>(block) * block;
    for (int by = 0; by < out.height; ++by) {
        for (int bx = 0; bx < out.width; ++bx) {
            for (int c = 0; c < 3; ++c) {
                double sum = 0;
                for (int y = by * block; y < (by + 1) * block; ++y)
                    for (int x = bx * block; x < (bx + 1) * block; ++x)
                        sum += img.rgb[3 * (static_cast<std::size_t>(y) * img.width + x) + c];
                out.rgb[3 * (static_cast<std::size_t>(by) * out.width + bx) + c] =
                    static_cast<float>(sum / area);
            }
        }
    }
    return out;
}

const std::vector<std::string> kBounceSettings = {"-ad", "256", "-as", "128", "-aa", ".15",
                                                  "-ar", "64"};

std::vector<std::string> Options(std::vector<std::string> head,
                                 const std::vector<std::string>& tail = {}) {
    head.insert(head.end(), tail.begin(), tail.end());
    return head;
}

std::vector<GoldenCase> Cases() {
    return {
        {"cornell_ab0", "cornell", Options({"-x", "64", "-y", "64", "-ab", "0"}), 1e-3, 0.02,
         1e-3, 1e-3},
        {"daylit_room_ab0", "daylit_room", Options({"-x", "64", "-y", "64", "-ab", "0"}), 1e-3,
         0.02, 1e-3, 1e-3},
        {"cornell_ab1", "cornell", Options({"-x", "64", "-y", "64", "-ab", "1"}, kBounceSettings),
         0.08, std::nullopt, 0.017, 0.0022},
        {"daylit_room_ab2", "daylit_room",
         Options({"-x", "64", "-y", "64", "-ab", "2"}, kBounceSettings), 0.28, std::nullopt, 0.25,
         0.013},
    };
}

/// Renders the case with rvimage to an RGBE picture at `path`, the format of
/// the reference, so that both values went through the same rounding.
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
    EXPECT_EQ(RunRvimage(args, out, err, env, false), 0) << err.str();
    return ReadHdr(path);
}

class GoldenImage : public ::testing::TestWithParam<GoldenCase> {};

TEST_P(GoldenImage, MatchesRadiance) {
    const GoldenCase& c = GetParam();
    const std::string golden = std::string(RT_SOURCE_DIR) + "/tests/data/golden/" + c.name + ".hdr";
    ASSERT_TRUE(std::filesystem::exists(golden)) << golden << " missing";
    const std::string path = (std::filesystem::temp_directory_path() /
                              ("golden_" + std::to_string(getpid()) + "_" + c.name + ".hdr"))
                                 .string();
    const Image img = RenderCase(c, path);
    std::filesystem::remove(path);
    const Image reference = ReadHdr(golden);
    ASSERT_EQ(img.width, reference.width);
    ASSERT_EQ(img.height, reference.height);
    const CompareResult pixels = CompareImages(img, reference);
    const CompareResult blocks =
        CompareImages(BlockMeans(img, kBlock), BlockMeans(reference, kBlock));
    const double shift = MeanLuminance(img) / MeanLuminance(reference) - 1.0;
    char pixelLimit[32] = "none";
    if (c.maxPixel) std::snprintf(pixelLimit, sizeof pixelLimit, "%.3g", *c.maxPixel);
    std::printf("%s: pixels rms %.3g (limit %.3g), max %.3g at %d %d (limit %s); block max %.3g "
                "at block %d %d (limit %.3g); mean shift %.3g (limit %.3g)\n",
                c.name, pixels.rmsRelative, c.maxRms, pixels.maxRelative, pixels.maxX,
                pixels.maxY, pixelLimit, blocks.maxRelative, blocks.maxX, blocks.maxY, c.maxBlock,
                shift, c.maxMeanShift);
    EXPECT_LE(pixels.rmsRelative, c.maxRms);
    if (c.maxPixel) {
        EXPECT_LE(pixels.maxRelative, *c.maxPixel);
    }
    EXPECT_LE(blocks.maxRelative, c.maxBlock);
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
