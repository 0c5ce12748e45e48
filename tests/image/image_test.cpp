// SPDX-License-Identifier: MIT
#include "image/image.h"

#include <gtest/gtest.h>

#include "core/error.h"

namespace rt {
namespace {

TEST(Image, StartsBlackAndStoresTopRowFirst) {
    Image img(3, 2);
    EXPECT_EQ(img.rgb.size(), 18u);
    EXPECT_EQ(img.Get(2, 1), Rgb());
    img.Set(1, 0, Rgb(1, 2, 3));
    EXPECT_EQ(img.rgb[3], 1.0f);
    EXPECT_EQ(img.rgb[5], 3.0f);
    EXPECT_EQ(img.Get(1, 0), Rgb(1, 2, 3));
}

TEST(Image, LayersHaveUniqueNonReservedNames) {
    Image img(2, 2);
    ImageLayer& z = img.AddLayer("Z");
    EXPECT_EQ(z.values.size(), 4u);
    EXPECT_NE(img.FindLayer("Z"), nullptr);
    EXPECT_EQ(img.FindLayer("depth"), nullptr);
    EXPECT_THROW(img.AddLayer("Z"), Error);
    EXPECT_THROW(img.AddLayer("R"), Error);
}

}  // namespace
}  // namespace rt
