// SPDX-License-Identifier: MIT
#include "ambfiles/record_codec.h"

#include <cmath>

#include "core/conventions.h"
#include "core/dircode.h"
#include "core/portable.h"

namespace rt {
namespace {

constexpr double kHuge = 1e10;  // FHUGE

// Radiance holds every stored quantity as float (AMBVAL), so values are rounded to
// float before putflt(), and getflt() results are rounded to float on assignment.
float ToFloat(double v) { return static_cast<float>(v); }

void PutFloatField(double v, std::uint8_t* out) { PutPortableFloat(ToFloat(v), out); }
double GetFloatField(const std::uint8_t* in) { return ToFloat(GetPortableFloat(in)); }

// badflt(): outside [−FHUGE, FHUGE]. Written as a negated range test so NaN would
// also count as bad (decoded fields are always finite, so this never differs).
bool BadFloat(double v) { return !(v >= -kHuge && v <= kHuge); }

}  // namespace

RecordBytes EncodeRecord(const AmbientRecord& r) {
    RecordBytes b{};
    const auto& f = kRecordLayout;
    PutPortableInt(r.level, 1, &b[f[0].offset]);
    PutFloatField(r.weight, &b[f[1].offset]);
    for (int i = 0; i < 3; ++i) {
        PutFloatField(r.position[i], &b[f[2].offset + kPortableFloatBytes * i]);
    }
    PutPortableInt(EncodeDirection(r.normal), 4, &b[f[3].offset]);
    PutPortableInt(EncodeDirection(r.uAxis), 4, &b[f[4].offset]);
    const auto rgbe = EncodeRgbe(ToFloat(r.value.r), ToFloat(r.value.g), ToFloat(r.value.b));
    for (std::size_t i = 0; i < kRgbeBytes; ++i) b[f[5].offset + i] = rgbe[i];
    for (int i = 0; i < 2; ++i) {
        PutFloatField(r.radius[i], &b[f[6].offset + kPortableFloatBytes * i]);
        PutFloatField(r.posGradient[i], &b[f[7].offset + kPortableFloatBytes * i]);
        PutFloatField(r.dirGradient[i], &b[f[8].offset + kPortableFloatBytes * i]);
    }
    PutPortableInt(r.corral, 4, &b[f[9].offset]);
    return b;
}

std::optional<AmbientRecord> DecodeRecord(std::span<const std::uint8_t, kRecordBytes> b) {
    const auto& f = kRecordLayout;
    AmbientRecord r;
    r.level = b[f[0].offset];
    r.weight = GetFloatField(&b[f[1].offset]);
    for (int i = 0; i < 3; ++i) {
        r.position[i] = GetFloatField(&b[f[2].offset + kPortableFloatBytes * i]);
    }
    const auto ndir = static_cast<std::uint32_t>(GetPortableInt(&b[f[3].offset], 4));
    const auto udir = static_cast<std::uint32_t>(GetPortableInt(&b[f[4].offset], 4));
    const Rgb value = DecodeRgbe(&b[f[5].offset]);
    r.value = {ToFloat(value.r), ToFloat(value.g), ToFloat(value.b)};
    for (int i = 0; i < 2; ++i) {
        r.radius[i] = GetFloatField(&b[f[6].offset + kPortableFloatBytes * i]);
        r.posGradient[i] = GetFloatField(&b[f[7].offset + kPortableFloatBytes * i]);
        r.dirGradient[i] = GetFloatField(&b[f[8].offset + kPortableFloatBytes * i]);
    }
    r.corral = static_cast<std::uint32_t>(GetPortableInt(&b[f[9].offset], 4));

    // ambvalOK(), in its order.
    for (int i = 0; i < 3; ++i) {
        if (BadFloat(r.position[i])) return std::nullopt;
    }
    if (ndir == kZeroDirectionCode || udir == kZeroDirectionCode) return std::nullopt;
    if (!(r.weight > 0.0 && r.weight <= 1.0)) return std::nullopt;
    for (double rad : r.radius) {
        if (!(rad > 0.0 && rad < kHuge)) return std::nullopt;
    }
    if (r.radius[0] > r.radius[1] + kFtiny) return std::nullopt;
    for (int i = 0; i < 3; ++i) {
        if (!(r.value[i] >= 0.0 && r.value[i] < kHuge)) return std::nullopt;
    }
    for (int i = 0; i < 2; ++i) {
        if (BadFloat(r.posGradient[i]) || BadFloat(r.dirGradient[i])) return std::nullopt;
    }
    r.normal = DecodeDirection(ndir);
    r.uAxis = DecodeDirection(udir);
    if (!IsFinite(r.normal) || !IsFinite(r.uAxis)) return std::nullopt;
    return r;
}

bool IsStorable(const AmbientRecord& record) {
    const RecordBytes bytes = EncodeRecord(record);
    return DecodeRecord(bytes).has_value();
}

}  // namespace rt
