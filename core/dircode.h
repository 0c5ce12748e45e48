// SPDX-License-Identifier: MIT
//
// Radiance's 32-bit unit-vector code (src/common/dircode.c encodedir/decodedir,
// radiance-notes.md §5.5): sign bits for x, y, z, two flag bits naming which two
// components are stored, and the two smaller magnitudes in 13 bits each; the
// largest component is recovered from the unit length. Mean error ≈ 0.0022°.
#pragma once

#include <cstdint>

#include "core/vecmath.h"

namespace rt {

/// Code 0 means "zero vector" and makes an ambient record invalid.
inline constexpr std::uint32_t kZeroDirectionCode = 0;

/// encodedir(): `v` should be unit length (it is not normalised here, as in Radiance);
/// returns kZeroDirectionCode when every component rounds to 0. For far-from-unit
/// input the stored fields are masked to 13 bits where Radiance lets them spill into
/// the neighbouring bits; either code is meaningless then.
std::uint32_t EncodeDirection(const Vec3& v);

/// decodedir(): kZeroDirectionCode gives (0, 0, 0). Codes whose stored magnitudes
/// exceed unit length (only possible in damaged data) give a NaN component, exactly
/// as Radiance's sqrt of a negative number does; DecodeRecord() rejects those.
Vec3 DecodeDirection(std::uint32_t code);

}  // namespace rt
