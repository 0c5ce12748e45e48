// SPDX-License-Identifier: MIT
#include "rtrace/ray_input.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace rt {
namespace {

std::vector<InputRay> ReadAll(const std::string& data, char format) {
    std::istringstream in(data);
    RayReader reader(in, format);
    std::vector<InputRay> rays;
    while (auto r = reader.Next()) rays.push_back(*r);
    return rays;
}

std::string ErrorOf(const std::string& data, char format, std::size_t* goodRays = nullptr) {
    std::istringstream in(data);
    RayReader reader(in, format);
    std::size_t n = 0;
    try {
        while (reader.Next()) ++n;
    } catch (const BadRayError& e) {
        if (goodRays) *goodRays = n;
        EXPECT_EQ(e.ExitCode(), 1);
        return e.what();
    }
    return "(no error)";
}

template <typename T>
std::string Binary(const std::vector<T>& values) {
    return std::string(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
}

TEST(RayInputAscii, WordsInAnyLayout) {
    auto rays = ReadAll("1 2 3\n4 5 6\n  7\t8\n9 10\n11 12\n\n", 'a');
    ASSERT_EQ(rays.size(), 2u);
    EXPECT_EQ(rays[0].origin, Vec3(1, 2, 3));
    EXPECT_EQ(rays[0].direction, Vec3(4, 5, 6));
    EXPECT_EQ(rays[1].origin, Vec3(7, 8, 9));
    EXPECT_EQ(rays[1].direction, Vec3(10, 11, 12));
    rays = ReadAll("2.78000e+00 -8.00000e+00 2.74000e+00 -3.08647e-01 8.99708e-01 3.08647e-01", 'a');
    ASSERT_EQ(rays.size(), 1u);
    EXPECT_EQ(rays[0].direction.x, -3.08647e-01);
    EXPECT_TRUE(ReadAll("", 'a').empty());
    EXPECT_TRUE(ReadAll(" \n\n ", 'a').empty());
    // Zero direction is returned as is: the caller treats it as a flush request.
    EXPECT_EQ(ReadAll("1 1 1 0 0 0\n", 'a')[0].direction, Vec3(0, 0, 0));
}

TEST(RayInputAscii, BadWordsReportTheirLine) {
    std::size_t good = 0;
    EXPECT_EQ(ErrorOf("0 0 0 0 0 1\n0 0 0\n0 x 1\n", 'a', &good), "bad ray at line 3");
    EXPECT_EQ(good, 1u);
    EXPECT_EQ(ErrorOf("0 0 0 0 0 1e999\n", 'a'), "bad ray at line 1");
    EXPECT_EQ(ErrorOf("0 0 0 0 0 nan\n", 'a'), "bad ray at line 1");
    EXPECT_EQ(ErrorOf("\n\n0 0 0 0 0 inf\n", 'a'), "bad ray at line 3");
    EXPECT_EQ(ErrorOf("0 0 0 0 0 1\n1 2 3\n4\n\n", 'a', &good), "bad ray at line 3");  // truncated
    EXPECT_EQ(good, 1u);
    EXPECT_EQ(ErrorOf("0 0 0 0 0 1,\n", 'a'), "bad ray at line 1");
}

TEST(RayInputBinary, FloatsAndDoubles) {
    auto rays = ReadAll(Binary<float>({1, 2, 3, 0.5f, 0, -1, 7, 8, 9, 0, 0, 0}), 'f');
    ASSERT_EQ(rays.size(), 2u);
    EXPECT_EQ(rays[0].direction, Vec3(0.5, 0, -1));
    EXPECT_EQ(rays[1].origin, Vec3(7, 8, 9));
    rays = ReadAll(Binary<double>({0.1, 0.2, 0.3, 0.4, 0.5, 0.6}), 'd');
    ASSERT_EQ(rays.size(), 1u);
    EXPECT_EQ(rays[0].origin, Vec3(0.1, 0.2, 0.3));
    EXPECT_EQ(rays[0].direction, Vec3(0.4, 0.5, 0.6));
}

TEST(RayInputBinary, BadRecordsReportRecordAndByte) {
    std::size_t good = 0;
    std::string data = Binary<float>({1, 2, 3, 4, 5, 6, 1, 2, 3});
    EXPECT_EQ(ErrorOf(data, 'f', &good), "bad ray at record 2 (byte 36)");
    EXPECT_EQ(good, 1u);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(ErrorOf(Binary<double>({1, 2, 3, 4, 5, 6, 0, 0, 0, 0, nan, 1}), 'd'),
              "bad ray at record 2 (byte 80)");
    const float inf = std::numeric_limits<float>::infinity();
    EXPECT_EQ(ErrorOf(Binary<float>({inf, 0, 0, 0, 0, 1}), 'f'), "bad ray at record 1 (byte 0)");
}

}  // namespace
}  // namespace rt
