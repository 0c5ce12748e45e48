// SPDX-License-Identifier: MIT
//
// End-to-end: every sky of tests/data/sky/skies.txt (gensky's -c -i +i -s +s -u
// and gendaylit's -W and -G inputs, by date and place or by -ang) as a
// daylighting tool writes it, `!gensky …` plus the sky and ground glow
// hemispheres, seen by the -I -ab 1 sensors of sensors.pts (up, vertical
// facing south, tilted 45 degrees to the west) through build/bin/rtrace, against
// the converged irradiance of real Radiance 5.4a (make_ref.sh there).
//
// RAYPATH is the data folder, which holds no .cal files: lazyrad evaluates the
// skies with its own lib/skybright.cal and lib/perezlum.cal, as on a machine
// without Radiance. The sun is a direct source; the sky and ground arrive in
// the one bounce.
//
// Also the daylit room's work plane under gensky -c and +s skies at a
// daylighting tool's -ab 2 settings, against converged Radiance references.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "tests/testing/rtrace_rows.h"
#include "tests/testing/shell.h"

namespace {

using rt::testing::Luminance;

const std::string kData = rt::testing::kSourceDir + "/tests/data/sky";
const std::string kBin = std::string(RT_BINARY_DIR) + "/bin";

// The bound the project claims for its sky functions at -ab 1: relative error
// of the sensor's luminance against Radiance's converged value.
constexpr double kMaxRelativeError = 0.005;
// A reference whose own standard error came near the bound could not tell a
// wrong sky from its own noise; make_ref.sh's is far below this.
constexpr double kMaxReferenceError = kMaxRelativeError / 20;
// Stratified over 16384 directions, one estimate of these smooth skies is
// more than ten times closer to its mean than the bound, and cheap enough to run
// every sky under ASan. -lw 1e-9 keeps every sample (no Russian roulette), as
// the reference does.
const std::string kOptions = "-I -ab 1 -aa 0 -ad 16384 -as 0 -lw 1e-9";

const std::string kHemispheres =
    "skyfunc glow sky_glow 0 0 4 1 1 1 0\n"
    "sky_glow source sky 0 0 4 0 0 1 180\n"
    "skyfunc glow ground_glow 0 0 4 1 1 1 0\n"
    "ground_glow source ground 0 0 4 0 0 -1 180\n";

struct Sky {
    std::string name;
    std::string command;  // gensky or gendaylit command line
};

/// GoogleTest names a failing case by this instead of the struct's bytes.
void PrintTo(const Sky& sky, std::ostream* os) { *os << sky.name << ": " << sky.command; }

std::vector<Sky> ReadSkies() {
    std::vector<Sky> skies;
    std::ifstream in(kData + "/skies.txt");
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream words(line);
        Sky sky;
        words >> sky.name >> std::ws;
        std::getline(words, sky.command);
        skies.push_back(sky);
    }
    return skies;
}

struct Reference {
    std::vector<double> rgb;
    double relStdErr = 0;
};

/// ref.txt, keyed by sky name, one entry per sensor in sensors.pts order.
std::map<std::string, std::vector<Reference>> ReadReference() {
    std::map<std::string, std::vector<Reference>> refs;
    std::ifstream in(kData + "/ref.txt");
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream words(line);
        std::string name;
        size_t sensor = 0;
        Reference r;
        r.rgb.resize(3);
        words >> name >> sensor >> r.rgb[0] >> r.rgb[1] >> r.rgb[2] >> r.relStdErr;
        auto& list = refs[name];
        if (list.size() <= sensor) list.resize(sensor + 1);
        list[sensor] = r;
    }
    return refs;
}

/// Radiance's generator output for each sky (radiance_skies.txt).
std::map<std::string, std::string> ReadRadianceSkies() {
    std::map<std::string, std::string> out;
    std::ifstream in(kData + "/radiance_skies.txt");
    std::string line, name;
    while (std::getline(in, line)) {
        if (line.rfind("=== ", 0) == 0) {
            name = line.substr(4);
        } else {
            out[name] += line + "\n";
        }
    }
    return out;
}

std::string TempDir() {
    char dir[] = "/tmp/rt_sky_test_XXXXXX";
    return mkdtemp(dir) ? dir : "";
}

class SkySensors : public ::testing::TestWithParam<Sky> {};

/// lazyrad's bundled generator writes the sky Radiance's writes, so the sky
/// lazyrad renders is the one the reference was made under.
TEST_P(SkySensors, GeneratorOutputIsRadiances) {
    const Sky& sky = GetParam();
    static const auto radiance = ReadRadianceSkies();
    ASSERT_TRUE(radiance.count(sky.name)) << "no Radiance output for " << sky.name;
    // Run through PATH, as a `!gensky` line does, so argv[0] (which the
    // generators echo) is the bare name as it was for Radiance's.
    const auto r =
        rt::testing::RunShell("PATH=" + kBin + ":\"$PATH\" " + sky.command + " 2>/dev/null");
    EXPECT_EQ(r.status, 0);
    EXPECT_EQ(r.out, radiance.at(sky.name));
}

TEST_P(SkySensors, IrradianceMatchesConvergedRadiance) {
    const Sky& sky = GetParam();
    static const auto refs = ReadReference();
    ASSERT_TRUE(refs.count(sky.name)) << "no reference for " << sky.name;
    const auto& ref = refs.at(sky.name);

    const std::string dir = TempDir();
    ASSERT_FALSE(dir.empty());
    const std::string scene = dir + "/sky.rad";
    std::ofstream(scene) << "!" << sky.command << "\n" << kHemispheres;
    const auto r =
        rt::testing::RunShell("RAYPATH=" + kData + " " + rt::testing::kRtrace + " -h -w " +
                              kOptions + " " + scene + " < " + kData + "/sensors.pts");
    std::filesystem::remove_all(dir);
    ASSERT_EQ(r.status, 0);
    rt::testing::Rows rows;
    std::istringstream lines(r.out);
    for (std::string line; std::getline(lines, line);) {
        std::istringstream numbers(line);
        rows.emplace_back();
        for (double x; numbers >> x;) rows.back().push_back(x);
    }

    ASSERT_EQ(rows.size(), ref.size());
    double worst = 0;
    for (size_t i = 0; i < rows.size(); ++i) {
        ASSERT_EQ(rows[i].size(), 3u);
        EXPECT_LT(ref[i].relStdErr, kMaxReferenceError) << sky.name << " reference " << i + 1;
        const double want = Luminance(ref[i].rgb);
        const double rel = Luminance(rows[i]) / want - 1;
        EXPECT_LT(std::fabs(rel), kMaxRelativeError)
            << sky.name << " sensor on line " << i + 1 << " of sensors.pts: " << Luminance(rows[i])
            << " against Radiance's " << want;
        worst = std::max(worst, std::fabs(rel));
    }
    std::printf("%-12s worst of %zu sensors %.4f %%\n", sky.name.c_str(), rows.size(), 100 * worst);
}

std::string SkyName(const ::testing::TestParamInfo<Sky>& skyInfo) { return skyInfo.param.name; }

INSTANTIATE_TEST_SUITE_P(Skies, SkySensors, ::testing::ValuesIn(ReadSkies()), SkyName);

// The daylit room's work plane under gensky skies at a daylighting tool's
// settings, against converged -ab 2 references made with real Radiance
// (scenes/daylit_room/make_sky_refs.sh). The bound is Radiance's own error at
// the same settings: the smallest RMS error of five -u+ runs of Radiance 5.4a
// (bench/daylit_sky_refcheck.sh), which includes the reference's own noise.
struct DaylitSky {
    std::string name;        // c or s: sky_gensky_<name>.rad, ref/workplane_I_ab2_gensky_<name>.txt
    double radianceRms = 0;  // Radiance's best relative RMS error at kDaylightOptions
};

void PrintTo(const DaylitSky& sky, std::ostream* os) { *os << "gensky " << sky.name; }

const std::string kDaylightOptions = "-I -aa .1 -ab 2 -ad 2048 -ar 64";

class DaylitRoomSky : public ::testing::TestWithParam<DaylitSky> {};

TEST_P(DaylitRoomSky, WorkPlaneErrorIsWithinRadiances) {
    const DaylitSky& sky = GetParam();
    const std::string room = rt::testing::kSourceDir + "/scenes/daylit_room";
    const std::string dir = TempDir();
    ASSERT_FALSE(dir.empty());
    // The room without its own sky and sun, which are its first 25 lines.
    const std::string scene = dir + "/room.rad";
    {
        std::ofstream out(scene);
        std::ifstream skyFile(room + "/sky_gensky_" + sky.name + ".rad");
        out << skyFile.rdbuf();
        std::ifstream roomFile(room + "/daylit_room.rad");
        std::string line;
        for (int n = 1; std::getline(roomFile, line); ++n) {
            if (n > 25) out << line << "\n";
        }
    }
    const auto r = rt::testing::RunShell("RAYPATH=" + kData + " " + rt::testing::kRtrace +
                                         " -h -w " + kDaylightOptions + " " + scene + " < " + room +
                                         "/workplane.pts > " + dir + "/out.txt");
    ASSERT_EQ(r.status, 0);
    std::ifstream outFile(dir + "/out.txt");
    rt::testing::Rows rows;
    for (std::string line; std::getline(outFile, line);) {
        std::istringstream numbers(line);
        rows.emplace_back();
        for (double x; numbers >> x;) rows.back().push_back(x);
    }
    std::filesystem::remove_all(dir);
    const auto e = rt::testing::CompareWithReference(
        rows, room + "/ref/workplane_I_ab2_gensky_" + sky.name + ".txt");
    ASSERT_EQ(e.count, 96u);
    std::printf("daylit room, gensky %s: %.2f %% RMS, %.2f %% max (Radiance's best %.2f %% RMS)\n",
                sky.name.c_str(), 100 * e.rms, 100 * e.worst, 100 * sky.radianceRms);
    EXPECT_LT(e.rms, sky.radianceRms);
}

std::string DaylitSkyName(const ::testing::TestParamInfo<DaylitSky>& skyInfo) {
    return skyInfo.param.name == "c" ? "Overcast" : "ClearWithSun";
}

INSTANTIATE_TEST_SUITE_P(GenskySkies, DaylitRoomSky,
                         ::testing::Values(DaylitSky{"c", 0.0740}, DaylitSky{"s", 0.0179}),
                         DaylitSkyName);

/// The point of the test is lazyrad's own sky functions: a skybright.cal or
/// perezlum.cal in the data folder would be found on RAYPATH first.
TEST(SkyData, HoldsNoSkyFunctionFiles) {
    EXPECT_FALSE(std::filesystem::exists(kData + "/skybright.cal"));
    EXPECT_FALSE(std::filesystem::exists(kData + "/perezlum.cal"));
    EXPECT_FALSE(std::filesystem::exists(kData + "/rayinit.cal"));
}

}  // namespace
