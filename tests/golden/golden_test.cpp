// End-to-end: build/bin/rtrace against outputs of real Radiance 5.4a on the
// shared scenes (scenes/*/ref/). At -ab 0 lazyrad claims to print what Radiance
// prints, so every number on every line (value, length, point, normal,
// unperturbed normal) must agree to within kMaxLastDigits units of the 7th
// significant digit, the last one rtrace's %e prints, and the modifier names
// must be identical.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "tests/testing/shell.h"

namespace {

const std::string kSource = RT_SOURCE_DIR;
const std::string kRtrace = std::string(RT_BINARY_DIR) + "/bin/rtrace";

struct Row {
    std::vector<double> numbers;
    std::string modifier;
};

std::vector<Row> ParseRows(std::istream& in) {
    std::vector<Row> rows;
    std::string line;
    while (std::getline(in, line)) {
        Row row;
        std::istringstream words(line);
        std::string w;
        while (words >> w) {
            char* end = nullptr;
            double v = std::strtod(w.c_str(), &end);
            if (end && *end == '\0') {
                row.numbers.push_back(v);
            } else {
                // Names (surface, modifier, material) in order.
                row.modifier += row.modifier.empty() ? w : " " + w;
            }
        }
        rows.push_back(row);
    }
    return rows;
}

/// Runs a shell command and returns its standard output; fails the test on a
/// non-zero exit.
std::string RunCommand(const std::string& command) {
    const rt::testing::ShellResult r = rt::testing::RunShell(command);
    EXPECT_EQ(r.status, 0) << command;
    return r.out;
}

// Both programs round to 7 significant digits, so numbers that differ by less
// than one unit of the last digit can print one unit apart. Two units leave
// room for that and for a true difference of about one unit (evaluation order,
// libm); a wrong formula, constant or hit point shows as many more.
constexpr double kMaxLastDigits = 2.0;

// Below these magnitudes a number counts as zero: Radiance prints some
// coordinates that are 0 in exact arithmetic as rounding residue of order 1e-16
// (scene units), and lit values in the shared scenes are many orders of
// magnitude above 1e-9 W·sr⁻¹·m⁻².
constexpr double kValueFloor = 1e-9;     // W·sr⁻¹·m⁻²
constexpr double kGeometryFloor = 1e-9;  // scene units, and for the unit normals

/// |a − b| in units of the 7th significant digit of the larger magnitude (at
/// least `floor`): 1 means the two differ by one in the last digit printed by %e.
double LastDigitsApart(double a, double b, double floor) {
    const double larger = std::max({std::fabs(a), std::fabs(b), floor});
    const double lastDigit = std::pow(10.0, std::floor(std::log10(larger)) - 6);
    return std::fabs(a - b) / lastDigit;
}

/// Runs `cmd` (an rtrace -h -ab 0 command, -ovlpnNm or -I) and compares its
/// output with Radiance's in the file `refPath`; `scene` names the case in the
/// report. The first three numbers of a line are a colour.
void CompareOutput(const std::string& scene, const std::string& cmd, const std::string& refPath) {
    std::istringstream out(RunCommand(cmd));
    std::ifstream refFile(refPath);
    ASSERT_TRUE(refFile) << refPath;
    auto got = ParseRows(out);
    auto want = ParseRows(refFile);
    ASSERT_EQ(got.size(), want.size());
    static const char* const kFields[13] = {"red",      "green",    "blue",     "length", "point x",
                                            "point y",  "point z",  "normal x", "normal y",
                                            "normal z", "normal x (unperturbed)",
                                            "normal y (unperturbed)", "normal z (unperturbed)"};
    double largest = 0;
    std::size_t largestLine = 0;
    int largestField = 0, numbers = 0, differing = 0;
    for (size_t i = 0; i < want.size(); ++i) {
        const Row& g = got[i];
        const Row& w = want[i];
        ASSERT_TRUE(w.numbers.size() == 13u || w.numbers.size() == 3u) << refPath;
        ASSERT_EQ(g.numbers.size(), w.numbers.size()) << "line " << i + 1;
        EXPECT_EQ(g.modifier, w.modifier) << "line " << i + 1;
        for (int k = 0; k < static_cast<int>(w.numbers.size()); ++k) {
            const double floor = k < 3 ? kValueFloor : kGeometryFloor;
            const double apart = LastDigitsApart(g.numbers[k], w.numbers[k], floor);
            // The quotient of two printed numbers carries rounding: 2 units can
            // come out as 2.0000000001.
            EXPECT_LE(apart, kMaxLastDigits + 1e-6)
                << "line " << i + 1 << " " << kFields[k] << ": " << g.numbers[k] << " vs Radiance "
                << w.numbers[k];
            ++numbers;
            if (g.numbers[k] != w.numbers[k]) ++differing;
            if (apart > largest) {
                largest = apart;
                largestLine = i + 1;
                largestField = k;
            }
        }
    }
    std::printf("%s: %d numbers on %zu lines, %d not identical, largest difference %.3g units of "
                "the 7th digit (line %zu, %s; limit %g)\n",
                scene.c_str(), numbers, want.size(), differing, largest, largestLine,
                kFields[largestField], kMaxLastDigits);
}

void CompareAb0(const std::string& scene, const std::string& rays, const std::string& ref) {
    CompareOutput(scene,
                  kRtrace + " -h -ab 0 -ovlpnNm " + kSource + "/scenes/" + scene + " < " + kSource +
                      "/scenes/" + rays,
                  kSource + "/scenes/" + ref);
}

/// Runs `cmd` and compares its output with Radiance's in `refPath` line by
/// line: the same indentation (a ray tree's depth), the same names, and every
/// number within kMaxLastDigits units of the 7th digit (magnitudes below
/// kGeometryFloor count as zero); `label` names the case.
void CompareNumbers(const std::string& label, const std::string& cmd, const std::string& refPath) {
    std::istringstream out(RunCommand(cmd));
    std::ifstream refFile(refPath);
    ASSERT_TRUE(refFile) << refPath;
    auto lines = [](std::istream& in) {
        std::vector<std::string> v;
        for (std::string line; std::getline(in, line);) v.push_back(line);
        return v;
    };
    const auto got = lines(out);
    const auto want = lines(refFile);
    ASSERT_EQ(got.size(), want.size()) << label;
    for (std::size_t i = 0; i < want.size(); ++i) {
        const auto depth = [](const std::string& s) { return s.find_first_not_of('\t'); };
        EXPECT_EQ(depth(got[i]), depth(want[i])) << label << " line " << i + 1;
        std::istringstream g(got[i]), w(want[i]);
        const Row gr = ParseRows(g).at(0), wr = ParseRows(w).at(0);
        EXPECT_EQ(gr.modifier, wr.modifier) << label << " line " << i + 1;
        ASSERT_EQ(gr.numbers.size(), wr.numbers.size()) << label << " line " << i + 1;
        for (std::size_t k = 0; k < wr.numbers.size(); ++k) {
            EXPECT_LE(LastDigitsApart(gr.numbers[k], wr.numbers[k], kGeometryFloor),
                      kMaxLastDigits + 1e-6)
                << label << " line " << i + 1 << " number " << k + 1 << ": " << gr.numbers[k]
                << " vs Radiance " << wr.numbers[k];
        }
    }
}

TEST(Golden, CornellDirectMatchesRadiance) {
    CompareAb0("cornell/cornell.rad", "cornell/cam32.rays", "cornell/ref/cam32_ab0_ovlpnNm.txt");
}

TEST(Golden, CornellFromGeneratorLinesMatchesRadiance) {
    CompareAb0("cornell/cornell_src.rad", "cornell/cam32.rays",
               "cornell/ref/cam32_ab0_ovlpnNm.txt");
}

TEST(Golden, DaylitRoomDirectMatchesRadiance) {
    CompareAb0("daylit_room/daylit_room.rad", "daylit_room/cam32x24.rays",
               "daylit_room/ref/cam32x24_ab0_ovlpnNm.txt");
}

TEST(Golden, DaylitRoomFromGeneratorLinesMatchesRadiance) {
    CompareAb0("daylit_room/daylit_room_src.rad", "daylit_room/cam32x24.rays",
               "daylit_room/ref/cam32x24_ab0_ovlpnNm.txt");
}

/// A `trans` surface seen from its back, by a view ray and by shadow rays, at
/// -bv+ and -bv- (tests/data/shading_rules/make_refs.sh): with -bv- Radiance 5.4a
/// passes the ray through as for any material; lazyrad shaded trans from
/// behind whatever -bv until 2026-12-05.
TEST(Golden, TransBackFacesFollowBv) {
    const std::string data = kSource + "/tests/data/shading_rules/";
    for (const std::string bv : {"+", "-"}) {
        for (const std::string scene : {"trans_view", "trans_rough_view"}) {
            CompareOutput(scene + " -bv" + bv,
                          kRtrace + " -h -ab 0 -dj 0 -ss 0 -bv" + bv + " -ov " + data + scene +
                              ".rad < " + data + "view.rays",
                          data + scene + "_bv" + bv + ".txt");
        }
        CompareOutput("trans_shadow -bv" + bv,
                      kRtrace + " -h -I -ab 0 -dj 0 -bv" + bv + " -ov " + data +
                          "trans_shadow.rad < " + data + "shadow.pts",
                      data + "trans_shadow_bv" + bv + ".txt");
    }
}

/// 60 random rays in the cornell box filled with a global medium
/// (tests/data/shading_rules/make_refs.sh): the lamp is divided for the shadow
/// rays' weight, which the viewing ray's path through the medium lowers, as in
/// Radiance (lazyrad divided it for the viewing ray's own weight until
/// 2026-12-05: other sample points, 8 of these rays off, one by 50 %).
TEST(Golden, MediumLowersSourcePartitionWeight) {
    const std::string data = kSource + "/tests/data/shading_rules/";
    CompareNumbers("medium", kRtrace + " -h -ab 0 -dj 0 -dt 0 -ss 0 -me .05 .05 .05 -ma .8 .8 .8 "
                                       "-mg .5 -ov " + kSource + "/scenes/cornell/cornell.rad < " +
                                       data + "medium_rays.txt",
                   data + "medium_ov.txt");
}

/// A sensor lit through a glass pane (tests/data/shading_rules/make_refs.sh):
/// the shadow ray the pane transmits goes on whatever its weight, at the
/// default limits, below -lw (.88 against .95) and under Russian roulette,
/// as Radiance's rayorigin() commits to shadow rays. Until 2026-12-05
/// lazyrad cut it (0) or put it to roulette (0.746 once promoted).
TEST(Golden, ShadowRaysAreNeverCut) {
    const std::string data = kSource + "/tests/data/shading_rules/";
    std::string cmd = "(";
    for (const char* limits : {"", "-lw .95 -lr 10", "-lw .95 -lr -10"}) {
        cmd += "echo 0 0 0 0 0 1 | " + kRtrace + " -h -I -ab 0 " + limits + " " + data +
               "shadow_commitment.rad; ";
    }
    CompareNumbers("shadow commitment", cmd + ")", data + "shadow_commitment.txt");
}

/// -oLlRX (first-hit, effective, mirrored and unmirrored ray lengths) for 400
/// rays from random points of the mixed room in random directions, against
/// Radiance's (tests/data/golden/make_lengths.sh): the mirrored length is 1e10
/// unless a pure specular reflection (the chrome, the glass) set it, and the
/// effective length follows whichever part dominates. 22 of the rays see a
/// mirror length, 21 an unmirrored length beyond the first hit.
TEST(Golden, RayLengthsMatchRadiance) {
    const std::string data = kSource + "/tests/data/golden/";
    CompareNumbers("-oLlRX", kRtrace + " -h -oLlRX -ab 0 -dj 0 " + kSource +
                                 "/scenes/mixed/mixed.rad < " + data + "mixed_lengths.rays",
                   data + "mixed_lengths_oLlRX.txt");
}

/// Output that needs no value (-oodcLpNswmM~: points, lengths, normals,
/// names) only intersects the rays, as Radiance's castonly does: the same
/// records as Radiance's at -ab 2, nothing shaded (no shadow ray, no
/// hemisphere in the -t summary), and the -af file neither opened nor created.
TEST(Golden, CastOnlyOutputMatchesRadiance) {
    const std::string data = kSource + "/tests/data/golden/";
    const std::string ambient = ::testing::TempDir() + "cast_only.amb";
    std::remove(ambient.c_str());
    const std::string rest = " -h -oodcLpNswmM~ -ab 2 -af " + ambient + " " + kSource +
                             "/scenes/mixed/mixed.rad < " + data + "mixed_lengths.rays";
    CompareNumbers("-oodcLpNswmM~", kRtrace + rest, data + "mixed_cast.txt");
    EXPECT_FALSE(std::filesystem::exists(ambient)) << "cast-only run made " << ambient;
    const std::string summary = RunCommand(kRtrace + " -t 1000" + rest + " 2>&1 >/dev/null");
    EXPECT_NE(summary.find(" 0 hemispheres, 400 rays traced + 0 shadow rays"), std::string::npos)
        << summary;
}

/// A 180° sky and a 180° ground (`source` with glow): Radiance keeps their
/// solid angle in a float, so each covers its closed hemisphere and about 3e-8
/// beyond. Horizontal rays (a level view's middle row) see the sky, which
/// comes first; so does a ray 1e-9 below the horizon, and one 1e-7 below
/// sees the ground. The expected lines are Radiance 5.4a's output for
/// tests/data/golden/horizon.rays (`oconv horizon.rad`, `rtrace -h -w -ov`).
TEST(Golden, HorizontalRaysSeeTheFirst180DegreeSource) {
    const std::string data = kSource + "/tests/data/golden/";
    const std::string sky = "1.000000e+00\t2.000000e+00\t3.000000e+00\t\n";
    const std::string ground = "4.000000e+00\t5.000000e+00\t6.000000e+00\t\n";
    EXPECT_EQ(RunCommand(kRtrace + " -h -w -ov " + data + "horizon.rad < " + data + "horizon.rays"),
              sky + sky + sky + ground + sky);
}

/// -i meters the first surface a primary ray meets; on an illum that is its
/// alternate material (Radiance's m_illum() shades it through rayshade()):
/// a plastic or a mirror alternate becomes the Lambertian meter, a glass one
/// is passed through, and an illum without one as well. Radiance's output in
/// tests/data/golden/illum_i_ovs.txt (make_illum_i.sh).
TEST(Golden, IrradianceAtHitMetersAnIllumsAlternate) {
    const std::string data = kSource + "/tests/data/golden/";
    CompareNumbers("-i illum", kRtrace + " -h -w -i -dt 0 -ovs " + data + "illum_i.rad < " + data +
                                   "illum_i.rays",
                   data + "illum_i_ovs.txt");
}

/// Trace output in a participating medium: each ray's line carries its value
/// before the medium between its origin and its end acts on it (Radiance's
/// raytrace() reports before rayparticipate()); the primary record after.
/// A room in fog lit through a glass pane; Radiance's output in
/// tests/data/golden/fog_trace_oTvL.txt (make_lengths.sh).
TEST(Golden, TraceShowsValuesBeforeTheMedium) {
    const std::string data = kSource + "/tests/data/golden/";
    CompareNumbers("-oTvL in fog", kRtrace + " -h -w -me .1 .1 .1 -ab 0 -dj 0 -dt 0 -oTvL " + data +
                                       "fog_trace.rad < " + data + "fog_trace.rays",
                   data + "fog_trace_oTvL.txt");
}

/// Trace output (-otvsL, the ray tree) for 60 random rays in the cornell box
/// against Radiance's (tests/data/golden/make_lengths.sh): shadow rays that
/// something other than their source stops are reported, as Radiance's
/// direct() reports them; 25 of the 85 lines are such rays.
TEST(Golden, TraceReportsBlockedShadowRays) {
    const std::string data = kSource + "/tests/data/golden/";
    CompareNumbers("-otvsL", kRtrace + " -h -ab 0 -dj 0 -dt 0 -ss 0 -u- -otvsL " + kSource +
                                 "/scenes/cornell/cornell.rad < " + data + "cornell_trace.rays",
                   data + "cornell_otvsL.txt");
}

/// -I with trace output (tests/data/golden/make_irradiance_trace.sh): a
/// sensor is shaded without raytrace(), so Radiance's trace has no line for
/// it, and lit sensors show none at all. lazyrad used to print a depth-0
/// line for every sensor.
TEST(Golden, IrradianceSensorsHaveNoTraceLineOfTheirOwn) {
    const std::string data = kSource + "/tests/data/golden/";
    CompareNumbers("-I -ovtvsL", kRtrace + " -h -I -ab 0 -dj 0 -dt 0 -ss 0 -u- -ovtvsL " + kSource +
                                     "/scenes/cornell/cornell.rad < " + data + "cornell_sensors.pts",
                   data + "cornell_I_ovtvsL.txt");
}

/// The obstructor cache (tests/data/golden/make_obstructor_refs.sh): in one
/// process over the mixed room's 120 work-plane sensors, the shadow rays
/// lazyrad traces are Radiance's, line for line (the cache skips those whose
/// blocker it knows, filled from the sources outward at their first use and
/// from blocked shadow rays after), and so are the values where adaptive
/// shadow testing estimates the untested samples from what was tested.
TEST(Golden, ObstructorCacheMatchesRadiance) {
    const std::string data = kSource + "/tests/data/golden/";
    const std::string run = kRtrace + " -h -I -ab 0 -u- -dj 0 -ss 0 ";
    const std::string scene = kSource + "/scenes/mixed/mixed.rad < " + kSource +
                              "/scenes/mixed/workplane.pts";
    CompareNumbers("shadow rays", run + "-dt .3 -dc .5 -oTvmp " + scene,
                   data + "mixed_obstructed_oTvmp.txt");
    CompareNumbers("-dt 1 -dc 0", run + "-dt 1 -dc 0 -ov " + scene,
                   data + "mixed_obstructed_dt1.txt");
    CompareNumbers("-dt .5 -dc .25", run + "-dt .5 -dc .25 -ov " + scene,
                   data + "mixed_obstructed_dt5.txt");
    // A cached blocker beyond the source does not block it.
    const std::string shade = data + "obstructor_shade.rad < " + data + "obstructor_shade.pts";
    CompareNumbers("lampshade trace", kRtrace + " -h -I -ab 0 -dt 0 -oTvmp " + shade,
                   data + "obstructor_shade_oTvmp.txt");
    CompareNumbers("lampshade", kRtrace + " -h -I -ab 0 -dt 0 -ov " + shade,
                   data + "obstructor_shade_ov.txt");
}

/// -oT in the daylit room (tests/data/golden/make_lengths.sh): a shadow ray
/// that reaches the sun unobstructed is reported as the sun (Radiance traces
/// it when -oT has it follow every source). One process per ray, as the
/// reference was made (before lazyrad had Radiance's obstructor cache, which
/// hides blocked shadow rays of later rays).
TEST(Golden, TraceFollowsShadowRaysToTheSun) {
    const std::string data = kSource + "/tests/data/golden/";
    CompareNumbers("-oTvsL", "while IFS= read -r ray; do echo \"$ray\" | " + kRtrace +
                                 " -h -ab 0 -dj 0 -dt 0 -ss 0 -u- -oTvsL " + kSource +
                                 "/scenes/daylit_room/daylit_room.rad; done < " + data +
                                 "daylit_sun_trace.rays",
                   data + "daylit_sun_oTvsL.txt");
}

/// Light sources under -dv+ and -dv- (tests/data/shading_rules/make_refs.sh), value
/// and coefficient (-ovW): with -dv- a light gives no light and a zero
/// coefficient from either side, and a glow is hidden unless the primary
/// path's whole length, through a glass pane too, exceeds its radius.
TEST(Golden, InvisibleSourcesFollowRadiance) {
    const std::string data = kSource + "/tests/data/shading_rules/";
    for (const std::string dv : {"+", "-"}) {
        CompareNumbers("-dv" + dv,
                       kRtrace + " -h -ab 0 -dv" + dv + " -ovW " + data +
                           "glow_through_glass.rad < " + data + "glow_rays.txt 2>/dev/null",
                       data + "glow_ovW_dv" + dv + ".txt");
    }
}

// Octrees made by real Radiance's oconv (tests/data/octree/make_octrees.sh).
// Octrees that name their scene files store relative names, so rtrace runs
// from that folder, as Radiance's would.
const std::string kOctrees = kSource + "/tests/data/octree";

std::string InOctreeFolder(const std::string& rtraceArgs) {
    return "(cd " + kOctrees + " && " + kRtrace + " " + rtraceArgs + ")";
}

/// An octree naming its .rad files gives exactly the output of those files:
/// the same objects and the same cube, so also the same records at -ab 1.
TEST(GoldenOctree, NamedSceneGivesTheRadOutputByteForByte) {
    for (const auto& [octree, rad, rays] :
         {std::tuple{"cornell.oct", "cornell/cornell.rad", "cornell/cam32.rays"},
          std::tuple{"daylit_room.oct", "daylit_room/daylit_room.rad", "daylit_room/cam32x24.rays"}}) {
        for (const std::string options : {"-ab 0 -ovlpnNm", "-ab 1 -ad 64 -as 16 -aa .2 -ar 32"}) {
            const std::string raysPath = kSource + "/scenes/" + rays;
            const std::string fromOctree =
                RunCommand(InOctreeFolder("-h " + options + " " + octree + " < " + raysPath));
            const std::string fromRad = RunCommand(kRtrace + " -h " + options + " " + kSource +
                                                   "/scenes/" + rad + " < " + raysPath);
            EXPECT_FALSE(fromOctree.empty());
            EXPECT_EQ(fromOctree, fromRad) << octree << " " << options;
        }
    }
}

/// A frozen octree stores its reals in 5 bytes, so Radiance's own output for
/// it differs from its .rad output in the last digit: compare with that.
TEST(GoldenOctree, FrozenCornellMatchesRadianceOnTheSameOctree) {
    CompareOutput("cornell_frozen.oct",
                  InOctreeFolder("-h -ab 0 -ovlpnNm cornell_frozen.oct < " + kSource +
                                 "/scenes/cornell/cam32.rays"),
                  kOctrees + "/cornell_frozen_ab0.txt");
}

TEST(GoldenOctree, FrozenDaylitRoomMatchesRadianceOnTheSameOctree) {
    CompareOutput("daylit_room_frozen.oct",
                  InOctreeFolder("-h -ab 0 -ovlpnNm daylit_room_frozen.oct < " + kSource +
                                 "/scenes/daylit_room/cam32x24.rays"),
                  kOctrees + "/daylit_room_frozen_ab0.txt");
}

/// Frozen octrees crossed with every shape and the source kinds: the mixed
/// room's spheres (one a light), cylinders, rings, cone, metal, glass and trans
/// screen, hit by rays aimed at them. -dt 0 and -ss 0 keep Radiance's output
/// deterministic (tests/data/octree/make_octrees.sh).
TEST(GoldenOctree, FrozenMixedRoomMatchesRadianceOnTheSameOctree) {
    CompareOutput("mixed_frozen.oct",
                  InOctreeFolder("-h -ab 0 -dt 0 -ss 0 -ovlpnNm mixed_frozen.oct < mixed_room.rays"),
                  kOctrees + "/mixed_frozen_ab0.txt");
}

/// A frozen octree's reals are rounded, so a plane's unit normal can have a
/// dot product with itself an ulp above 1; second-bounce records on such a
/// plane were all refused (a NaN weight), and the frozen cornell octree made
/// far more records on the fast floor than its .rad file (README, "Frozen
/// octrees"). Same scene, same cache: the counts must agree within a few per
/// cent (the rounded coordinates change the samples, not how many records fit).
TEST(GoldenOctree, FrozenCornellMakesAsManyRecordsAsItsRadFile) {
    const auto records = [](const std::string& command) {
        const std::string said = RunCommand(command + " 2>&1 >/dev/null");
        const size_t at = said.find("records per level ");
        EXPECT_NE(at, std::string::npos) << said;
        int first = 0, second = 0;
        if (at == std::string::npos ||
            std::sscanf(said.c_str() + at, "records per level %d/%d", &first, &second) != 2) {
            ADD_FAILURE() << said;
        }
        return first + second;
    };
    const std::string options = "-t 1000 -h -I -ab 2 -ad 256 -as 128 -aa .2 -ar 64 ";
    const std::string points = kSource + "/scenes/cornell/floor.pts";
    const int fromRad =
        records(kRtrace + " " + options + kSource + "/scenes/cornell/cornell.rad < " + points);
    const int fromFrozen = records(InOctreeFolder(options + "cornell_frozen.oct < " + points));
    EXPECT_GT(fromRad, 1000);
    EXPECT_NEAR(fromFrozen, fromRad, 0.05 * fromRad);
}

/// Virtual sources (-dr): light sources seen in planar mirrors, against
/// Radiance's output on the same scenes (tests/data/virtual/make_references.sh,
/// -ab 0 -dj 0 -dt 0).
const std::string kVirtual = kSource + "/tests/data/virtual";

void CompareVirtual(const std::string& scene, const std::string& options,
                    const std::string& rays, const std::string& ref) {
    CompareOutput(scene + " " + options,
                  kRtrace + " -h -ab 0 -dj 0 -dt 0 " + options + " " + kVirtual + "/" + scene +
                      ".rad < " + kVirtual + "/" + rays,
                  kVirtual + "/" + ref);
}

/// One row per case: scene, options, rays, Radiance's output.
TEST(GoldenVirtual, ScenesMatchRadiance) {
    const struct {
        const char *scene, *options, *rays, *ref;
    } cases[] = {
        // A lamp facing up under a mirror ceiling lights the floor only
        // through the mirror; with -dr 0 the floor is dark, as in Radiance.
        {"lamp_ceiling", "-I -dr 2", "room.pts", "lamp_ceiling_dr2.txt"},
        {"lamp_ceiling", "-I -dr 0", "room.pts", "lamp_ceiling_dr0.txt"},
        // The sun off a light shelf, at sensors and seen by camera rays.
        {"shelf", "-I -dr 2", "room.pts", "shelf_dr2.txt"},
        {"shelf", "-ovlpnNm -dr 2", "shelf_camera.rays", "shelf_camera_dr2.txt"},
        // Images of images between facing mirrors (a ring and a polygon),
        // one mirror patterned, at one and three relays.
        {"relays", "-I -dr 1", "room.pts", "relays_dr1.txt"},
        {"relays", "-I -dr 3", "room.pts", "relays_dr3.txt"},
        // Penumbrae through mirrors smaller than the lamp, finely
        // partitioned; a tilted spotlight's cone through a mirror; a glow's
        // reach and an illum.
        {"penumbra", "-I -ds .02", "line.pts", "penumbra_ds02.txt"},
        {"uplight", "-I -ds .02", "grid.pts", "uplight_ds02.txt"},
        {"glow_illum", "-I -dr 2", "room.pts", "glow_illum_dr2.txt"},
        // An illum whose alternate is a mirror relays as the mirror
        // (vsmaterial()); 34 of the 40 sensors read less before.
        {"illum_mirror", "-I -dr 2", "room.pts", "illum_mirror_dr2.txt"},
        {"illum_mirror", "-I -dr 0", "room.pts", "illum_mirror_dr0.txt"},
        // A cylinder's image, partitioned along its axis.
        {"tube", "-I -dr 2 -ds .02", "room.pts", "tube_ds02.txt"},
        // A mirror's texture does not bend the light it relays; its pattern
        // colours it.
        {"textured", "-I -dr 2", "room.pts", "textured_dr2.txt"},
        // -bv- makes a mirror's back transparent to other rays, never to
        // shadow rays (sensors under the shelf stay in its shadow).
        {"shelf", "-I -dr 2 -bv-", "room.pts", "shelf_bv.txt"},
        {"relays", "-I -dr 2 -bv-", "room.pts", "relays_bv.txt"},
    };
    for (const auto& c : cases) CompareVirtual(c.scene, c.options, c.rays, c.ref);
}

/// A mirror inside an instance makes no virtual sources, in Radiance as here:
/// the lamp-ceiling floor stays dark with the ceiling instanced.
TEST(GoldenVirtual, MirrorsInsideInstancesRelayNothing) {
    CompareOutput("mirror_instance -I -dr 2",
                  "(cd " + kVirtual + " && " + kRtrace +
                      " -h -ab 0 -dj 0 -dt 0 -I -dr 2 mirror_instance.rad < room.pts)",
                  kVirtual + "/mirror_instance_dr2.txt");
}

/// Images of images in a closed mirrored box, four reflections deep. Within
/// 1e-6 relative rather than 2 units of the 7th digit: Radiance adds a
/// point's dozens of source contributions in single precision.
TEST(GoldenVirtual, MirroredBoxMatchesRadiance) {
    std::istringstream out(RunCommand(kRtrace + " -h -I -ab 0 -dj 0 -dt 0 -dr 4 " + kVirtual +
                                      "/mirror_box.rad < " + kVirtual + "/room.pts"));
    std::ifstream refFile(kVirtual + "/mirror_box_dr4.txt");
    const std::vector<Row> got = ParseRows(out), want = ParseRows(refFile);
    ASSERT_EQ(got.size(), want.size());
    ASSERT_GT(want.size(), 0u);
    for (size_t i = 0; i < want.size(); ++i) {
        ASSERT_EQ(got[i].numbers.size(), 3u);
        for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(got[i].numbers[k], want[i].numbers[k],
                        1e-6 * std::fabs(want[i].numbers[k]) + kValueFloor)
                << "line " << i + 1;
        }
    }
}

/// A mirrored box makes images without end: an absurd -dr must neither hang
/// nor exhaust memory; lazyrad goes as deep as its image limit allows, says
/// so, and answers as at that depth.
TEST(GoldenVirtual, EndlessRelaysStopAtTheImageLimit) {
    const auto run = [](const std::string& dr, const std::string& redirect) {
        return RunCommand(kRtrace + " -h -I -ab 0 -dj 0 -dt 0 -dr " + dr + " " + kVirtual +
                          "/mirror_box.rad < " + kVirtual + "/room.pts " + redirect);
    };
    const std::string said = run("1000000", "2>&1 >/dev/null");
    const size_t at = said.find("-dr 1000000 makes more than 10000 virtual sources; using -dr ");
    ASSERT_NE(at, std::string::npos) << said;
    const int depth = std::atoi(said.c_str() + said.find("using -dr ") + 10);
    EXPECT_GE(depth, 4);
    EXPECT_EQ(run("1000000", "2>/dev/null"), run(std::to_string(depth), "2>/dev/null"));
    EXPECT_EQ(run(std::to_string(depth), "2>&1 >/dev/null"), "");
}

/// Curved mirrors make no virtual sources; Radiance says so once per
/// surface, and only when relays are asked for.
TEST(GoldenVirtual, CurvedMirrorIsReported) {
    const auto warnings = [](const std::string& options) {
        return RunCommand("echo 0 0 0.001 0 0 1 | " + kRtrace + " -h -I -ab 0 " + options + " " +
                          kVirtual + "/sphere_mirror.rad 2>&1 >/dev/null");
    };
    const std::string said = warnings("");
    EXPECT_NE(said.find("secondary sources not supported for sphere \"ball\""),
              std::string::npos)
        << said;
    EXPECT_EQ(warnings("-dr 0"), "");
}

const std::string kPrism = kSource + "/tests/data/prism";

/// rtrace run in tests/data/prism, where RAYPATH=. finds prism.cal.
std::string InPrismFolder(const std::string& args) {
    return "(cd " + kPrism + " && RAYPATH=. " + kRtrace + " " + args + ")";
}

/// The mean of the first number of every line of `output`.
double MeanFirstColumn(const std::string& output) {
    std::istringstream in(output);
    double sum = 0, value = 0;
    int n = 0;
    for (std::string line; std::getline(in, line); ++n) {
        std::istringstream(line) >> value;
        sum += value;
    }
    return n > 0 ? sum / n : 0.0;
}

/// prism1 and prism2 against Radiance 5.4a (tests/data/prism/make_refs.sh):
/// sensors lit through a prism2 panel's two images of a lamp, a turned ring
/// prism1's image of a spotlight, a mirror's images of those and the
/// prisms' images of the mirror's; 200 random rays redirected by the prisms
/// (value and lengths); the sun through a tilted prism2 whose
/// coefficient follows the direction to the sun (DzA), and blocked by it
/// without virtual sources (-dr 0); the sun off a mirror wall through the
/// prism (an image of an image, -dr 2 against -dr 1); the room's panel as an
/// octree instance.
TEST(GoldenPrism, PrismsRedirectAsRadiance) {
    const std::string fixed = "-h -ab 0 -dj 0 -dt 0 -ss 0 ";
    CompareNumbers("room -I", InPrismFolder(fixed + "-I room.rad < room.pts"),
                   kPrism + "/room_I.txt");
    CompareNumbers("room -ovRX", InPrismFolder(fixed + "-ovRX room.rad < room.rays"),
                   kPrism + "/room_ovRX.txt");
    for (const std::string dr : {"2", "0"}) {
        CompareNumbers("sun -dr " + dr, InPrismFolder(fixed + "-dr " + dr + " -I sun.rad < sun.pts"),
                       kPrism + "/sun_I_dr" + dr + ".txt");
    }
    // The panel an illum whose alternate is the prism: it relays as the prism
    // (vsmaterial()); lazyrad stopped with an internal error before.
    CompareNumbers("illum over a prism", InPrismFolder(fixed + "-I sun_illum.rad < sun.pts"),
                   kPrism + "/sun_illum_I.txt");
    // The sun off a mirror wall, then through the prism: an image of an image.
    for (const std::string dr : {"1", "2"}) {
        CompareNumbers("sun off the mirror -dr " + dr,
                       InPrismFolder(fixed + "-dr " + dr + " -I sun_mirror.rad < sun_mirror.pts"),
                       kPrism + "/sun_mirror_I_dr" + dr + ".txt");
    }
    // The panel as an octree instance: it redirects with the instance's
    // transform and, being inside an instance, makes no images.
    CompareNumbers("instanced -I",
                   "(cd " + kPrism + " && head -96 room.pts | RAYPATH=. " + kRtrace + " " + fixed +
                       "-I room_inst.rad)",
                   kPrism + "/room_inst_I.txt");
    CompareNumbers("instanced -ov", InPrismFolder(fixed + "-ov room_inst.rad < room.rays"),
                   kPrism + "/room_inst_ov.txt");
}

/// Indirect light through the prisms: the room's 96 floor sensors at -ab 1
/// with the cache average what Radiance's do (0.13955 in the committed run)
/// within 1 % (seeds 0-3 gave 0.1396-0.1399). And a shadow ray redirected by a prism is never put
/// to Russian roulette (Radiance's "shadow commitment"): at -aa 0 -ad 1024
/// the hemisphere rays' prism children fall below -lw, and the mean with
/// roulette (the default -lr -10) agrees with the mean without it (-lw
/// 1e-9) within 2 %; a first version that promoted such shadow rays without
/// ever ending them made 5.7 % more.
TEST(GoldenPrism, IndirectLightThroughPrisms) {
    const std::string floor = "head -96 room.pts | ";
    const auto mean = [&](const std::string& options) {
        return MeanFirstColumn(RunCommand("(cd " + kPrism + " && " + floor + "RAYPATH=. " +
                                          kRtrace + " -h -I -ab 1 " + options +
                                          " room.rad 2>/dev/null)"));
    };
    std::ifstream ref(kPrism + "/room_ab1.txt");
    const double radiance = MeanFirstColumn(
        std::string(std::istreambuf_iterator<char>(ref), std::istreambuf_iterator<char>()));
    EXPECT_NEAR(mean("-aa .1 -ad 1024 -as 256 -ar 64"), radiance, 0.01 * radiance);
    const double roulette = mean("-aa 0 -ad 1024 -as 0");
    const double whole = mean("-aa 0 -ad 1024 -as 0 -lw 1e-9");
    EXPECT_NEAR(roulette, whole, 0.02 * whole);
}

/// A prism's function errors: too few strings stop loading with the
/// material's name; a zero direction or a math error is a compute error
/// (Radiance's warnings, "projection compute error" when making images) and
/// the ray gets nothing that way.
TEST(GoldenPrism, BadRedirectionsAreReported) {
    const std::string tmp = ::testing::TempDir() + "/prism_bad";
    RunCommand("mkdir -p " + tmp);
    const auto run = [&](const std::string& material) {
        {
            std::ofstream scene(tmp + "/p.rad");
            scene << material << "\np polygon q 0 0 12  -1 -1 1  1 -1 1  1 1 1  -1 1 1\n";
        }
        return RunCommand("cd " + tmp + " && echo 0 0 0 0 0 1 | RAYPATH=. " + kRtrace +
                          " -h -ab 0 p.rad 2>&1; echo status $?");
    };
    EXPECT_EQ(run("void prism1 p 4 1 0 0 1 0 0"),
              "rtrace: fatal - p.rad:1: prism1 \"p\": too few string arguments\nstatus 1\n");
    EXPECT_EQ(run("void prism2 p 8 1 0 0 1 1 0 0 1 0 0"),
              "rtrace: fatal - p.rad:1: prism2 \"p\": too few string arguments\nstatus 1\n");
    const std::string zero = run("void prism1 p 5 1 0 0 0 . 0 0");
    EXPECT_NE(zero.find("rtrace: warning - compute error for prism1 \"p\"\n"), std::string::npos)
        << zero;
    EXPECT_NE(zero.find("0.000000e+00\t0.000000e+00\t0.000000e+00\t\nstatus 0"),
              std::string::npos)
        << zero;
    // A math error (here at every ray) when the lamp's image is made and at
    // the ray: Radiance's two warnings, and no light that way.
    const std::string domain = run(
        "void light l 0 0 3 10 10 10\nl sphere s 0 0 4  0 0 3  .1\n"
        "void prism1 p 5 sqrt(Dz-5) Dx Dy Dz . 0 0");
    EXPECT_NE(domain.find("rtrace: warning - projection compute error for prism1 \"p\"\n"),
              std::string::npos)
        << domain;
    EXPECT_NE(domain.find("rtrace: warning - compute error for prism1 \"p\"\n"), std::string::npos)
        << domain;
    EXPECT_NE(domain.find("0.000000e+00\t0.000000e+00\t0.000000e+00\t\nstatus 0"),
              std::string::npos)
        << domain;
}

/// oconv -i: an octree extended with another file (a lamp). -dt 0: with two
/// sources, -dt's estimates depend on the shadow statistics of earlier rays,
/// which Radiance's obstructor cache changes (README, Differences).
TEST(GoldenOctree, IncrementalOctreeMatchesRadiance) {
    CompareOutput("cornell_plus_lamp.oct",
                  InOctreeFolder("-h -ab 0 -dt 0 -ovlpnNm cornell_plus_lamp.oct < " + kSource +
                                 "/scenes/cornell/cam32.rays"),
                  kOctrees + "/cornell_plus_lamp_ab0.txt");
}

/// An octree from a `!command`, as rtrace takes "!oconv ...".
TEST(GoldenOctree, OctreeFromACommand) {
    const std::string raysPath = kSource + "/scenes/cornell/cam32.rays";
    EXPECT_EQ(RunCommand(InOctreeFolder("-h -ab 0 -ovlpnNm '!cat cornell_frozen.oct' < " + raysPath)),
              RunCommand(InOctreeFolder("-h -ab 0 -ovlpnNm cornell_frozen.oct < " + raysPath)));
}

/// An octree on standard input ("-"), followed there by the rays, as pyradiance
/// sends it.
TEST(GoldenOctree, OctreeOnStandardInputFollowedByRays) {
    const std::string raysPath = kSource + "/scenes/cornell/cam32.rays";
    EXPECT_EQ(RunCommand("cat " + kOctrees + "/cornell_frozen.oct " + raysPath + " | " + kRtrace +
                         " -h -ab 0 -ovlpnNm -"),
              RunCommand(InOctreeFolder("-h -ab 0 -ovlpnNm cornell_frozen.oct < " + raysPath)));
}

/// rtrace's header copies the octree's header lines before its own command line.
TEST(GoldenOctree, HeaderCopiesTheOctreeHeader) {
    const std::string out =
        RunCommand("echo '0 0 0 0 0 1' | " + InOctreeFolder("cornell_plus_lamp.oct"));
    EXPECT_EQ(out.rfind("#?RADIANCE\noconv ../../../scenes/cornell/cornell.rad\n"
                        "oconv -i cornell.oct lamp.rad\n",
                        0),
              0u)
        << out;
}

/// The octree was made when stale.rad had two objects; it has three now.
TEST(GoldenOctree, StaleOctreeIsAnError) {
    const rt::testing::ShellResult r =
        rt::testing::RunShell("echo '0 0 5 0 0 -1' | " + InOctreeFolder("-h stale.oct 2>&1"));
    EXPECT_EQ(r.status, 1);
    // Radiance: "rtrace: fatal - (stale.oct): bad object count; octree stale?"
    EXPECT_NE(r.out.find("rtrace: fatal - stale.oct: bad object count; octree stale?"),
              std::string::npos)
        << r.out;
}

/// stale_undefined.oct was made when its scene file had two objects; the
/// third it has now names an undefined modifier. Radiance reports that error,
/// met while reading the file, before it counts the objects (its output in
/// stale_undefined_radiance.txt); so does lazyrad, which builds each object
/// as it reads it.
TEST(GoldenOctree, SceneFileErrorComesBeforeTheStaleCount) {
    const rt::testing::ShellResult r = rt::testing::RunShell(
        "echo '0 0 5 0 0 -1' | " + InOctreeFolder("-h stale_undefined.oct 2>&1"));
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.out.find("rtrace: fatal - stale_undefined.rad:3: undefined modifier \"nosuch\""),
              std::string::npos)
        << r.out;
    EXPECT_EQ(r.out.find("stale?"), std::string::npos) << r.out;
}

/// skyplane at -ab 0: the sky is a zero-radius glow, not a light source, so
/// the irradiance above the ground is 0 and the ground looks black.
TEST(Golden, SkyplaneWithoutBouncesIsDark) {
    std::string scene = kSource + "/scenes/skyplane/skyplane.rad";
    std::istringstream irr(RunCommand("echo '0 0 0.01 0 0 1' | " + kRtrace + " -h -I -ab 0 -w " + scene));
    auto rows = ParseRows(irr);
    ASSERT_EQ(rows.size(), 1u);
    EXPECT_EQ(rows[0].numbers, (std::vector<double>{0, 0, 0}));
    std::istringstream down(RunCommand("echo '0 0 1 0 0 -1' | " + kRtrace + " -h -ab 0 -w " + scene));
    rows = ParseRows(down);
    ASSERT_EQ(rows.size(), 1u);
    EXPECT_EQ(rows[0].numbers, (std::vector<double>{0, 0, 0}));
    std::istringstream up(RunCommand("echo '0 0 1 0 0 1' | " + kRtrace + " -h -ab 0 -w " + scene));
    rows = ParseRows(up);
    ASSERT_EQ(rows.size(), 1u);
    EXPECT_EQ(rows[0].numbers, (std::vector<double>{1, 1, 1}));
}

/// furnace at -ab 0 with -av 1: a ray inside returns rho·L = 0.5, -I returns π.
TEST(Golden, FurnaceWithoutBouncesReturnsAmbientValue) {
    std::string scene = kSource + "/scenes/furnace/furnace.rad";
    std::istringstream rad(
        RunCommand("echo '0.1 0.2 0.3 1 -2 0.5' | " + kRtrace + " -h -ab 0 -av 1 1 1 -w " + scene));
    auto rows = ParseRows(rad);
    ASSERT_EQ(rows.size(), 1u);
    EXPECT_NEAR(rows[0].numbers[1], 0.5, 1e-6);
    std::istringstream irr(
        RunCommand("echo '0 0 0 0 1 0' | " + kRtrace + " -h -I -ab 0 -av 1 1 1 -w " + scene));
    rows = ParseRows(irr);
    ASSERT_EQ(rows.size(), 1u);
    EXPECT_NEAR(rows[0].numbers[1], 3.14159265, 1e-6);
}

}  // namespace

// Instances (radiance-functions.md §13.1-13.2), with octrees made by real
// Radiance's oconv from scenes in tests/data/instance (make_instances.sh). The
// instanced octrees name their .rad files relative to that folder, and are
// found on RAYPATH=., so rtrace runs there.
const std::string kInstances = kSource + "/tests/data/instance";

std::string InInstanceFolder(const std::string& rtraceArgs) {
    return "(cd " + kInstances + " && RAYPATH=. " + kRtrace + " " + rtraceArgs + ")";
}

/// The verified values of §13.6: a void instance shades with its own
/// material and a pattern in instance coordinates; an overriding modifier
/// shades every inner surface, with its pattern in world coordinates; points,
/// normals, distances and names as Radiance prints them, byte for byte.
TEST(GoldenInstance, PlacedSquaresMatchRadianceByteForByte) {
    for (const std::string octree : {"two_squares", "two_squares_frozen"}) {
        std::ifstream ref(kInstances + "/" + octree + "_ab0.txt");
        ASSERT_TRUE(ref);
        std::stringstream want;
        want << ref.rdbuf();
        EXPECT_EQ(RunCommand(InInstanceFolder("-h -ab 0 -ovnNLpsmM " + octree +
                                              ".oct < two_squares.rays")),
                  want.str())
            << octree;
    }
}

/// Nested instances (chairs in rows in a room), turned, scaled, mirrored and
/// overridden at both levels, with every surface kind, a pattern in chair
/// coordinates and mirror-like metal reflecting other instances.
TEST(GoldenInstance, NestedRoomMatchesRadiance) {
    for (const std::string octree : {"room", "room_frozen"}) {
        CompareOutput(octree + ".oct",
                      InInstanceFolder("-h -ab 0 -ovlpnNsm " + octree + ".oct < room.rays"),
                      kInstances + "/" + octree + "_ab0.txt");
    }
}

/// -ab 1 irradiance on floor points against Radiance's, converged (8192
/// rays, no interpolation, mean of 8 runs; the file gives the mean and its
/// relative standard error, below 0.1 %). `folder` is where rtrace runs.
void CompareFloorAtOneBounce(const std::string& folder) {
    std::istringstream got(RunCommand("(cd " + folder + " && RAYPATH=. " + kRtrace +
                                      " -h -I -ab 1 -aa 0 -ad 8192 -as 0 -lw 1e-5 -ov room.oct "
                                      "< floor.pts)"));
    std::ifstream want(folder + "/room_floor_ab1.txt");
    ASSERT_TRUE(want);
    double r, g, b, ref, relativeError;
    int n = 0;
    while (want >> ref >> relativeError) {
        ASSERT_LT(relativeError, 0.002) << "reference not converged, point " << n + 1;
        ASSERT_TRUE(got >> r >> g >> b);
        EXPECT_NEAR(r, ref, 0.01 * ref) << folder << " point " << n + 1;
        ++n;
    }
    EXPECT_EQ(n, 6);
}

/// The largest difference measured is 0.1 %; a missing or misplaced chair
/// shadows several per cent.
TEST(GoldenInstance, FloorIrradianceAtOneBounceMatchesRadiance) { CompareFloorAtOneBounce(kInstances); }

/// §13.6 item 4: a light inside an instance is seen (100) but lights nothing,
/// neither directly nor through the ambient calculation.
TEST(GoldenInstance, LampInsideAnInstanceLightsNothing) {
    const rt::testing::ShellResult r =
        rt::testing::RunShell(InInstanceFolder("-h -ab 0 -ov lamp_scene.oct < lamp_scene.rays 2>&1"));
    EXPECT_EQ(r.status, 0);
    EXPECT_EQ(r.out,
              "rtrace: warning - no light sources found\n"
              "0.000000e+00\t0.000000e+00\t0.000000e+00\t\n"
              "1.000000e+02\t1.000000e+02\t1.000000e+02\t\n");
    EXPECT_EQ(RunCommand(InInstanceFolder("-h -I -ab 1 -ov lamp_scene.oct < lamp_scene.rays "
                                          "2>/dev/null | head -1")),
              "0.000000e+00\t0.000000e+00\t0.000000e+00\t\n");
}

/// Bad instances: each one line naming the file (and line or byte), a
/// non-zero exit, no crash.
TEST(GoldenInstance, BadInstancesAreOneLineErrors) {
    struct Case {
        std::string scene;     // written to a temporary .rad in the instance folder
        int status;
        std::string message;
    };
    const std::string dir = ::testing::TempDir();
    const std::string truncated = dir + "/truncated_chair.oct";
    {
        std::ifstream in(kInstances + "/room_frozen.oct", std::ios::binary);
        std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        ASSERT_GT(bytes.size(), 700u);
        std::ofstream(truncated, std::ios::binary) << bytes.substr(0, 700);
    }
    const std::string truncatedMesh = dir + "/truncated_tri.rtm";
    {
        std::ifstream in(kSource + "/tests/data/mesh/tri.rtm", std::ios::binary);
        std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        ASSERT_GT(bytes.size(), 500u);
        std::ofstream(truncatedMesh, std::ios::binary) << bytes.substr(0, 500);
    }
    const std::vector<Case> cases = {
        {"void mesh x 1 nothere.rtm 0 0", 2, "bad.rad:1: cannot find mesh file \"nothere.rtm\""},
        {"void mesh x 1 square.oct 0 0", 1, "square.oct: byte 52: incompatible mesh format"},
        {"void mesh x 1 " + truncatedMesh + " 0 0", 1, truncatedMesh + ": byte 500: truncated mesh file"},
        {"void instance x 1 nothere.oct 0 0", 2, "bad.rad:1: cannot find octree file \"nothere.oct\""},
        {"void instance me 1 self.oct 0 0", 1, "self.rad:1: instance \"me\": octree \"self.oct\" includes itself"},
        {"void instance x 3 square.oct -t 1 0 0", 1, "bad.rad:1: instance \"x\": bad transform"},
        {"void instance x 0 0 0", 1, "bad.rad:1: bad number of arguments for instance \"x\""},
        {"void instance x 1 " + truncated + " 0 0", 1, truncated + ": byte 700: truncated octree"},
        {"void instance x 1 square.rad 0 0", 1, "square.rad: byte 0: not a Radiance octree"},
        {"void instance x 1 . 0 0", 2, "cannot find octree file \".\""},
        {"undefined instance x 1 square.oct 0 0", 1, "bad.rad:1: undefined modifier \"undefined\""},
    };
    for (const Case& c : cases) {
        std::ofstream(dir + "/bad.rad") << c.scene << "\n";
        const rt::testing::ShellResult r = rt::testing::RunShell(
            "echo '0 0 0 0 0 1' | " + InInstanceFolder("-h " + dir + "/bad.rad 2>&1 >/dev/null"));
        EXPECT_EQ(r.status, c.status) << c.scene << "\n" << r.out;
        EXPECT_NE(r.out.find(c.message), std::string::npos) << c.scene << "\n" << r.out;
        EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;
    }
}

// Meshes (radiance-functions.md §13.3-13.4) made by real Radiance's obj2mesh
// from models we generate (tests/data/meshscene/make_mesh_scenes.sh).
const std::string kMeshScenes = kSource + "/tests/data/meshscene";

/// §13.6 item 5: the worked-example mesh placed with its own materials, with
/// an overriding light, and under a pattern of the mesh's (u,v) in world
/// coordinates; interpolated normals (-on), geometric ones (-oN), distances,
/// points and names, byte for byte.
TEST(GoldenMesh, WorkedExampleMatchesRadianceByteForByte) {
    std::ifstream ref(kMeshScenes + "/tri_scene_ab0.txt");
    ASSERT_TRUE(ref);
    std::stringstream want;
    want << ref.rdbuf();
    EXPECT_EQ(RunCommand("(cd " + kMeshScenes + " && RAYPATH=. " + kRtrace +
                         " -h -ab 0 -ovnNLpsm tri_scene.oct < tri_scene.rays 2>/dev/null)"),
              want.str());
}

/// Vases as meshes with smooth normals (plastic, mirror-like metal and a
/// pattern of Lu, Lv): as they are, turned and scaled, mirrored, overridden,
/// and inside instanced octrees (overridden there too), named and frozen.
TEST(GoldenMesh, RoomOfVasesMatchesRadiance) {
    for (const std::string octree : {"room", "room_frozen"}) {
        CompareOutput(octree + ".oct",
                      "(cd " + kMeshScenes + " && RAYPATH=. " + kRtrace + " -h -ab 0 -ovlpnNsm " +
                          octree + ".oct < room.rays)",
                      kMeshScenes + "/" + octree + "_ab0.txt");
    }
}

/// The largest difference measured is 0.2 %.
TEST(GoldenMesh, FloorIrradianceAtOneBounceMatchesRadiance) { CompareFloorAtOneBounce(kMeshScenes); }
