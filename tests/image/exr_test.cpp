// SPDX-License-Identifier: MIT
#include "image/exr.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>

#include "core/error.h"

namespace rt {
namespace {

std::string TempPath(const std::string& name) {
    return (std::filesystem::temp_directory_path() /
            ("lazyrad_image_" + std::to_string(::getpid()) + "_" + name))
        .string();
}

Image TestPattern(int w, int h) {
    Image img(w, h);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            img.Set(x, y, Rgb(x + 0.1 * y, 1e-30 * (x + 1), 3.0e7 / (y + 1)));
        }
    }
    // Values that are easy to lose: denormals, negatives, the largest float.
    img.rgb[0] = std::numeric_limits<float>::denorm_min();
    img.rgb[1] = -2.5f;
    img.rgb[2] = std::numeric_limits<float>::max();
    img.rgb[4] = 0.1f;
    return img;
}

TEST(Exr, RoundTripIsBitExactWithLayersAndMetadata) {
    Image img = TestPattern(7, 5);
    ImageLayer& z = img.AddLayer("Z");
    for (std::size_t i = 0; i < z.values.size(); ++i)
        z.values[i] = 0.5f * static_cast<float>(i);
    const ImageMetadata meta = {{"commandLine", "rtrace -ab 2 -x 7 -y 5 scene.rad"},
                                {"software", "lazyrad 0.1.0"}};
    const std::string path = TempPath("roundtrip.exr");
    WriteExr(path, img, meta);
    EXPECT_TRUE(IsExrFile(path));

    ImageMetadata readMeta;
    const Image back = ReadExr(path, &readMeta);
    ASSERT_EQ(back.width, 7);
    ASSERT_EQ(back.height, 5);
    ASSERT_EQ(back.rgb.size(), img.rgb.size());
    EXPECT_EQ(std::memcmp(back.rgb.data(), img.rgb.data(), img.rgb.size() * sizeof(float)), 0);
    ASSERT_EQ(back.layers.size(), 1u);
    EXPECT_EQ(back.layers[0], img.layers[0]);
    EXPECT_EQ(back, img);
    for (const auto& entry : meta) {
        EXPECT_NE(std::find(readMeta.begin(), readMeta.end(), entry), readMeta.end())
            << entry.first;
    }
    std::filesystem::remove(path);
}

TEST(Exr, MetadataIsVisibleToOpenExrItself) {
    const std::string path = TempPath("meta.exr");
    WriteExr(path, Image(4, 3), {{"software", "lazyrad test"}});
    Imf::InputFile file(path.c_str());
    const auto* attr = file.header().findTypedAttribute<Imf::StringAttribute>("software");
    ASSERT_NE(attr, nullptr);
    EXPECT_EQ(attr->value(), "lazyrad test");
    EXPECT_NE(file.header().channels().findChannel("R"), nullptr);
    EXPECT_EQ(file.header().channels().findChannel("R")->type, Imf::FLOAT);
    EXPECT_EQ(file.header().dataWindow().max.x, 3);
    EXPECT_EQ(file.header().dataWindow().max.y, 2);
    std::filesystem::remove(path);
}

TEST(Exr, ErrorsNameTheFile) {
    try {
        (void)ReadExr("/nonexistent/dir/missing.exr");
        FAIL() << "no exception";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("missing.exr"), std::string::npos) << e.what();
    }
    try {
        WriteExr("/nonexistent/dir/out.exr", Image(2, 2));
        FAIL() << "no exception";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("out.exr"), std::string::npos) << e.what();
    }
    EXPECT_THROW(WriteExr(TempPath("x.exr"), Image(2, 2), {{"channels", "x"}}), Error);
    EXPECT_THROW(WriteExr(TempPath("y.exr"), Image(0, 0)), Error);
}

}  // namespace
}  // namespace rt
