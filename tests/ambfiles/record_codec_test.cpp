// SPDX-License-Identifier: MIT
#include "ambfiles/record_codec.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "core/dircode.h"
#include "core/portable.h"
#include "tests/ambfiles/test_util.h"

namespace rt {
namespace {

using testing::DataPath;
using testing::kRadianceRecordCount;
using testing::kRadianceRecordsOffset;
using testing::ReadBytes;

std::vector<RecordBytes> RadianceRecords() {
    const auto file = ReadBytes(DataPath("cornell_radiance54.amb"));
    EXPECT_EQ(file.size(), kRadianceRecordsOffset + kRadianceRecordCount * kRecordBytes);
    std::vector<RecordBytes> out;
    for (std::size_t pos = kRadianceRecordsOffset; pos + kRecordBytes <= file.size();
         pos += kRecordBytes) {
        RecordBytes b;
        std::copy_n(file.begin() + static_cast<std::ptrdiff_t>(pos), kRecordBytes, b.begin());
        out.push_back(b);
    }
    return out;
}

std::uint32_t Be32(const std::uint8_t* p) {
    return (std::uint32_t{p[0]} << 24) | (std::uint32_t{p[1]} << 16) | (std::uint32_t{p[2]} << 8) |
           p[3];
}

std::vector<std::uint8_t> FloatBytes(double f) {
    std::vector<std::uint8_t> b(kPortableFloatBytes);
    PutPortableFloat(f, b.data());
    return b;
}

AmbientRecord Typical() {
    AmbientRecord r;
    r.position = {2, 2, 0};
    r.normal = {0, 0, 1};
    r.uAxis = Normalize(Vec3(-0.578445, -0.815721, 0));
    r.value = Rgb::Grey(0.529138);
    r.radius[0] = r.radius[1] = 0.8;
    r.posGradient[0] = -0.009374;
    r.posGradient[1] = -0.003547;
    r.dirGradient[0] = 0.012898;
    r.dirGradient[1] = 0.005010;
    return r;
}

TEST(RecordCodec, FieldWidthsSumTo67) {
    std::size_t sum = 0, expectedOffset = 0;
    for (const RecordField& f : kRecordLayout) {
        EXPECT_EQ(f.offset, expectedOffset) << f.name;
        expectedOffset += f.bytes;
        sum += f.bytes;
    }
    EXPECT_EQ(sum, 67u);
    EXPECT_EQ(kRecordBytes, 67u);
    // lvl + weight + pos + ndir + udir + RGBE + rad + gpos + gdir + corral
    EXPECT_EQ(1 + kPortableFloatBytes + 3 * kPortableFloatBytes + 4 + 4 + kRgbeBytes +
                  2 * kPortableFloatBytes * 3 + 4,
              kRecordBytes);
    EXPECT_EQ(kAmbientMagic, 559);
}

TEST(RecordCodec, EveryRadianceRecordDecodesAndReencodesBitExact) {
    const auto records = RadianceRecords();
    ASSERT_EQ(records.size(), kRadianceRecordCount);
    for (std::size_t i = 0; i < records.size(); ++i) {
        const auto r = DecodeRecord(records[i]);
        ASSERT_TRUE(r.has_value()) << "record " << i;
        EXPECT_EQ(EncodeRecord(*r), records[i]) << "record " << i;
        EXPECT_TRUE(IsStorable(*r));
    }
}

TEST(RecordCodec, DirectionCodesOfRadianceRecordsRoundTrip) {
    for (const RecordBytes& b : RadianceRecords()) {
        for (std::size_t off : {kRecordLayout[3].offset, kRecordLayout[4].offset}) {
            const std::uint32_t code = Be32(&b[off]);
            const Vec3 v = DecodeDirection(code);
            EXPECT_NEAR(Length(v), 1.0, 1e-4);
            EXPECT_EQ(EncodeDirection(v), code) << std::hex << code;
        }
    }
}

TEST(DirCode, KnownCodesFromRadiance) {
    EXPECT_EQ(EncodeDirection({0, 0, 1}), 0x00000008u);
    EXPECT_EQ(EncodeDirection({-1, 0, 0}), 0x00000011u);
    EXPECT_EQ(EncodeDirection({0.6, -0.8, 0}), 0x000364FAu);
    EXPECT_EQ(EncodeDirection({0, 0, 0}), kZeroDirectionCode);
    EXPECT_EQ(DecodeDirection(kZeroDirectionCode), Vec3(0, 0, 0));
    // The worked example's u axis (radiance-notes.md §5.2): code 0x000345bb.
    const Vec3 u = DecodeDirection(0x000345bb);
    EXPECT_NEAR(u.x, -0.578445, 5e-7);
    EXPECT_NEAR(u.y, -0.815721, 5e-7);
    EXPECT_EQ(u.z, 0.0);
}

TEST(DirCode, AxesAndDiagonalsRoundTrip) {
    const double s2 = 1 / std::sqrt(2.0), s3 = 1 / std::sqrt(3.0);
    std::vector<Vec3> dirs;
    for (int axis = 0; axis < 3; ++axis) {
        for (double sign : {1.0, -1.0}) {
            Vec3 v;
            v[axis] = sign;
            dirs.push_back(v);
        }
    }
    for (double sx : {1.0, -1.0}) {
        for (double sy : {1.0, -1.0}) {
            dirs.push_back({sx * s2, sy * s2, 0});
            dirs.push_back({sx * s2, 0, sy * s2});
            dirs.push_back({0, sx * s2, sy * s2});
            for (double sz : {1.0, -1.0}) dirs.push_back({sx * s3, sy * s3, sz * s3});
        }
    }
    for (const Vec3& v : dirs) {
        const std::uint32_t code = EncodeDirection(v);
        const Vec3 d = DecodeDirection(code);
        EXPECT_NE(code, kZeroDirectionCode);
        EXPECT_LT(std::acos(std::min(1.0, Dot(d, v))), 0.006 * std::numbers::pi / 180) << v;
        EXPECT_EQ(EncodeDirection(d), code) << v;
    }
}

TEST(DirCode, RandomDirectionsWithinRadianceAccuracy) {
    std::mt19937 rng(7);
    std::normal_distribution<double> g;
    double worst = 0;
    int notFixed = 0;
    for (int i = 0; i < 100000; ++i) {
        const Vec3 v = Normalize(Vec3(g(rng), g(rng), g(rng)));
        const std::uint32_t code = EncodeDirection(v);
        ASSERT_EQ(code >> 31, 0u);
        const Vec3 d = DecodeDirection(code);
        worst = std::max(worst, Length(Cross(d, v)));
        // Re-encoding a decoded vector reproduces the code except (as in Radiance) when
        // two components tie after rounding, or a component rounded to 0 had its sign
        // bit set (encodedir tests v < 0, decode gives −0); the vector is the same then.
        const Vec3 again = DecodeDirection(EncodeDirection(d));
        ASSERT_LT(Length(Cross(again, d)), 1.1e-4) << v;
        ASSERT_GT(Dot(again, d), 0.0) << v;
        if (EncodeDirection(d) != code) ++notFixed;
    }
    EXPECT_LT(notFixed, 100);  // of 100000
    // dircode.c: maximum error 0.0058°; allow a little for our sampling.
    EXPECT_LT(worst * 180 / std::numbers::pi, 0.0065);
}

TEST(PortableFloat, KnownBytes) {
    EXPECT_EQ(FloatBytes(1.0), (std::vector<std::uint8_t>{0x3f, 0xff, 0xff, 0xff, 0x01}));
    EXPECT_EQ(FloatBytes(2.0), (std::vector<std::uint8_t>{0x3f, 0xff, 0xff, 0xff, 0x02}));
    EXPECT_EQ(FloatBytes(0.5), (std::vector<std::uint8_t>{0x3f, 0xff, 0xff, 0xff, 0x00}));
    EXPECT_EQ(FloatBytes(-2.25), (std::vector<std::uint8_t>{0xb8, 0x00, 0x00, 0x01, 0x02}));
    EXPECT_EQ(FloatBytes(0.0), (std::vector<std::uint8_t>{0, 0, 0, 0, 0}));
    EXPECT_EQ(FloatBytes(1e-300), (std::vector<std::uint8_t>{0, 0, 0, 0, 0}));  // underflow
    EXPECT_EQ(FloatBytes(1e300), (std::vector<std::uint8_t>{0x7f, 0xff, 0xff, 0xff, 0x7f}));
    EXPECT_EQ(FloatBytes(-1e300), (std::vector<std::uint8_t>{0x80, 0x00, 0x00, 0x01, 0x7f}));
    EXPECT_EQ(FloatBytes(std::nan("")), FloatBytes(1e300));
}

TEST(PortableFloat, RoundTripOfFloatsIsExact) {
    for (float f : {1.0f, -1.0f, 0.1f, -0.009374f, 1e-30f, 3e30f, 1e-38f, 123456.789f,
                    std::nextafter(1.0f, 2.0f), std::nextafter(1.0f, 0.0f)}) {
        const auto b = FloatBytes(f);
        EXPECT_EQ(static_cast<float>(GetPortableFloat(b.data())), f);
    }
}

TEST(PortableInt, SignExtendsFirstByte) {
    std::uint8_t b[4];
    PutPortableInt(-2, 4, b);
    EXPECT_EQ(GetPortableInt(b, 4), -2);
    PutPortableInt(559, 2, b);
    EXPECT_EQ(b[0], 0x02);
    EXPECT_EQ(b[1], 0x2F);
    EXPECT_EQ(GetPortableInt(b, 2), 559);
    PutPortableInt(0xffffffff, 4, b);
    EXPECT_EQ(static_cast<std::uint32_t>(GetPortableInt(b, 4)), 0xffffffffu);
}

TEST(Rgbe, MatchesRadianceExamples) {
    EXPECT_EQ(EncodeRgbe(0.3, 0.4, 0.5), (std::array<std::uint8_t, 4>{0x4C, 0x66, 0x80, 0x80}));
    EXPECT_EQ(EncodeRgbe(0.529138, 0.529138, 0.529138),
              (std::array<std::uint8_t, 4>{135, 135, 135, 128}));
    const std::uint8_t grey[4] = {135, 135, 135, 128};
    EXPECT_DOUBLE_EQ(DecodeRgbe(grey).r, 0.529296875);
    EXPECT_EQ(EncodeRgbe(0, 0, 0), (std::array<std::uint8_t, 4>{0, 0, 0, 0}));
    EXPECT_EQ(EncodeRgbe(1e-33, 0, 0), (std::array<std::uint8_t, 4>{0, 0, 0, 0}));
    EXPECT_EQ(EncodeRgbe(-1, 0.5, 0)[0], 0);  // negative channels clamp to 0
    const std::uint8_t zero[4] = {10, 20, 30, 0};
    EXPECT_EQ(DecodeRgbe(zero), Rgb());
}

TEST(RecordCodec, RoundTripIsBitExactAtTheEdges) {
    std::vector<AmbientRecord> cases;
    cases.push_back(Typical());
    AmbientRecord r = Typical();
    r.posGradient[0] = r.posGradient[1] = r.dirGradient[0] = r.dirGradient[1] = 0;
    cases.push_back(r);  // zero gradients
    r = Typical();
    r.posGradient[0] = -1e9;
    r.posGradient[1] = -1e-30;
    r.dirGradient[0] = -123.456;
    r.dirGradient[1] = -1e-38;
    cases.push_back(r);  // negative, huge and tiny gradients
    r = Typical();
    r.position = {-9.9e9, 1e-30, 9.9e9};
    r.radius[0] = 1e-30;
    r.radius[1] = 9.9e9;
    r.value = {1e-30, 0, 9e9};
    r.weight = 1e-30;
    cases.push_back(r);  // tiny and huge magnitudes inside the validity limits
    r = Typical();
    r.level = 255;
    r.corral = 0xffffffffu;
    r.weight = 0.0625;
    cases.push_back(r);
    for (const Vec3& n : {Vec3(1, 0, 0), Vec3(0, -1, 0), Vec3(0, 0, -1),
                          Normalize(Vec3(1, 1, 0)), Normalize(Vec3(-1, 1, -1))}) {
        r = Typical();
        r.normal = n;
        r.uAxis = Perpendicular(n);
        cases.push_back(r);
    }
    for (const AmbientRecord& c : cases) {
        const RecordBytes bytes = EncodeRecord(c);
        const auto decoded = DecodeRecord(bytes);
        ASSERT_TRUE(decoded.has_value()) << c;
        EXPECT_EQ(EncodeRecord(*decoded), bytes) << c;
        // Decoding a decoded record's encoding is the identity (float-exact values).
        EXPECT_EQ(*DecodeRecord(EncodeRecord(*decoded)), *decoded);
        for (int i = 0; i < 3; ++i) {
            EXPECT_EQ(decoded->position[i], static_cast<float>(c.position[i]));
        }
        EXPECT_EQ(decoded->level, c.level);
        EXPECT_EQ(decoded->corral, c.corral);
        EXPECT_EQ(decoded->weight, static_cast<float>(c.weight));
        for (int i = 0; i < 2; ++i) {
            EXPECT_EQ(decoded->radius[i], static_cast<float>(c.radius[i]));
            EXPECT_EQ(decoded->posGradient[i], static_cast<float>(c.posGradient[i]));
            EXPECT_EQ(decoded->dirGradient[i], static_cast<float>(c.dirGradient[i]));
        }
        EXPECT_LT(Length(Cross(decoded->normal, c.normal)), 1.1e-4);
        EXPECT_GT(Dot(decoded->normal, c.normal), 0);
    }
}

TEST(RecordCodec, WorkedExampleBytes) {
    const RecordBytes b = EncodeRecord(Typical());
    EXPECT_EQ(b[0], 0);
    EXPECT_EQ(Be32(&b[21]), 0x00000008u);
    EXPECT_EQ(Be32(&b[25]), 0x000345bbu);
    EXPECT_EQ(Be32(&b[29]), 0x87878780u);
    EXPECT_EQ(Be32(&b[63]), 0u);
}

TEST(RecordCodec, ValidityFollowsAmbvalOK) {
    auto rejects = [](auto mutate) {
        AmbientRecord r = Typical();
        mutate(r);
        return !DecodeRecord(EncodeRecord(r)).has_value() && !IsStorable(r);
    };
    EXPECT_TRUE(rejects([](AmbientRecord& r) { r.weight = 0; }));
    EXPECT_TRUE(rejects([](AmbientRecord& r) { r.weight = -0.5; }));
    EXPECT_TRUE(rejects([](AmbientRecord& r) { r.weight = 1.5; }));
    EXPECT_TRUE(rejects([](AmbientRecord& r) { r.radius[0] = 0; }));
    EXPECT_TRUE(rejects([](AmbientRecord& r) { r.radius[1] = -1; }));
    EXPECT_TRUE(rejects([](AmbientRecord& r) { r.radius[1] = 2e10; }));
    EXPECT_TRUE(rejects([](AmbientRecord& r) { r.position.y = 2e10; }));
    EXPECT_TRUE(rejects([](AmbientRecord& r) { r.position.z = -2e10; }));
    EXPECT_TRUE(rejects([](AmbientRecord& r) { r.posGradient[1] = 2e10; }));
    EXPECT_TRUE(rejects([](AmbientRecord& r) { r.dirGradient[0] = -2e10; }));
    EXPECT_TRUE(rejects([](AmbientRecord& r) { r.value.g = 2e10; }));
    EXPECT_TRUE(rejects([](AmbientRecord& r) { r.normal = {}; }));
    EXPECT_TRUE(rejects([](AmbientRecord& r) { r.uAxis = {}; }));
    EXPECT_TRUE(rejects([](AmbientRecord& r) { r.weight = std::nan(""); }));
    // rad[0] <= rad[1] + FTINY: a first radius larger than the second is one
    // flipped bit away from a valid record, and Radiance stops reading there.
    EXPECT_TRUE(rejects([](AmbientRecord& r) { r.radius[0] = 5; }));
    EXPECT_TRUE(rejects([](AmbientRecord& r) { r.radius[0] = r.radius[1] + 2e-6; }));
    EXPECT_FALSE(rejects([](AmbientRecord& r) { r.radius[0] = r.radius[1] + 0.5e-6; }));
    EXPECT_FALSE(rejects([](AmbientRecord& r) { r.radius[0] = 0.25; }));
    // Not checked by Radiance: level, corral.
    EXPECT_FALSE(rejects([](AmbientRecord& r) { r.level = 200; }));
    EXPECT_FALSE(rejects([](AmbientRecord& r) { r.corral = 0xffffffffu; }));
    EXPECT_TRUE(DecodeRecord(RecordBytes{}) == std::nullopt);  // all zero bytes
    RecordBytes ff;
    ff.fill(0xff);
    EXPECT_FALSE(DecodeRecord(ff).has_value());  // the garbage in bad_garbage_record.amb
}

}  // namespace
}  // namespace rt
