// SPDX-License-Identifier: MIT
#include "image/compare.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/error.h"

namespace rt {
namespace {

Image Uniform(int w, int h, const Rgb& c) {
    Image img(w, h);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x)
            img.Set(x, y, c);
    }
    return img;
}

TEST(CompareImages, IdenticalImagesDifferByZero) {
    const Image a = Uniform(4, 4, Rgb(0.3, 0.5, 0.7));
    const CompareResult r = CompareImages(a, a);
    EXPECT_EQ(r.rmsRelative, 0.0);
    EXPECT_EQ(r.maxRelative, 0.0);
}

TEST(CompareImages, ScaledImageGivesTheSymmetricRelativeDifference) {
    // b = 1.1·a everywhere: d = 0.1 / 1.05 at every pixel, so rms = max.
    const Image a = Uniform(3, 2, Rgb(1, 2, 3));
    const Image b = Uniform(3, 2, Rgb(1.1, 2.2, 3.3));
    const CompareResult r = CompareImages(a, b);
    EXPECT_NEAR(r.maxRelative, 0.1 / 1.05, 1e-6);
    EXPECT_NEAR(r.rmsRelative, 0.1 / 1.05, 1e-6);
    const CompareResult swapped = CompareImages(b, a);
    EXPECT_DOUBLE_EQ(swapped.rmsRelative, r.rmsRelative);
}

TEST(CompareImages, OnePixelOffGivesKnownRmsAndLocation) {
    Image a = Uniform(4, 4, Rgb::Grey(1));
    Image b = a;
    b.Set(2, 3, Rgb::Grey(3));  // d = 2 / 2 = 1 at one pixel of 16
    const CompareResult r = CompareImages(a, b);
    EXPECT_NEAR(r.maxRelative, 1.0, 1e-6);
    EXPECT_NEAR(r.rmsRelative, std::sqrt(1.0 / 16.0), 1e-6);
    EXPECT_EQ(r.maxX, 2);
    EXPECT_EQ(r.maxY, 3);
}

TEST(CompareImages, BlackPixelsAreJudgedAgainstTheFloor) {
    // Mean luminance is ~1, so the floor is 0.01; a 1e-6 error on black is tiny.
    Image a = Uniform(10, 10, Rgb::Grey(1));
    Image b = a;
    a.Set(0, 0, Rgb());
    b.Set(0, 0, Rgb::Grey(1e-6));
    const CompareResult r = CompareImages(a, b);
    EXPECT_NEAR(r.floor, 0.01 * 0.99, 1e-6);
    EXPECT_NEAR(r.maxRelative, 1e-6 / r.floor, 1e-9);
    EXPECT_LT(r.maxRelative, 1e-3);
    // Uses luminance: a pure-blue change of 1 weighs 0.065.
    Image c = Uniform(2, 1, Rgb::Grey(1));
    Image d = c;
    d.Set(0, 0, Rgb(1, 1, 2));
    EXPECT_NEAR(CompareImages(c, d).maxRelative, 0.064811243 / (1.0 + 0.064811243 / 2), 1e-6);
}

TEST(CompareImages, NonFiniteAndMismatchedSizes) {
    Image a = Uniform(2, 2, Rgb::Grey(1));
    Image b = a;
    b.rgb[0] = std::numeric_limits<float>::quiet_NaN();
    EXPECT_TRUE(std::isinf(CompareImages(a, b).maxRelative));
    EXPECT_THROW((void)CompareImages(a, Image(3, 2)), Error);
}

}  // namespace
}  // namespace rt
