// SPDX-License-Identifier: MIT
//
// Radiance's affine transforms (MAT4 + XF scale, src/common/xf.c): a 4×4
// matrix acting on row vectors, p' = p·M, the translation in the last row.
// Built from transform arguments by scene/transform.h; used for pattern
// spaces now and object-to-world transforms of instances later.
#pragma once

#include <cmath>

#include "core/vecmath.h"

namespace rt {

struct Transform {
    double m[4][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
    /// Overall uniform scale, negative when the transform mirrors (odd number of -m*
    /// or negative -s).
    double scale = 1;

    Vec3 Point(const Vec3& p) const {
        Vec3 r;
        for (int j = 0; j < 3; ++j) r[j] = p.x * m[0][j] + p.y * m[1][j] + p.z * m[2][j] + m[3][j];
        return r;
    }
    Vec3 Vector(const Vec3& v) const {
        Vec3 r;
        for (int j = 0; j < 3; ++j) r[j] = v.x * m[0][j] + v.y * m[1][j] + v.z * m[2][j];
        return r;
    }
    /// Row i of the 3×3 part: where the unit vector along axis i goes.
    Vec3 Row(int i) const { return {m[i][0], m[i][1], m[i][2]}; }
};

/// `a` then `b` (row vectors: the matrix product a·b).
inline Transform Compose(const Transform& a, const Transform& b) {
    Transform r;
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) {
            double sum = 0;
            for (int k = 0; k < 4; ++k) sum += a.m[i][k] * b.m[k][j];
            r.m[i][j] = sum;
        }
    }
    r.scale = a.scale * b.scale;
    return r;
}

/// The inverse of an affine transform (the 3×3 part must be invertible, as
/// every transform of Radiance's arguments is): Compose(t, Inverse(t)) is
/// the identity up to rounding. Its scale is 1/t.scale.
inline Transform Inverse(const Transform& t) {
    const auto& a = t.m;
    const double c00 = a[1][1] * a[2][2] - a[1][2] * a[2][1];
    const double c01 = a[1][2] * a[2][0] - a[1][0] * a[2][2];
    const double c02 = a[1][0] * a[2][1] - a[1][1] * a[2][0];
    const double det = a[0][0] * c00 + a[0][1] * c01 + a[0][2] * c02;
    Transform r;
    r.m[0][0] = c00 / det;
    r.m[0][1] = (a[0][2] * a[2][1] - a[0][1] * a[2][2]) / det;
    r.m[0][2] = (a[0][1] * a[1][2] - a[0][2] * a[1][1]) / det;
    r.m[1][0] = c01 / det;
    r.m[1][1] = (a[0][0] * a[2][2] - a[0][2] * a[2][0]) / det;
    r.m[1][2] = (a[0][2] * a[1][0] - a[0][0] * a[1][2]) / det;
    r.m[2][0] = c02 / det;
    r.m[2][1] = (a[0][1] * a[2][0] - a[0][0] * a[2][1]) / det;
    r.m[2][2] = (a[0][0] * a[1][1] - a[0][1] * a[1][0]) / det;
    // Translation row: -(t's translation)·(inverse 3×3).
    for (int j = 0; j < 3; ++j) {
        r.m[3][j] = -(a[3][0] * r.m[0][j] + a[3][1] * r.m[1][j] + a[3][2] * r.m[2][j]);
    }
    r.scale = 1.0 / t.scale;
    return r;
}

}  // namespace rt
