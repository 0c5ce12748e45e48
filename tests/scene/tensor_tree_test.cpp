// SPDX-License-Identifier: MIT
//
// Tensor-tree BSDF files (scene/tensor_tree.h): the concentric map, the
// order of a tree's children and of a leaf grid's values, the isotropic
// (TensorTree3) coordinates, the Lambertian part, the hemispherical total
// against an integral over directions, the sampler's distribution (chi²),
// and the reader's one-line errors. Whole scenes against real Radiance are
// in tests/data/bsdf_tree/ (tests/direct/direct_matrix_test.cpp).
#include "scene/tensor_tree.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "core/conventions.h"
#include "core/error.h"
#include "core/random.h"

namespace rt {
namespace {

/// A tensor-tree file of `rank` with each (WINDOW direction, tree text)
/// block, on the Shirley-Chiu basis unless `basis` says otherwise.
std::string TreeFile(int rank, const std::vector<std::pair<std::string, std::string>>& blocks,
                     const std::string& basis = "LBNL/Shirley-Chiu") {
    std::ostringstream s;
    s << "<?xml version=\"1.0\"?>\n<WindowElement xmlns=\"http://windows.lbl.gov\">\n"
         "<Optical><Layer><DataDefinition><IncidentDataStructure>TensorTree"
      << rank << "</IncidentDataStructure></DataDefinition>\n";
    for (const auto& [direction, tree] : blocks) {
        s << "<WavelengthData><Wavelength unit=\"Integral\">Visible</Wavelength>"
             "<WavelengthDataBlock><WavelengthDataDirection>"
          << direction << "</WavelengthDataDirection><AngleBasis>" << basis
          << "</AngleBasis><ScatteringData>" << tree
          << "</ScatteringData></WavelengthDataBlock></WavelengthData>\n";
    }
    s << "</Layer></Optical></WindowElement>\n";
    return s.str();
}

/// A leaf grid's text: `values` as written.
std::string Leaf(const std::vector<double>& values) {
    std::ostringstream s;
    s << "{ ";
    for (double v : values) s << v << ", ";
    s << "}";
    return s.str();
}

std::string ErrorOf(const std::string& text) {
    try {
        static_cast<void>(ParseBsdf(text, "dir/t.xml"));
    } catch (const Error& e) {
        return e.what();
    }
    return "(no error)";
}

Vec3 Unit(double x, double y, double z) { return Normalize(Vec3(x, y, z)); }

TEST(ConcentricMap, KeepsAreasAndLibBsdfsOrientation) {
    double d[2], s[2];
    SquareToDisk(1.0, 0.5, d);  // the right edge's middle: +x
    EXPECT_NEAR(d[0], 1.0, 1e-15);
    EXPECT_NEAR(d[1], 0.0, 1e-15);
    SquareToDisk(0.5, 1.0, d);  // the top edge's middle: +y
    EXPECT_NEAR(d[0], 0.0, 1e-15);
    EXPECT_NEAR(d[1], 1.0, 1e-15);
    // Round trips, and the share of a regular grid of the square within
    // radius r is r² (the map keeps areas) to the grid's resolution.
    constexpr int kN = 600;
    int inside = 0;
    for (int i = 0; i < kN; ++i) {
        for (int j = 0; j < kN; ++j) {
            const double sx = (i + 0.5) / kN, sy = (j + 0.5) / kN;
            SquareToDisk(sx, sy, d);
            DiskToSquare(d[0], d[1], s);
            ASSERT_NEAR(s[0], sx, 1e-12);
            ASSERT_NEAR(s[1], sy, 1e-12);
            inside += d[0] * d[0] + d[1] * d[1] < 0.49;
        }
    }
    EXPECT_NEAR(double(inside) / (kN * kN), 0.49, 0.004);
}

TEST(TensorTree, GridValuesRunAxisZeroSlowestAndBranchesByBit) {
    // Light from the front along -in = (0.5, -0.3): on the square, axis 0
    // upper, axis 1 lower; transmitted toward (-0.2, -0.6): axes 2 and 3
    // lower. A 2-a-side grid holds it at index 1·8 = 8 (axis 0 slowest);
    // a branch of 16 constant children at child 1 (bit 0 for axis 0).
    const Vec3 in = Unit(-0.5, 0.3, 0.8), out = Unit(-0.2, -0.6, -0.77);
    std::vector<double> grid(16);
    for (int k = 0; k < 16; ++k) grid[std::size_t(k)] = 1 + k;  // min 1 > 1.5/π: kept whole
    const BsdfData g = ParseBsdf(TreeFile(4, {{"Transmission Back", Leaf(grid)}}), "g.xml");
    ASSERT_TRUE(g.tf);
    EXPECT_FLOAT_EQ(g.tf->Value(out, in).value(), 9.0f);
    EXPECT_FLOAT_EQ(g.Evaluate(out, in), 9.0);
    EXPECT_FLOAT_EQ(g.Evaluate(in, out), 9.0);                 // reciprocity: the same pair
    EXPECT_FALSE(g.tf->Value(in, Unit(0, 0, 1)).has_value());  // both in front
    std::string branch = "{ ";
    for (int n = 0; n < 16; ++n) branch += "{ " + std::to_string(1 + n) + " } ";
    branch += "}";
    const BsdfData b = ParseBsdf(TreeFile(4, {{"Transmission Back", branch}}), "b.xml");
    EXPECT_FLOAT_EQ(b.Evaluate(out, in), 2.0);
    // Light from behind meets "Transmission Front", the tree WINDOW calls
    // front (Radiance's back); with only that, light from the front meets
    // it by reciprocity.
    const BsdfData f = ParseBsdf(TreeFile(4, {{"Transmission Front", Leaf(grid)}}), "f.xml");
    ASSERT_TRUE(f.tb && !f.tf);
    EXPECT_EQ(f.Transmission(true), f.tb.get());
    const Vec3 inBack(in.x, in.y, -in.z), outFront(out.x, out.y, -out.z);
    EXPECT_FLOAT_EQ(f.Evaluate(outFront, inBack), 9.0);
    EXPECT_FLOAT_EQ(f.Evaluate(inBack, outFront), 9.0);
}

TEST(TensorTree, IsotropicDataTurnsWithTheIncidentAzimuth) {
    // A TensorTree3 grid 4 a side whose values all differ: turning both
    // directions about the normal keeps the value, turning one changes it.
    std::vector<double> grid(64);
    for (int k = 0; k < 64; ++k) grid[std::size_t(k)] = 0.5 + 0.1 * k;
    const BsdfData b = ParseBsdf(TreeFile(3, {{"Reflection Back", Leaf(grid)}}), "i.xml");
    ASSERT_TRUE(b.rf);
    const Vec3 in = Unit(0.6, 0.1, 0.5), out = Unit(-0.3, 0.35, 0.7);
    const double f = b.Evaluate(out, in);
    for (double turn : {0.4, 1.3, 2.9, -2.2}) {
        const double c = std::cos(turn), s = std::sin(turn);
        const auto spin = [&](const Vec3& v) {
            return Vec3(c * v.x - s * v.y, s * v.x + c * v.y, v.z);
        };
        EXPECT_FLOAT_EQ(b.Evaluate(spin(out), spin(in)), f) << turn;
    }
    EXPECT_NE(b.Evaluate(out, Unit(-0.1, 0.6, 0.5)), f);
}

TEST(TensorTree, SmallestLiveValueIsTheLambertianPart) {
    // TensorTree3: the dead half (axis 0 >= 0.5) may hold smaller values;
    // they do not count. The live minimum 0.1 (between 0.01/π and 1.5/π)
    // is taken out as 0.1·π.
    std::string tree = "{ ";
    for (int n = 0; n < 8; ++n) tree += (n & 1) ? "{ 0.01 } " : (n == 2 ? "{ 0.1 } " : "{ 0.4 } ");
    tree += "}";
    const BsdfData b = ParseBsdf(TreeFile(3, {{"Transmission Back", tree}}), "l.xml");
    EXPECT_NEAR(b.tLambFront, 0.1 * kPi, 1e-7);
    EXPECT_NEAR(b.tLambBack, 0.1 * kPi, 1e-7);  // reciprocity's copy
    ASSERT_TRUE(b.tf);
    // get_extrema() before the subtraction: the mean over the live half
    // (its cells are half a side, so one incident step) is (0.4 + 0.1 +
    // 0.4 + 0.4)/4, less the Lambertian part: 0.225·π.
    EXPECT_NEAR(b.tf->maxHemispherical(), 0.225 * kPi, 1e-6);
    // A constant tree is all Lambertian: no component left.
    const BsdfData c = ParseBsdf(TreeFile(4, {{"Reflection Front", "{ 0.2 }"}}), "c.xml");
    EXPECT_FALSE(c.rb);
    EXPECT_NEAR(c.rLambBack, 0.2 * kPi, 1e-7);
    EXPECT_NEAR(c.Evaluate(Unit(0, 0.3, -1), Unit(0.2, 0, -1)), 0.2, 1e-7);
    // Too large a minimum (1.5/π or more) stays in the tree.
    const BsdfData d = ParseBsdf(TreeFile(4, {{"Reflection Front", "{ 0.6 }"}}), "d.xml");
    EXPECT_DOUBLE_EQ(d.rLambBack, 0.0);
    ASSERT_TRUE(d.rb);
}

/// A TensorTree4 grid 2 a side: 0.2 everywhere (the Lambertian part) but
/// the slice for light from the front with -in in the square's upper-upper
/// quarter, which holds 1, 2, 3 and 4 over the four output quarters.
BsdfData SliceTree() {
    std::vector<double> grid(16, 0.2);
    for (int k = 0; k < 4; ++k) grid[std::size_t(12 + k)] = 1 + k;
    return ParseBsdf(TreeFile(4, {{"Transmission Back", Leaf(grid)}}), "s.xml");
}

TEST(TensorTree, TotalIsTheIntegralOverProjectedSolidAngle) {
    const BsdfData b = SliceTree();
    ASSERT_TRUE(b.tf);
    const Vec3 in = Unit(-0.4, -0.3, 0.7);  // -in = (0.4, 0.3): upper-upper
    // Above the Lambertian part: (0.8 + 1.8 + 2.8 + 3.8)/4 · π.
    EXPECT_NEAR(b.tf->Total(in), 2.3 * kPi, 1e-6);  // float values
    EXPECT_NEAR(b.DirectHemispherical(in, true), 2.3 * kPi, 1e-6);
    // The same by integrating the BSDF times cosθ over the back hemisphere
    // (midpoints in θ and φ, independent of the square): within 0.5 %.
    constexpr int kTheta = 400, kPhi = 800;
    double sum = 0;
    for (int i = 0; i < kTheta; ++i) {
        const double t = (i + 0.5) * (kPi / 2) / kTheta;
        for (int j = 0; j < kPhi; ++j) {
            const double p = (j + 0.5) * 2 * kPi / kPhi;
            const Vec3 out(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), -std::cos(t));
            sum += (b.Evaluate(out, in) - b.tLambFront / kPi) * std::cos(t) * std::sin(t);
        }
    }
    sum *= (kPi / 2 / kTheta) * (2 * kPi / kPhi);
    EXPECT_NEAR(sum / (2.3 * kPi), 1.0, 0.005);
    // The other slices hold nothing above the Lambertian part.
    EXPECT_NEAR(b.tf->Total(Unit(0.4, 0.3, 0.7)), 0.0, 1e-12);
    double psa[2];
    b.Size(psa, in, nullptr, true);  // output cells a half a side
    EXPECT_NEAR(psa[0], kPi / 4, 1e-12);
    EXPECT_NEAR(psa[1], kPi / 4, 1e-12);
}

TEST(TensorTree, SamplerDrawsCellsByTheirShare) {
    // Chi² of 40000 draws over the four output quarters against the shares
    // 0.8 : 1.8 : 2.8 : 3.8, 3 degrees of freedom: below 16.3 (p = 0.001).
    const BsdfData b = SliceTree();
    const Vec3 in = Unit(-0.4, -0.3, 0.7);
    Rng rng(11);
    int counts[4] = {0, 0, 0, 0};
    constexpr int kDraws = 40000;
    for (int n = 0; n < kDraws; ++n) {
        const auto dir = b.tf->Sample(in, rng.Uniform(), rng.Uniform(), rng.Uniform());
        ASSERT_TRUE(dir.has_value());
        ASSERT_LT(dir->z, 0.0);  // transmitted: leaves behind
        ASSERT_NEAR(Length(*dir), 1.0, 1e-9);
        double s[2];
        DiskToSquare(dir->x, dir->y, s);
        ++counts[(s[0] >= 0.5 ? 2 : 0) + (s[1] >= 0.5 ? 1 : 0)];
    }
    double chi2 = 0;
    for (int k = 0; k < 4; ++k) {
        const double expected = kDraws * (0.8 + k) / 9.2;
        chi2 += (counts[k] - expected) * (counts[k] - expected) / expected;
    }
    EXPECT_LT(chi2, 16.3);
    // Light from behind: reversed, the sample leaves in front.
    const BsdfData t = ParseBsdf(TreeFile(4, {{"Transmission Back",
                                               "{ { 1 } { 0.1 } { 0.1 } "
                                               "{ 0.1 } { 0.1 } { 0.1 } "
                                               "{ 0.1 } { 0.1 } { 0.1 } "
                                               "{ 0.1 } { 0.1 } { 0.1 } "
                                               "{ 0.1 } { 0.1 } { 0.1 } "
                                               "{ 0.1 } }"}}),
                                 "r.xml");
    const auto back = t.tf->Sample(Unit(-0.3, -0.4, -0.8), 0.3, 0.5, 0.5);
    ASSERT_TRUE(back.has_value());
    EXPECT_GT(back->z, 0.0);
}

TEST(TensorTree, BadTreesGiveOneLineErrors) {
    const std::string head = TreeFile(4, {{"Transmission Back", "@"}});
    const auto with = [&](const std::string& tree) {
        std::string s = head;
        s.replace(s.find('@'), 1, tree);
        return s;
    };
    const long long at = static_cast<long long>(head.find('@'));
    const auto byte = [&](long long offset) {
        return "dir/t.xml: byte " + std::to_string(at + offset) + ": ";
    };
    EXPECT_EQ(ErrorOf(with("1 2")), byte(0) + "missing '{' in tensor tree");
    EXPECT_EQ(ErrorOf(with("{ 1 2 3 }")), byte(2) + "illegal value count in tensor tree (3)");
    EXPECT_EQ(ErrorOf(with("{ 1 ")), byte(4) + "missing '}' in tensor tree");
    EXPECT_EQ(ErrorOf(with("{ x }")), byte(2) + "real format error in tensor tree");
    EXPECT_EQ(ErrorOf(with("{ 1e40 }")), byte(2) + "value out of range in tensor tree");
    EXPECT_EQ(ErrorOf(with("{ 1 } }")), byte(6) + "extra characters at end of ScatteringData");
    EXPECT_EQ(ErrorOf(with("{ { 1 } }")), byte(8) + "missing '{' in tensor tree");
    EXPECT_EQ(ErrorOf(TreeFile(4, {{"Transmission Back", "{ 1 }"}}, "LBNL/Klems Full")),
              "dir/t.xml: unsupported angle basis 'LBNL/Klems Full' for a tensor tree");
    EXPECT_EQ(ErrorOf(TreeFile(4, {{"Transmission Back", "{ 1 }"}}, "")),
              "dir/t.xml: missing angle basis for a tensor tree");
    EXPECT_EQ(ErrorOf(TreeFile(4, {{"Transmission Back", " "}})),
              "dir/t.xml: missing ScatteringData");
    // Seventeen levels of halving: finer than libBSDF's sampling tables.
    std::string deep;
    for (int k = 0; k < 17; ++k) deep += "{ ";
    deep += "{ 1 }";
    EXPECT_EQ(ErrorOf(with(deep)), byte(34) + "tensor tree finer than 2^16 cells a side");
    EXPECT_EQ(ErrorOf(with("{ 1 }")), "(no error)");
}

}  // namespace
}  // namespace rt
