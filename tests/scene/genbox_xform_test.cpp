// SPDX-License-Identifier: MIT
//
// End-to-end checks of the bundled genbox and xform programs (build/bin/).
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "scene/reader.h"
#include "scene_test_util.h"

namespace rt {
namespace {

const std::string kBin = RT_BINARY_DIR "/bin/";

struct RunResult {
    std::string output;  // standard output and standard error
    int status = -1;
};

RunResult RunShell(const std::string& command) {
    RunResult result;
    std::FILE* pipe = popen(("PATH='" + kBin + "':\"$PATH\"; export PATH; " + command + " 2>&1").c_str(), "r");
    if (pipe == nullptr) return result;
    char buffer[4096];
    std::size_t n;
    while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) result.output.append(buffer, n);
    const int status = pclose(pipe);
    result.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return result;
}

std::vector<SceneObject> Objects(const std::string& text) { return testing::ParseText(text); }

Vec3 PolygonNormalSum(const Scene& scene) {
    Vec3 sum;
    for (const Surface& s : scene.surfaces) {
        const auto& p = std::get<Polygon>(s.shape);
        sum += p.normal * p.area;
    }
    return sum;
}

TEST(Genbox, MatchesRadianceOutput) {
    const RunResult run = RunShell("genbox white short_block 1.65 1.65 1.65");
    ASSERT_EQ(run.status, 0) << run.output;
    EXPECT_EQ(run.output.rfind("# genbox white short_block 1.65 1.65 1.65\n", 0), 0u);
    EXPECT_NE(run.output.find("\nwhite polygon short_block.1540\n0\n0\n12\n"
                              "\t              1.65\t                 0\t                 0\n"
                              "\t              1.65\t                 0\t              1.65\n"
                              "\t                 0\t                 0\t              1.65\n"
                              "\t                 0\t                 0\t                 0\n"),
              std::string::npos)
        << run.output;
    const auto objects = Objects(run.output);
    ASSERT_EQ(objects.size(), 6u);
    const char* names[] = {"1540", "4620", "2310", "3267", "5137", "6457"};
    for (int i = 0; i < 6; ++i) EXPECT_EQ(objects[static_cast<std::size_t>(i)].name, std::string("short_block.") + names[i]);
}

// Real Radiance 5.4a's genbox output for each form it writes without its
// polygon-mesh library (tests/data/genbox/cases.txt: file, then command),
// byte for byte: -i mirrors the vertices (not their order), rounded edges
// and corners are named by their vertex letters.
TEST(Genbox, EveryFormMatchesRadianceOutput) {
    const std::string dir = RT_SOURCE_DIR "/tests/data/genbox/";
    std::ifstream cases(dir + "cases.txt");
    int checked = 0;
    for (std::string line; std::getline(cases, line);) {
        const std::string file = line.substr(0, line.find(' '));
        const std::string command = line.substr(line.find(' ') + 1);
        const RunResult run = RunShell(command);
        ASSERT_EQ(run.status, 0) << run.output;
        std::ifstream in(dir + file);
        const std::string want((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        EXPECT_EQ(run.output, want) << command;
        ++checked;
    }
    EXPECT_EQ(checked, 7);
}

TEST(Genbox, BoxIsClosedAndFacesOutward) {
    const RunResult run = RunShell("echo 'void plastic m 0 0 5 1 1 1 0 0'; genbox m b 1 2 3");
    ASSERT_EQ(run.status, 0) << run.output;
    const Scene scene = testing::BuildText(run.output);
    ASSERT_EQ(scene.surfaces.size(), 6u);
    double area = 0;
    for (const Surface& s : scene.surfaces) {
        const auto& p = std::get<Polygon>(s.shape);
        area += p.area;
        // Outward: the centre (.5, 1, 1.5) lies behind every face.
        EXPECT_LT(Dot(p.normal, Vec3(.5, 1, 1.5)) - p.offset, 0) << s.name;
    }
    EXPECT_DOUBLE_EQ(area, 2 * (2 + 6 + 3));
    const Vec3 sum = PolygonNormalSum(scene);
    EXPECT_NEAR(Length(sum), 0, 1e-12);
}

TEST(Genbox, InvertedBevelledAndRounded) {
    const RunResult inverted = RunShell("echo 'void plastic m 0 0 5 1 1 1 0 0'; genbox m b 1 1 1 -i");
    ASSERT_EQ(inverted.status, 0);
    for (const Surface& s : testing::BuildText(inverted.output).surfaces) {
        const auto& p = std::get<Polygon>(s.shape);
        EXPECT_GT(Dot(p.normal, Vec3(.5, .5, .5)) - p.offset, 0) << s.name;
    }
    const RunResult bevel = RunShell("echo 'void plastic m 0 0 5 1 1 1 0 0'; genbox m b 1 2 3 -b .1");
    ASSERT_EQ(bevel.status, 0) << bevel.output;
    const Scene bevelled = testing::BuildText(bevel.output);
    EXPECT_EQ(bevelled.surfaces.size(), 26u);
    EXPECT_NEAR(Length(PolygonNormalSum(bevelled)), 0, 1e-9);  // closed surface
    const RunResult round = RunShell("echo 'void plastic m 0 0 5 1 1 1 0 0'; genbox m b 1 2 3 -r .1");
    ASSERT_EQ(round.status, 0) << round.output;
    const Scene rounded = testing::BuildText(round.output);
    EXPECT_EQ(rounded.surfaces.size(), 6u + 12u + 8u);
    EXPECT_EQ(rounded.surfaces[6].type, SurfaceType::Cylinder);
    EXPECT_EQ(rounded.surfaces[25].type, SurfaceType::Sphere);
}

TEST(Genbox, UsageErrors) {
    RunResult run = RunShell("genbox m b 1 1");
    EXPECT_EQ(run.status, 1);
    EXPECT_NE(run.output.find("Usage: genbox material name xsize ysize zsize"), std::string::npos);
    run = RunShell("genbox m b 1 one 1");
    EXPECT_EQ(run.status, 1);
    EXPECT_EQ(run.output, "genbox: bad size 'one'\n");
    // A bevel wider than half the box is written as Radiance writes it (the
    // faces cross; case7.rad of EveryFormMatchesRadianceOutput), not refused.
    run = RunShell("genbox m b 1 1 1 -b .6");
    EXPECT_EQ(run.status, 0);
    run = RunShell("genbox m b 1 0 1");  // Radiance: usage
    EXPECT_EQ(run.status, 1);
    EXPECT_NE(run.output.find("Usage: genbox"), std::string::npos);
    const std::pair<const char*, const char*> bad[] = {
        {"-n 0", "genbox: -n needs a whole number of segments, at least 1\n"},
        {"-r .1 -n 2.5", "genbox: -n needs a whole number of segments, at least 1\n"},
        {"-b 0", "genbox: -b needs a positive number\n"},
        {"-r", "genbox: -r needs a positive number\n"}};
    for (const auto& [args, message] : bad) {
        run = RunShell(std::string("genbox m b 1 1 1 ") + args);
        EXPECT_EQ(run.status, 1) << args;
        EXPECT_EQ(run.output, message) << args;
    }
    // What Radiance writes through its polygon-mesh library is refused.
    for (const char* args : {"-r .1 -n 3", "-r .1 -i", "-o"}) {
        run = RunShell(std::string("genbox m b 1 1 1 ") + args);
        EXPECT_EQ(run.status, 1) << args;
        EXPECT_NE(run.output.find("not supported"), std::string::npos) << run.output;
        EXPECT_EQ(std::count(run.output.begin(), run.output.end(), '\n'), 1) << run.output;
    }
}

TEST(Xform, HeaderCommentsAndPipeline) {
    const RunResult run = RunShell("genbox white short_block 1.65 1.65 1.65 | xform -rz -17 -t 1.3 0.9 0");
    ASSERT_EQ(run.status, 0) << run.output;
    EXPECT_EQ(run.output.rfind("# xform -rz -17 -t 1.3 0.9 0\n# genbox white short_block 1.65 1.65 "
                               "1.65\n\nwhite polygon short_block.1540\n0\n0\n12\n"
                               "      2.87790284734     0.417586687207                  0\n",
                               0),
              0u)
        << run.output;
}

// Every type Radiance's xform writes its own way (cones, cylinders, rings and
// text three reals to a line, a spotlight's aim after a tab, dielectric,
// interface and mist in %12.6g, mist's source names unquoted): real
// Radiance 5.4a's output of tests/data/xform/all_types.rad, byte for byte.
TEST(Xform, LaysOutEveryTypeAsRadiance) {
    const std::string dir = RT_SOURCE_DIR "/tests/data/xform";
    const std::pair<const char*, const char*> cases[] = {
        {"-rz 30 -s 2 -t 1 2 3", "rz30_s2_t.txt"}, {"-I -n pre -mx -s .5", "inv_prefix_mx.txt"}};
    for (const auto& [args, file] : cases) {
        const RunResult run =
            RunShell("cd '" + dir + "' && xform " + args + " all_types.rad");
        ASSERT_EQ(run.status, 0) << run.output;
        std::ifstream in(dir + "/" + file);
        const std::string want((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        ASSERT_FALSE(want.empty()) << file;
        EXPECT_EQ(run.output, want) << args;
    }
}

TEST(Xform, MirrorKeepsFacesOutward) {
    const RunResult run =
        RunShell("echo 'void plastic m 0 0 5 1 1 1 0 0'; genbox m b 1 2 3 | xform -n left -mx");
    ASSERT_EQ(run.status, 0) << run.output;
    const Scene scene = testing::BuildText(run.output);
    ASSERT_EQ(scene.surfaces.size(), 6u);
    EXPECT_EQ(scene.surfaces[0].name, "left.b.1540");
    for (const Surface& s : scene.surfaces) {
        const auto& p = std::get<Polygon>(s.shape);
        EXPECT_LT(Dot(p.normal, Vec3(-.5, 1, 1.5)) - p.offset, 0) << s.name;
    }
    const RunResult inverted = RunShell("genbox m b 1 1 1 | xform -I -m other");
    const auto objects = Objects(inverted.output);
    ASSERT_EQ(objects.size(), 6u);
    EXPECT_EQ(objects[0].modifier, "other");
    // -I reverses vertex order: 1540 becomes 0451.
    EXPECT_EQ(std::vector<double>(objects[0].rargs.begin(), objects[0].rargs.begin() + 3),
              (std::vector<double>{0, 0, 0}));
}

TEST(Xform, ArrayMakesNumberedCopies) {
    const RunResult run = RunShell("echo 'm sphere s 0 0 4 0 0 0 .1' | xform -a 3 -t 1 0 0");
    ASSERT_EQ(run.status, 0) << run.output;
    const auto objects = Objects(run.output);
    ASSERT_EQ(objects.size(), 3u);
    for (int k = 0; k < 3; ++k) {
        const SceneObject& o = objects[static_cast<std::size_t>(k)];
        EXPECT_EQ(o.name, "a" + std::to_string(k) + ".s");
        EXPECT_DOUBLE_EQ(o.rargs[0], k);
    }
    const RunResult named = RunShell("echo 'm sphere s 0 0 4 0 0 0 .1' | xform -n row -a 2 -t 0 1 0");
    const auto namedObjects = Objects(named.output);
    ASSERT_EQ(namedObjects.size(), 2u);
    EXPECT_EQ(namedObjects[1].name, "row.1.s");
    EXPECT_DOUBLE_EQ(namedObjects[1].rargs[1], 1);
}

TEST(Xform, ExpandsOrKeepsCommands) {
    const auto dir = std::filesystem::temp_directory_path() / "rt_xform_test";
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "inner.rad") << "m sphere s 0 0 4 0 0 0 1\n";
    std::ofstream(dir / "outer.rad") << "# outer\n!xform -t 0 0 5 inner.rad\n";
    // Commands run in the file's directory, so the relative name resolves.
    const std::string outer = (dir / "outer.rad").string();
    RunResult run = RunShell("xform -t 1 0 0 '" + outer + "'");
    ASSERT_EQ(run.status, 0) << run.output;
    auto objects = Objects(run.output);
    ASSERT_EQ(objects.size(), 1u);
    EXPECT_EQ(objects[0].rargs, (std::vector<double>{1, 0, 5, 1}));
    EXPECT_NE(run.output.find("# outer\n"), std::string::npos);

    run = RunShell("xform -c -t 1 0 0 '" + outer + "'");
    ASSERT_EQ(run.status, 0) << run.output;
    EXPECT_NE(run.output.find("\n!xform -t 0 0 5 inner.rad | xform -e -t 1 0 0\n"), std::string::npos)
        << run.output;
    std::filesystem::remove_all(dir);
}

TEST(Xform, ErrorsAreOneLine) {
    RunResult run = RunShell("xform -t 1 0 0 -q < /dev/null");
    EXPECT_EQ(run.status, 1);
    EXPECT_EQ(run.output, "xform: command line error at '-q'\n");
    run = RunShell("xform /nonexistent.rad");
    EXPECT_EQ(run.status, 1);
    EXPECT_EQ(run.output.substr(run.output.find('\n') + 1), "xform: cannot open file \"/nonexistent.rad\"\n");
    run = RunShell("echo 'm sphere s 0 0 3 1 2 3' | xform -s 2");
    EXPECT_EQ(run.status, 1);
    EXPECT_NE(run.output.find("xform: standard input:1: bad sphere \"s\"\n"), std::string::npos)
        << run.output;
    run = RunShell("echo 'm blob s 0 0 0' | xform");
    EXPECT_EQ(run.status, 1);
    EXPECT_NE(run.output.find("xform: standard input:1: unknown object type 'blob'\n"),
              std::string::npos);
    run = RunShell("echo '!exit 4' | xform");
    EXPECT_EQ(run.status, 1);
    EXPECT_NE(run.output.find("command failed (exit status 4)"), std::string::npos) << run.output;
}

TEST(Xform, SelfExpandingFileStops) {
    const auto path = std::filesystem::temp_directory_path() / "rt_xform_self.rad";
    std::ofstream(path) << "!xform " << path.string() << "\n";
    const RunResult run = RunShell("{ xform '" + path.string() + "' > /dev/null; }");
    EXPECT_EQ(run.status, 1);
    EXPECT_NE(run.output.find("commands nested more than 32 deep"), std::string::npos) << run.output;
    std::filesystem::remove(path);
}

}  // namespace
}  // namespace rt
