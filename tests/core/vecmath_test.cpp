#include "core/vecmath.h"
#include "core/rgb.h"

#include <gtest/gtest.h>

namespace rt {
namespace {

TEST(Vecmath, CrossIsRightHanded) {
    EXPECT_EQ(Cross(Vec3(1, 0, 0), Vec3(0, 1, 0)), Vec3(0, 0, 1));
}

TEST(Vecmath, PerpendicularIsUnitAndOrthogonal) {
    for (Vec3 n : {Vec3(0, 0, 1), Vec3(1, 0, 0), Vec3(0.6, 0.8, 0), Normalize(Vec3(1, 1, 1))}) {
        Vec3 p = Perpendicular(n);
        EXPECT_NEAR(Length(p), 1.0, 1e-12);
        EXPECT_NEAR(Dot(p, n), 0.0, 1e-12);
    }
}

TEST(Rgb, BrightUsesRadianceWeights) {
    EXPECT_NEAR(Bright(Rgb(1, 1, 1)), 1.0, 1e-8);
    EXPECT_DOUBLE_EQ(Bright(Rgb(0, 1, 0)), 0.670114631);
    EXPECT_DOUBLE_EQ(Intens(Rgb(0.2, 0.7, 0.1)), 0.7);
}

}  // namespace
}  // namespace rt
