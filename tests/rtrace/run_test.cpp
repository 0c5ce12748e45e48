// SPDX-License-Identifier: MIT
#include "rtrace/run.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "core/error.h"

namespace rt {
namespace {

// Stands in for the renderer: echoes the ray and reports what it was given.
struct FakeState {
    std::vector<std::string> sceneFiles;
    RtraceOptions options;
    std::vector<double> rmax;
    std::vector<std::uint64_t> indices;
    int built = 0;
};

class FakeEvaluator : public RayEvaluator {
public:
    explicit FakeEvaluator(FakeState& state) : state_(state) {}
    RayResult TraceInput(const Vec3& org, const Vec3& dir, double rmax,
                         std::uint64_t rayIndex) override {
        state_.rmax.push_back(rmax);
        state_.indices.push_back(rayIndex);
        RayResult r;
        r.origin = org;
        r.direction = dir;
        r.value = Rgb(0.5, 0.25, 0.125);
        r.firstLength = 2;
        r.point = org + 2 * dir;
        r.modifierName = "floor";
        if (callback_) {
            RayResult shadow;
            shadow.depth = 1;
            shadow.modifierName = shadows_ ? "lamp" : "wall";
            callback_(shadow);
            callback_(r);
        }
        return r;
    }
    void SetTraceCallback(std::function<void(const RayResult&)> callback, bool shadowRays) override {
        callback_ = std::move(callback);
        shadows_ = shadowRays;
    }

private:
    FakeState& state_;
    std::function<void(const RayResult&)> callback_;
    bool shadows_ = false;
};

struct Result {
    int status;
    std::string out, err;
};

Result RunWith(std::vector<std::string> args, const std::string& input, FakeState* state = nullptr,
               std::time_t now = 1000) {
    FakeState local;
    FakeState& s = state ? *state : local;
    RunEnvironment env;
    env.makeEvaluator = [&s](const std::vector<std::string>& files, const RtraceOptions& o,
                             const WarningSink&) -> std::unique_ptr<RayEvaluator> {
        s.sceneFiles = files;
        s.options = o;
        ++s.built;
        return std::make_unique<FakeEvaluator>(s);
    };
    env.clock = [now] { return now; };
    env.pid = 42;
    args.insert(args.begin(), "/opt/lazyrad/bin/rtrace");
    std::istringstream in(input);
    std::ostringstream out, err;
    int status = rt::Run(args, in, out, err, env);
    return {status, out.str(), err.str()};
}

constexpr const char* kValueLine = "5.000000e-01\t2.500000e-01\t1.250000e-01\t\n";

TEST(RtraceRun, WritesOneRecordPerRay) {
    Result r = RunWith({"-h", "box.rad"}, "0 0 0 0 0 1\n1 1 1 0 2 0\n");
    EXPECT_EQ(r.status, 0);
    EXPECT_EQ(r.out, std::string(kValueLine) + kValueLine);
    EXPECT_EQ(r.err, "");
}

TEST(RtraceRun, HeaderThenRecords) {
    setenv("TZ", "UTC", 1);
    tzset();
    Result r = RunWith({"-ab", "1", "-oL", "a.rad", "b.rad"}, "0 0 0 0 0 1\n");
    EXPECT_EQ(r.status, 0);
    EXPECT_EQ(r.out,
              "#?RADIANCE\n"
              "rtrace -ab 1 -oL\n"
              "SOFTWARE= lazyrad 0.1.0 (RADIANCE 5.4a compatible)\n"
              "CAPDATE= 1970:01:01 00:16:40\n"
              "GMT= 1970:01:01 00:16:40\n"
              "NCOMP=1\n"
              "FORMAT=ascii\n"
              "\n"
              "2.000000e+00\t\n");
}

TEST(RtraceRun, PassesNormalisedDirectionsLimitsAndSeeds) {
    FakeState s;
    Result r = RunWith({"-h", "-odv", "-ld", "-u-", "-ab", "2", "x.rad", "y.rad"},
                       "0 0 0 0 0 4\n0 0 0 3 0 4\n", &s);
    EXPECT_EQ(r.out,
              "0.000000e+00\t0.000000e+00\t1.000000e+00\t" + std::string(kValueLine) +
              "6.000000e-01\t0.000000e+00\t8.000000e-01\t" + kValueLine);
    EXPECT_EQ(s.rmax, (std::vector<double>{4, 5}));
    EXPECT_EQ(s.indices, (std::vector<std::uint64_t>{0, 1}));
    EXPECT_EQ(s.sceneFiles, (std::vector<std::string>{"x.rad", "y.rad"}));
    EXPECT_EQ(s.options.ambient.bounces, 2);
    EXPECT_EQ(s.options.shading.seed, 0u);
    EXPECT_FALSE(s.options.shading.uncorrelated);

    // The seed comes from -seed, never the clock: runs are repeatable.
    RunWith({"-h", "x.rad"}, "0 0 0 0 0 4\n", &s, 12345);
    EXPECT_EQ(s.rmax.back(), 0);
    EXPECT_EQ(s.options.shading.seed, 0u);
    EXPECT_TRUE(s.options.shading.uncorrelated);
    RunWith({"-h", "-seed", "7", "x.rad"}, "0 0 0 0 0 4\n", &s, 12345);
    EXPECT_EQ(s.options.shading.seed, 7u);
}

// -ld: Radiance takes a direction of length FTINY (1e-6) or less as no
// limit (its rayorigin() treats rmax <= FTINY as none), and only the length
// matters, not how small the components are.
TEST(RtraceRun, LimitDistanceIgnoresTinyDirections) {
    FakeState s;
    Result r = RunWith({"-h", "-ld", "x.rad"}, "0 0 0 0 0 1e-7\n0 0 0 0 0 1e-6\n0 0 0 0 0 2e-6\n",
                       &s);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(s.rmax, (std::vector<double>{0, 0, 2e-6}));
}

// Output that needs no value: the renderer only intersects (Radiance's
// castonly) and gets no ambient calculation and no ambient file.
TEST(RtraceRun, CastOnlyOutputLeavesTheAmbientCalculationOut) {
    FakeState s;
    RunWith({"-h", "-oLps", "-ab", "2", "-af", "x.amb", "x.rad"}, "0 0 0 0 0 1\n", &s);
    EXPECT_TRUE(s.options.shading.castOnly);
    EXPECT_EQ(s.options.ambient.bounces, 0);
    EXPECT_EQ(s.options.ambient.file, "");
    RunWith({"-h", "-oLpsv", "-ab", "2", "-af", "x.amb", "x.rad"}, "0 0 0 0 0 1\n", &s);
    EXPECT_FALSE(s.options.shading.castOnly);
    EXPECT_EQ(s.options.ambient.bounces, 2);
    EXPECT_EQ(s.options.ambient.file, "x.amb");
    RunWith({"-h", "-otLps", "-ab", "2", "x.rad"}, "0 0 0 0 0 1\n", &s);  // trace mode shades
    EXPECT_FALSE(s.options.shading.castOnly);
}

// Radiance 5.4a's rtrace: a flush interval (-x without -y) below -n lowers
// the process count to it, with a warning; not with -y, not when they are
// equal, and not for cast-only output, which runs in one process anyway.
TEST(RtraceRun, FlushIntervalBelowProcessCountReducesIt) {
    const std::string warning = "rtrace: warning - reducing number of processes to match flush interval\n";
    FakeState s;
    Result r = RunWith({"-h", "-n", "3", "-x", "2", "x.rad"}, "0 0 0 0 0 1\n", &s);
    EXPECT_EQ(r.err, warning);
    EXPECT_EQ(s.options.processes, 2);
    for (const std::vector<std::string>& args :
         {std::vector<std::string>{"-h", "-n", "2", "-x", "2", "x.rad"},
          std::vector<std::string>{"-h", "-n", "4", "-x", "3", "-y", "2", "x.rad"},
          std::vector<std::string>{"-h", "-n", "2", "-x", "1", "-oL", "x.rad"}}) {
        r = RunWith(args, "0 0 0 0 0 1\n", &s);
        EXPECT_EQ(r.err.find("reducing"), std::string::npos) << args[2] << " " << args[4];
    }
    EXPECT_EQ(s.options.processes, 1);  // the cast-only run
}

TEST(RtraceRun, FlushRequestRepeatsPreviousRay) {
    FakeState s;
    Result r = RunWith({"-h", "-oodvL", "s.rad"}, "0 0 0 0 0 0\n1 2 3 0 0 2\n0 0 0 0 0 0\n", &s);
    EXPECT_EQ(r.status, 0);
    const std::string zeros3 = "0.000000e+00\t0.000000e+00\t0.000000e+00\t";
    EXPECT_EQ(r.out,
              zeros3 + zeros3 + zeros3 + "1.000000e+10\t\n" +
              "1.000000e+00\t2.000000e+00\t3.000000e+00\t" + "0.000000e+00\t0.000000e+00\t1.000000e+00\t" +
              "5.000000e-01\t2.500000e-01\t1.250000e-01\t2.000000e+00\t\n" +
              "1.000000e+00\t2.000000e+00\t3.000000e+00\t" + "0.000000e+00\t0.000000e+00\t1.000000e+00\t" +
              zeros3 + "1.000000e+10\t\n");
    EXPECT_EQ(s.indices, std::vector<std::uint64_t>{1});
}

TEST(RtraceRun, CountsRecordsWithY) {
    Result r = RunWith({"-h", "-y", "2", "s.rad"}, "0 0 0 0 0 1\n0 0 0 0 0 0\n0 0 0 0 0 1\n");
    EXPECT_EQ(r.status, 0);
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 2);
    EXPECT_EQ(r.err, "");

    r = RunWith({"-h", "-y", "5", "s.rad"}, "0 0 0 0 0 1\n");
    EXPECT_EQ(r.status, 0);
    EXPECT_EQ(r.out, kValueLine);
    EXPECT_EQ(r.err, "rtrace: warning - unexpected EOF on input\n");
    r = RunWith({"-h", "-w-", "-y", "5", "s.rad"}, "0 0 0 0 0 1\n");
    EXPECT_EQ(r.err, "");
    // A negative count (unsigned in rtrace.c) reads all input and warns at its end.
    r = RunWith({"-h", "-y", "-1", "s.rad"}, "0 0 0 0 0 1\n0 0 0 0 0 1\n");
    EXPECT_EQ(r.status, 0);
    EXPECT_EQ(r.out, std::string(kValueLine) + kValueLine);
    EXPECT_EQ(r.err, "rtrace: warning - unexpected EOF on input\n");
}

TEST(RtraceRun, PictureResolutionLine) {
    std::string input;
    for (int i = 0; i < 7; ++i) input += "0 0 0 0 0 1\n";
    Result r = RunWith({"-h-", "-x", "3", "-y", "2", "s.rad"}, input);
    EXPECT_EQ(r.out.rfind("-Y 2 +X 3\n", 0), 0u);
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1 + 6);

    r = RunWith({"-ffc", "-x", "2", "-y", "1", "s.rad"},
                std::string(reinterpret_cast<const char*>(std::vector<float>{0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 1}.data()), 48));
    EXPECT_NE(r.out.find("FORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 2\n"), std::string::npos);
    // 0.5 0.25 0.125 -> mantissas 128 64 32, exponent 128
    EXPECT_EQ(r.out.substr(r.out.size() - 8), std::string("\x80\x40\x20\x80\x80\x40\x20\x80", 8));
}

TEST(RtraceRun, BadRayStopsAfterWritingEarlierResults) {
    Result r = RunWith({"-h", "s.rad"}, "0 0 0 0 0 1\n0 0 0\n0 0 zero\n");
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.out, kValueLine);
    EXPECT_EQ(r.err, "rtrace: bad ray at line 3\n");
}

TEST(RtraceRun, CommandLineErrors) {
    FakeState s;
    Result r = RunWith({"-ab2", "s.rad"}, "", &s);
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.err, "rtrace: fatal - command line error at '-ab2'\n");
    r = RunWith({"-ab", "2"}, "", &s);
    EXPECT_EQ(r.err, "rtrace: fatal - missing octree argument\n");
    r = RunWith({"-ovq", "s.rad"}, "", &s);
    EXPECT_EQ(r.err, "rtrace: fatal - unrecognized output option 'q'\n");
    r = RunWith({"-o", "s.rad"}, "", &s);
    EXPECT_EQ(r.err, "rtrace: fatal - empty output specification\n");
    r = RunWith({"-fac", "-ovo", "s.rad"}, "", &s);
    EXPECT_EQ(r.err, "rtrace: fatal - color format only with -ov, -or, -ox\n");
    // Radiance refuses the colour format last, after the letters' own
    // errors and warnings (real rtrace 5.4a's stderr for each command line).
    r = RunWith({"-fac", "-oq", "s.rad"}, "", &s);
    EXPECT_EQ(r.err, "rtrace: fatal - unrecognized output option 'q'\n");
    r = RunWith({"-fac", "-I", "-oL", "s.rad"}, "", &s);
    EXPECT_EQ(r.err, "rtrace: fatal - -I+ and -i+ options require some value output\n");
    r = RunWith({"-fac", "-oVW", "s.rad"}, "", &s);
    EXPECT_EQ(r.err,
              "rtrace: warning - -oVW options require trace mode\n"
              "rtrace: warning - -oVW options require trace mode\n"
              "rtrace: fatal - color format only with -ov, -or, -ox\n");
    r = RunWith({"-fac", "-ab", "1", "-ovtV", "s.rad"}, "", &s);
    EXPECT_EQ(r.err,
              "rtrace: warning - -otV accuracy depends on -aa 0 -as 0\n"
              "rtrace: fatal - color format only with -ov, -or, -ox\n");
    EXPECT_EQ(s.built, 0);  // all found before the scene is loaded
    r = RunWith({"@/no/such/file", "s.rad"}, "", &s);
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err, "rtrace: system - cannot expand '@/no/such/file': No such file or directory\n");
    // A bare '@' names no file: Radiance gives no cause.
    r = RunWith({"@", "s.rad"}, "", &s);
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err, "rtrace: system - cannot expand '@'\n");
    // A directory reads as no words, as Radiance's wordfile() reads it (it
    // used to be an internal error from the stream's failed read).
    r = RunWith({"-h", "@/", "s.rad"}, "0 0 0 0 0 1\n", &s);
    EXPECT_EQ(r.status, 0);
    EXPECT_EQ(r.err, "");
    EXPECT_EQ(r.out, kValueLine);
}

TEST(RtraceRun, SceneErrorsUseExitCodes) {
    RunEnvironment env;
    env.makeEvaluator = [](const std::vector<std::string>&, const RtraceOptions&,
                           const WarningSink&) -> std::unique_ptr<RayEvaluator> {
        ThrowUserError(FileLoc{"room.rad", 3, -1}, "undefined modifier 'paint'");
    };
    std::vector<std::string> args = {"rtrace", "room.rad"};
    std::istringstream in("");
    std::ostringstream out, err;
    EXPECT_EQ(rt::Run(args, in, out, err, env), 1);
    EXPECT_EQ(err.str(), "rtrace: fatal - room.rad:3: undefined modifier 'paint'\n");
    EXPECT_EQ(out.str(), "");
}

TEST(RtraceRun, VersionAndDefaults) {
    Result r = RunWith({"-version"}, "");
    EXPECT_EQ(r.status, 0);
    EXPECT_EQ(r.out, "lazyrad 0.1.0 (RADIANCE 5.4a compatible)\n");
    r = RunWith({"-ab", "3", "-defaults"}, "");
    EXPECT_EQ(r.status, 0);
    EXPECT_NE(r.out.find("-ab 3        \t\t\t# ambient bounces\n"), std::string::npos);
}

TEST(RtraceRun, TraceOutputWithLists) {
    Result r = RunWith({"-h", "-ov~tmL", "s.rad"}, "0 0 0 0 0 1\n");
    EXPECT_EQ(r.out, "\twall\t1.000000e+10\t\nfloor\t2.000000e+00\t\n" + std::string(kValueLine, 39) + "~\t\n");
    r = RunWith({"-h", "-ti", "floor", "-otm", "s.rad"}, "0 0 0 0 0 1\n");
    EXPECT_EQ(r.out, "floor\t\n");
    r = RunWith({"-h", "-te", "floor", "-otm", "s.rad"}, "0 0 0 0 0 1\n");
    EXPECT_EQ(r.out, "\twall\t\n");
    r = RunWith({"-h", "-oTm", "s.rad"}, "0 0 0 0 0 1\n");
    EXPECT_EQ(r.out, "\tlamp\t\nfloor\t\n");
}

TEST(RtraceRun, UnimplementedOptionsWarn) {
    Result r = RunWith({"-h", "-n", "2", "-me", "1", "1", "1", "s.rad"}, "");
    EXPECT_EQ(r.status, 0);
    EXPECT_EQ(r.err.find("multiprocessing"), std::string::npos);  // -n works now
    EXPECT_EQ(r.err.find("participating medium"), std::string::npos);  // -me works now
    r = RunWith({"-h", "-ap", "x.pm", "s.rad"}, "");
    EXPECT_NE(r.err.find("rtrace: warning - photon mapping"), std::string::npos);
}

TEST(RtraceRun, ErrorFileGetsBannerAndMessages) {
    std::string path = std::string(RT_BINARY_DIR) + "/rtrace_test_errors.log";
    std::remove(path.c_str());
    Result r = RunWith({"-h", "-e", path, "-y", "3", "s.rad"}, "0 0 0 0 0 1\n");
    EXPECT_EQ(r.status, 0);
    EXPECT_EQ(r.err, "");
    std::ifstream f(path);
    std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    EXPECT_EQ(text, "**************\n*** PID    42: rtrace -h -e " + path +
                        " -y 3 s.rad\n\nrtrace: warning - unexpected EOF on input\n");

    // No scene: Radiance opens the -e file first, so the message lands there.
    std::remove(path.c_str());
    r = RunWith({"-e", path}, "");
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.err, "");
    std::ifstream g(path);
    text.assign(std::istreambuf_iterator<char>(g), std::istreambuf_iterator<char>());
    EXPECT_EQ(text, "**************\n*** PID    42: rtrace -e " + path +
                        "\n\nrtrace: fatal - missing octree argument\n");
}

}  // namespace
}  // namespace rt
