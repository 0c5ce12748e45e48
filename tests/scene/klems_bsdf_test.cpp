// SPDX-License-Identifier: MIT
//
// Klems BSDF files (scene/klems_bsdf.h): the basis's patches and directions,
// what a file's blocks become (sides, Lambertian parts, reciprocity, rows
// against columns), the sampler's distribution (chi²), and the reader's
// one-line errors. Whole scenes against real Radiance are in
// tests/data/bsdf/ (tests/direct/direct_matrix_test.cpp).
#include "scene/klems_bsdf.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "core/conventions.h"
#include "core/error.h"
#include "core/random.h"

namespace rt {
namespace {

/// A small basis: the cap to 30° and a ring of four to 90°.
const std::vector<std::pair<double, int>> kTiny = {{0, 1}, {30, 4}};

/// A Klems file on the tiny basis (named "Tiny", defined in the file) with
/// each block's matrix given as rows of outgoing patches (or incident ones
/// with `rows`).
std::string TinyFile(
    const std::vector<std::pair<std::string, std::vector<std::vector<double>>>>& blocks,
    bool rows = false) {
    std::ostringstream s;
    s << "<?xml version=\"1.0\"?>\n<WindowElement xmlns=\"http://windows.lbl.gov\">\n"
         "<Optical><Layer><DataDefinition><IncidentDataStructure>"
      << (rows ? "Rows" : "Columns")
      << "</IncidentDataStructure>\n<AngleBasis><AngleBasisName>Tiny</AngleBasisName>"
         "<AngleBasisBlock><nPhis>1</nPhis><ThetaBounds><LowerTheta>0</LowerTheta>"
         "<UpperTheta>30</UpperTheta></ThetaBounds></AngleBasisBlock>"
         "<AngleBasisBlock><nPhis>4</nPhis><ThetaBounds><LowerTheta>30</LowerTheta>"
         "<UpperTheta>90</UpperTheta></ThetaBounds></AngleBasisBlock></AngleBasis>"
         "</DataDefinition>\n";
    for (const auto& [direction, m] : blocks) {
        s << "<WavelengthData><Wavelength unit=\"Integral\">Visible</Wavelength>"
             "<WavelengthDataBlock><WavelengthDataDirection>"
          << direction
          << "</WavelengthDataDirection><ColumnAngleBasis>Tiny</ColumnAngleBasis>"
             "<RowAngleBasis>Tiny</RowAngleBasis><ScatteringData>\n";
        for (const auto& row : m) {
            for (double v : row) s << v << ", ";
            s << "\n";
        }
        s << "</ScatteringData></WavelengthDataBlock></WavelengthData>\n";
    }
    s << "</Layer></Optical></WindowElement>\n";
    return s.str();
}

KlemsBasis TinyBasis() {
    KlemsBasis b;
    b.name = "Tiny";
    b.thetaMin = {0, 30, 90};
    b.phis = {1, 4};
    b.first = {0, 1};
    b.count = 5;
    return b;
}

KlemsBasis FullBasis() {
    KlemsBasis b;
    b.name = "LBNL/Klems Full";
    const std::pair<double, int> rings[] = {{0, 1},   {5, 8},   {15, 16}, {25, 20}, {35, 24},
                                            {45, 24}, {55, 24}, {65, 16}, {75, 12}};
    for (const auto& [t, n] : rings) {
        b.thetaMin.push_back(t);
        b.phis.push_back(n);
        b.first.push_back(b.count);
        b.count += n;
    }
    b.thetaMin.push_back(90);
    return b;
}

Vec3 Polar(double thetaDegrees, double phiDegrees, double zSign = 1.0) {
    const double t = thetaDegrees * kPi / 180.0, p = phiDegrees * kPi / 180.0;
    return Vec3(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), zSign * std::cos(t));
}

std::string ErrorOf(const std::string& text) {
    try {
        static_cast<void>(ParseBsdf(text, "dir/w.xml"));
    } catch (const Error& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(KlemsBasis, PatchesTileTheHemisphere) {
    const KlemsBasis b = FullBasis();
    double sum = 0;
    for (int i = 0; i < b.count; ++i) {
        sum += b.ProjectedSolidAngle(i);
        // A patch's middle maps back to it; its corners too, just inside.
        EXPECT_EQ(b.Index(b.Direction(i, 0.5, 0.5)), i) << i;
        EXPECT_EQ(b.Index(b.Direction(i, 0.001, 0.001)), i) << i;
        EXPECT_EQ(b.Index(b.Direction(i, 0.999, 0.999)), i) << i;
    }
    EXPECT_NEAR(sum, kPi, 1e-12);  // the projected hemisphere
    EXPECT_EQ(b.count, 145);
    EXPECT_EQ(b.ProjectedSolidAngle(-1), -1.0);
    EXPECT_EQ(b.ProjectedSolidAngle(145), -1.0);
    // Azimuth patches are centred on their angle: patch 1 (the first of the
    // 5–15° ring) spans ±22.5° about +x.
    EXPECT_EQ(b.Index(Polar(10, 22)), 1);
    EXPECT_EQ(b.Index(Polar(10, 23)), 2);
    EXPECT_EQ(b.Index(Polar(10, 338)), 1);
    EXPECT_EQ(b.Index(Polar(4.9, 100)), 0);
    EXPECT_EQ(b.Index(Polar(10, 0, -1)), -1);  // below the surface
    EXPECT_EQ(b.Index(Vec3(1, 0, 0)), -1);     // grazing: past the last bound
}

TEST(KlemsBasis, DirectionsAreUniformInProjectedSolidAngle) {
    // Within the ring 30–90° of the tiny basis, cos²θ of directions at u0
    // must be linear in u0 (Radiance 5.4a's fo_getvec()).
    const KlemsBasis b = TinyBasis();
    for (const double u0 : {0.0, 0.25, 0.5, 0.9}) {
        const Vec3 v = b.Direction(1, u0, 0.5);
        EXPECT_NEAR(v.z * v.z, (1 - u0) * 0.75, 1e-12) << u0;
    }
    // u1 spreads the azimuth over the patch's quarter, centred on +x.
    EXPECT_NEAR(std::atan2(b.Direction(1, 0.5, 0.0).y, b.Direction(1, 0.5, 0.0).x), -kPi / 4,
                1e-12);
    EXPECT_NEAR(std::atan2(b.Direction(1, 0.5, 1.0).y, b.Direction(1, 0.5, 1.0).x), kPi / 4, 1e-12);
}

TEST(KlemsBsdf, WindowsFrontIsRadiancesBack) {
    // Transmission Back = light entering from +z; Reflection Back = seen
    // from +z. Values on the diagonal only.
    std::vector<std::vector<double>> t(5, std::vector<double>(5, 0.0)), r = t;
    t[2][2] = 3.0;  // incident patch 2 straight through
    r[1][1] = 2.0;  // mirror reflection of incident patch 1 (azimuth 180°)
    r[0][0] = 0.5;
    const BsdfData b =
        ParseBsdf(TinyFile({{"Transmission Back", t}, {"Reflection Back", r}}), "t.xml");
    ASSERT_TRUE(b.tf && b.rf);
    EXPECT_FALSE(b.tb || b.rb);
    // Light from the front at azimuth 270° (x, y negated: incident patch 2,
    // centred at 90°), leaving behind straight on: patch 2 again.
    const Vec3 in = Polar(60, 270), through = -in;
    EXPECT_DOUBLE_EQ(b.Evaluate(through, in), 3.0);
    // By reciprocity the reverse path has the same value (the file gives
    // only one side's transmission).
    EXPECT_DOUBLE_EQ(b.Evaluate(in, through), 3.0);
    EXPECT_EQ(b.Transmission(false), &*b.tf);
    // Mirror reflection on the front.
    EXPECT_DOUBLE_EQ(b.Evaluate(Polar(60, 0), Polar(60, 180)), 2.0);
    EXPECT_DOUBLE_EQ(b.Evaluate(Polar(10, 0), Polar(10, 180)), 0.5);
    EXPECT_DOUBLE_EQ(b.Evaluate(Polar(60, 90), Polar(60, 180)), 0.0);
    // Nothing seen from the back: no reflection data there.
    EXPECT_DOUBLE_EQ(b.Evaluate(Polar(60, 0, -1), Polar(60, 180, -1)), 0.0);
}

TEST(KlemsBsdf, SmallestValueBecomesTheLambertianPart) {
    std::vector<std::vector<double>> t(5, std::vector<double>(5, 0.1)),
        r(5, std::vector<double>(5, 0.2));
    t[1][1] += 1.0;
    const BsdfData b =
        ParseBsdf(TinyFile({{"Transmission Front", t}, {"Reflection Front", r}}), "t.xml");
    EXPECT_NEAR(b.tLambBack, 0.1 * kPi, 1e-7);   // entering from behind
    EXPECT_NEAR(b.tLambFront, 0.1 * kPi, 1e-7);  // the other side's, by reciprocity
    EXPECT_NEAR(b.rLambBack, 0.2 * kPi, 1e-7);
    // Reflection is nothing but its Lambertian part: the matrix is dropped.
    EXPECT_FALSE(b.rb);
    ASSERT_TRUE(b.tb);
    // The whole BSDF is unchanged by the split.
    EXPECT_NEAR(b.Evaluate(Polar(45, 0), Polar(45, 180, -1)), 1.1, 1e-6);
    EXPECT_NEAR(b.Evaluate(Polar(45, 90), Polar(45, 180, -1)), 0.1, 1e-6);
    EXPECT_NEAR(b.Evaluate(Polar(45, 90, -1), Polar(45, 180, -1)), 0.2, 1e-6);
    // Hemispherical share above the Lambertian: patch 1's projected solid
    // angle times 1.
    const double ohm = kPi * (0.75 - 0.0) / 4;
    EXPECT_NEAR(b.DirectHemispherical(Polar(45, 180, -1), true), ohm, 1e-6);
    EXPECT_NEAR(b.tb->maxHemispherical(), ohm, 1e-6);
}

TEST(KlemsBsdf, RowsAndColumnsReadTheSameMatrix) {
    std::vector<std::vector<double>> m(5, std::vector<double>(5, 0.0)), transposed = m;
    for (int o = 0; o < 5; ++o)
        for (int i = 0; i < 5; ++i) m[o][i] = 0.01 * (1 + o + 7 * i);
    for (int o = 0; o < 5; ++o)
        for (int i = 0; i < 5; ++i) transposed[i][o] = m[o][i];
    const BsdfData c = ParseBsdf(TinyFile({{"Transmission Back", m}}), "c.xml");
    const BsdfData r =
        ParseBsdf(TinyFile({{"Transmission Back", transposed}}, true), "r.xml");
    for (const double a : {10.0, 50.0}) {
        for (const double p : {0.0, 100.0, 200.0}) {
            const Vec3 in = Polar(a, p), out = Polar(70 - a, p + 45, -1);
            EXPECT_DOUBLE_EQ(c.Evaluate(out, in), r.Evaluate(out, in)) << a << " " << p;
        }
    }
    // And which index is which: light from the cap (incident patch 0)
    // leaving through outgoing patch 3 reads m[3][0].
    EXPECT_NEAR(c.Evaluate(Polar(60, 180, -1), Polar(5, 0)), m[3][0], 1e-7);
}

TEST(KlemsBsdf, SamplerDrawsPatchesByTheirShare) {
    // One incident patch's row: shares 0, 1, 2, 3, 4 over the outgoing
    // patches (values scaled by their projected solid angles). Chi² of
    // 40000 draws against those shares, 4 degrees of freedom: below 18.5
    // (p = 0.001).
    const KlemsBasis basis = TinyBasis();
    std::vector<std::vector<double>> t(5, std::vector<double>(5, 0.0));
    for (int o = 0; o < 5; ++o) t[o][0] = o / basis.ProjectedSolidAngle(o);
    const BsdfData b = ParseBsdf(TinyFile({{"Transmission Back", t}}), "t.xml");
    ASSERT_TRUE(b.tf);
    const Vec3 in(0, 0, 1);
    EXPECT_NEAR(b.tf->Total(in), 10.0, 1e-5);
    Rng rng(7);
    std::vector<int> counts(5, 0);
    constexpr int kDraws = 40000;
    for (int n = 0; n < kDraws; ++n) {
        const auto dir = b.tf->Sample(in, rng.Uniform(), rng.Uniform(), rng.Uniform());
        ASSERT_TRUE(dir.has_value());
        ASSERT_LT(dir->z, 0.0);  // transmitted: leaves behind
        const int o = basis.Index(Vec3(dir->x, dir->y, -dir->z));
        ASSERT_GE(o, 0);
        ++counts[static_cast<std::size_t>(o)];
    }
    EXPECT_EQ(counts[0], 0);
    double chi2 = 0;
    for (int o = 1; o < 5; ++o) {
        const double expected = kDraws * o / 10.0;
        chi2 += (counts[static_cast<std::size_t>(o)] - expected) *
                (counts[static_cast<std::size_t>(o)] - expected) / expected;
    }
    EXPECT_LT(chi2, 18.5);
    // Nothing to sample in a row of zeros.
    EXPECT_FALSE(b.tf->Sample(Polar(60, 0), 0.5, 0.5, 0.5).has_value());
}

TEST(KlemsBsdf, ProjectedSolidAnglesOfTheQueriedPatches) {
    std::vector<std::vector<double>> t(5, std::vector<double>(5, 0.0));
    t[0][0] = 1.0;
    const BsdfData b = ParseBsdf(TinyFile({{"Transmission Back", t}}), "t.xml");
    const double cap = kPi * 0.25, side = kPi * 0.75 / 4;
    double psa[2];
    b.Size(psa, Polar(10, 0), nullptr, true);  // the view's patch, both ways
    EXPECT_NEAR(psa[0], cap, 1e-12);
    EXPECT_NEAR(psa[1], cap, 1e-12);
    const Vec3 source = Polar(60, 0);
    b.Size(psa, Polar(10, 0, -1), &source, false);
    EXPECT_NEAR(psa[0], side, 1e-12);  // by reciprocity: the source's smaller patch
    // No reflection data: a reflected pair is all diffuse.
    b.Size(psa, Polar(10, 0), &source, false);
    EXPECT_NEAR(psa[0], kPi, 1e-12);
}

TEST(KlemsBsdf, BadFilesGiveOneLineErrors) {
    EXPECT_EQ(ErrorOf("<WindowElement><Optical>"),
              "dir/w.xml: byte 23: bad XML in BSDF file: Start-end tags mismatch");
    EXPECT_EQ(ErrorOf("<Window/>"), "dir/w.xml: top level node not 'WindowElement'");
    EXPECT_EQ(ErrorOf("<WindowElement/>"), "dir/w.xml: no optical layer");
    EXPECT_EQ(ErrorOf("<WindowElement><Optical><Layer/></Optical></WindowElement>"),
              "dir/w.xml: missing IncidentDataStructure");
    EXPECT_EQ(ErrorOf("<WindowElement><Optical><Layer><DataDefinition><IncidentDataStructure>"
                      "Matrix</IncidentDataStructure></DataDefinition></Layer></Optical>"
                      "</WindowElement>"),
              "dir/w.xml: unsupported IncidentDataStructure 'Matrix'");
    std::vector<std::vector<double>> t(5, std::vector<double>(5, 0.1));
    std::string good = TinyFile({{"Transmission Back", t}});
    std::string noColumn = good;
    noColumn.replace(noColumn.find("<ColumnAngleBasis>Tiny</ColumnAngleBasis>"), 41, "");
    EXPECT_EQ(ErrorOf(noColumn), "dir/w.xml: missing column basis");
    std::string unknown = good;
    unknown.replace(unknown.find("<RowAngleBasis>Tiny"), 19, "<RowAngleBasis>Huge");
    EXPECT_EQ(ErrorOf(unknown), "dir/w.xml: undefined RowAngleBasis 'Huge'");
    std::string shortData = good;
    shortData.replace(shortData.find("0.1, \n</ScatteringData>"), 5, "");
    EXPECT_EQ(ErrorOf(shortData), "dir/w.xml: bad or missing ScatteringData (value 25 of 25)");
    std::string badPhis = good;
    badPhis.replace(badPhis.find("<nPhis>4</nPhis>"), 16, "<nPhis>x</nPhis>");
    EXPECT_EQ(ErrorOf(badPhis), "dir/w.xml: bad number 'x' in angle basis 'Tiny'");
    std::string oneAfterCap = good;
    oneAfterCap.replace(oneAfterCap.find("<nPhis>4</nPhis>"), 16, "<nPhis>1</nPhis>");
    EXPECT_EQ(ErrorOf(oneAfterCap), "dir/w.xml: illegal ring in angle basis 'Tiny'");
    std::string disagree = good;
    disagree.replace(disagree.find("<LowerTheta>30</LowerTheta>"), 27,
                     "<LowerTheta>31</LowerTheta>");
    EXPECT_EQ(ErrorOf(disagree), "dir/w.xml: theta values disagree in angle basis 'Tiny'");
    // A huge basis is refused before anything is allocated for it.
    std::string huge = good;
    huge.replace(huge.find("<nPhis>4</nPhis>"), 16, "<nPhis>90000</nPhis>");
    EXPECT_EQ(ErrorOf(huge), "dir/w.xml: bad or missing ScatteringData (too few values)");
    // Values beyond single precision (the fuzzer's find: sampling tables of
    // infinities gave NaN directions).
    std::string huge2 = good;
    huge2.replace(huge2.find("0.1, "), 4, "1e39");
    EXPECT_EQ(ErrorOf(huge2), "dir/w.xml: ScatteringData values too large");
    // The good file parses.
    EXPECT_EQ(ErrorOf(good), "(no error)");
}

TEST(BsdfFileCache, LoadsEachFileOnceAndSearchesThePath) {
    const std::string dir = ::testing::TempDir() + "bsdfcache_" + std::to_string(getpid());
    ASSERT_EQ(std::system(("mkdir -p " + dir).c_str()), 0);
    std::vector<std::vector<double>> t(5, std::vector<double>(5, 0.1));
    std::ofstream(dir + "/w.xml") << TinyFile({{"Transmission Back", t}});
    cal::SearchPath path;
    path.entries = {"/nonexistent", dir};
    BsdfFileCache cache(path);
    const auto a = cache.Load("w.xml", "s.rad:1: BSDF \"b\"");
    EXPECT_EQ(a, cache.Load("w.xml", "s.rad:9: aBSDF \"c\""));
    EXPECT_NEAR(a->tLambFront, 0.1 * kPi, 1e-7);
    try {
        static_cast<void>(cache.Load("missing.xml", "s.rad:3: BSDF \"b\""));
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), Error::Kind::System);
        EXPECT_EQ(std::string(e.what()),
                  "s.rad:3: BSDF \"b\": cannot find BSDF file \"missing.xml\"");
    }
    std::system(("rm -rf " + dir).c_str());
}

}  // namespace
}  // namespace rt
