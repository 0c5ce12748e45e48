// SPDX-License-Identifier: MIT
#include "rtrace/command_line.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "core/error.h"

namespace rt {
namespace {

// Verified output of Radiance 5.4a `rtrace -defaults` (radiance-notes.md §1.3).
constexpr const char* kRadianceDefaults =
    "-n 1 \t\t\t\t# number of rendering processes\n"
    "-x 0        \t\t\t# flush interval\n"
    "-y 0        \t\t\t# y resolution\n"
    "-ld-\t\t\t\t# limit distance off\n"
    "-h+\t\t\t\t# output header\n"
    "-faa\t\t\t\t# format input/output = ascii/ascii\n"
    "-ov        \t\t\t# output value\n"
    "-w+\t\t\t\t# warning messages on\n"
    "-i-\t\t\t\t# irradiance calculation off\n"
    "-u+\t\t\t\t# uncorrelated Monte Carlo sampling\n"
    "-bv+\t\t\t\t# back face visibility on\n"
    "-dt 0.030000\t\t\t# direct threshold\n"
    "-dc 0.750000\t\t\t# direct certainty\n"
    "-dj 0.000000\t\t\t# direct jitter\n"
    "-ds 0.200000\t\t\t# direct sampling\n"
    "-dr 2        \t\t\t# direct relays\n"
    "-dp 512      \t\t\t# direct pretest density\n"
    "-dv+\t\t\t\t# direct visibility on\n"
    "-ss 1.000000\t\t\t# specular sampling\n"
    "-st 0.150000\t\t\t# specular threshold\n"
    "-av 0.000000 0.000000 0.000000\t# ambient value\n"
    "-aw 0        \t\t\t# ambient value weight\n"
    "-ab 0        \t\t\t# ambient bounces\n"
    "-aa 0.100000\t\t\t# ambient accuracy\n"
    "-ar 256      \t\t\t# ambient resolution\n"
    "-ad 1024     \t\t\t# ambient divisions\n"
    "-as 512      \t\t\t# ambient super-samples\n"
    "-me 0.00e+00 0.00e+00 0.00e+00\t# mist extinction coefficient\n"
    "-ma 0.000000 0.000000 0.000000\t# mist scattering albedo\n"
    "-mg 0.000000\t\t\t# mist scattering eccentricity\n"
    "-ms 0.000000\t\t\t# mist sampling distance\n"
    "-lr -10      \t\t\t# limit reflection (Russian roulette)\n"
    "-lw 2.00e-03\t\t\t# limit weight\n"
    "-am 0.0\t\t\t\t# max photon search radius\n";

CommandLine Parse(std::vector<std::string> args, std::vector<std::string>* warnings = nullptr) {
    args.insert(args.begin(), "/usr/local/bin/rtrace");
    return ParseCommandLine(args, [warnings](const std::string& w) {
        if (warnings) warnings->push_back(w);
    });
}

RtraceOptions ParseOptions(std::vector<std::string> args) {
    args.push_back("scene.rad");
    return Parse(args).options;
}

std::string ErrorOf(std::vector<std::string> args) {
    try {
        Parse(args);
    } catch (const Error& e) {
        return e.what();
    }
    return "(no error)";
}

std::string ReplaceLine(std::string text, const std::string& from, const std::string& to) {
    auto pos = text.find(from);
    EXPECT_NE(pos, std::string::npos) << from;
    if (pos != std::string::npos) text.replace(pos, from.size(), to);
    return text;
}

TEST(RtraceDefaults, MatchesRadianceByteForByte) {
    CommandLine cl = Parse({"-defaults"});
    EXPECT_EQ(cl.action, CommandLine::Action::PrintDefaults);
    EXPECT_EQ(FormatDefaults(cl.options), kRadianceDefaults);
    EXPECT_EQ(Parse({"-help"}).action, CommandLine::Action::PrintDefaults);
}

/// Radiance 5.4a prints -n as given ("-n 100"), then forks at most 64
/// processes (65 with the parent, counted with pgrep); lazyrad printed 64.
TEST(RtraceDefaults, ShowTheProcessCountAsGivenAndRunAtMost64Threads) {
    const CommandLine cl = Parse({"-n", "100", "-defaults"});
    EXPECT_EQ(FormatDefaults(cl.options),
              ReplaceLine(kRadianceDefaults, "-n 1 \t\t\t\t# number of rendering processes",
                          "-n 100\t\t\t\t# number of rendering processes"));
    EXPECT_EQ(RenderThreads(cl.options), 64);
    EXPECT_EQ(RenderThreads(Parse({"-n", "3", "-defaults"}).options), 3);
}

TEST(RtraceDefaults, DefaultsMatchStructInitialisers) {
    EXPECT_EQ(FormatDefaults(RtraceOptions{}), kRadianceDefaults);
}

TEST(RtraceDefaults, ShowEarlierOptions) {
    CommandLine cl = Parse({"-I", "-x", "32", "-y", "16", "-h-", "-w-", "-u-", "-lr", "8",
                            "-ffd", "-ovlpnNmsMwWVdortTRxXLc~-", "-defaults", "-ab", "3"});
    std::string expected = std::string("-I+\t\t\t\t# immediate irradiance on\n") + kRadianceDefaults;
    expected = ReplaceLine(expected, "-x 0        \t\t\t# flush interval",
                           "-x 32       \t\t\t# x resolution");
    expected = ReplaceLine(expected, "-y 0        ", "-y 16       ");
    expected = ReplaceLine(expected, "-h+\t\t\t\t# output header", "-h-\t\t\t\t# no header");
    expected = ReplaceLine(expected, "-faa\t\t\t\t# format input/output = ascii/ascii",
                           "-ffd\t\t\t\t# format input/output = float/double");
    expected = ReplaceLine(
        expected, "-ov        \t\t\t# output value",
        "-ovlpnNmsMwWVdortTRxXLc~-\t\t\t# output value length point normal unperturbed_normal "
        "modifier surface material weight coefficient contribution direction origin "
        "reflect_contrib trace trace reflect_length unreflect_contrib unreflect_length "
        "first_length stroke");
    expected = ReplaceLine(expected, "-w+\t\t\t\t# warning messages on",
                           "-w-\t\t\t\t# warning messages off");
    expected = ReplaceLine(expected, "-u+\t\t\t\t# uncorrelated Monte Carlo sampling",
                           "-u-\t\t\t\t# correlated quasi-Monte Carlo sampling");
    expected = ReplaceLine(expected, "-lr -10      \t\t\t# limit reflection (Russian roulette)",
                           "-lr 8        \t\t\t# limit reflection");
    EXPECT_EQ(FormatDefaults(cl.options), expected);
}

TEST(RtraceDefaults, FlushIntervalCommentNeedsBothResolutions) {
    std::string text = FormatDefaults(Parse({"-x", "5", "-defaults"}).options);
    EXPECT_NE(text.find("-x 5        \t\t\t# flush interval\n"), std::string::npos);
}

TEST(RtraceDefaults, ValuesAndToggles) {
    std::string text = FormatDefaults(
        Parse({"-i", "-bv-", "-dv", "-ld", "-av", "1", "2", "3", "-me", ".5", "0", "1e-3",
               "-lw", "1e-4", "-n", "4", "-am", "2.5", "-defaults"})
            .options);
    EXPECT_NE(text.find("-i+\t\t\t\t# irradiance calculation on\n"), std::string::npos);
    EXPECT_NE(text.find("-bv-\t\t\t\t# back face visibility off\n"), std::string::npos);
    EXPECT_NE(text.find("-dv-\t\t\t\t# direct visibility off\n"), std::string::npos);
    EXPECT_NE(text.find("-ld+\t\t\t\t# limit distance on\n"), std::string::npos);
    EXPECT_NE(text.find("-av 1.000000 2.000000 3.000000\t# ambient value\n"), std::string::npos);
    EXPECT_NE(text.find("-me 5.00e-01 0.00e+00 1.00e-03\t# mist"), std::string::npos);
    EXPECT_NE(text.find("-lw 1.00e-04\t"), std::string::npos);
    EXPECT_NE(text.find("-n 4 \t\t\t\t#"), std::string::npos);
    EXPECT_NE(text.find("-am 2.5\t\t\t\t#"), std::string::npos);
    EXPECT_EQ(text.find("-I+"), std::string::npos);
}

TEST(RtraceOptionsParse, VersionAndSceneFiles) {
    EXPECT_EQ(Parse({"-version"}).action, CommandLine::Action::PrintVersion);
    CommandLine cl = Parse({"-ab", "2", "-h", "a.rad", "b.rad"});
    EXPECT_EQ(cl.action, CommandLine::Action::Render);
    EXPECT_EQ(cl.args[0], "rtrace");  // directories stripped
    EXPECT_EQ(cl.firstScene, 4u);
    EXPECT_EQ(cl.sceneFiles, (std::vector<std::string>{"a.rad", "b.rad"}));
    EXPECT_EQ(cl.options.ambient.bounces, 2);
    EXPECT_FALSE(cl.options.header);
}

// Walks the table: every option is found, takes the documented number of
// values, and writes what it should.
TEST(RtraceOptionsParse, EveryOptionInTheTableParses) {
    ASSERT_GE(OptionTable().size(), 45u);
    for (const OptionInfo& info : OptionTable()) {
        std::string name(info.name);
        std::vector<std::string> args;
        switch (info.kind) {
            case ValueKind::Toggle: args = {name}; break;
            case ValueKind::Int: args = {name, "3"}; break;
            case ValueKind::Real: args = {name, "0.5"}; break;
            case ValueKind::Rgb: args = {name, "0.1", "0.2", "0.3"}; break;
            case ValueKind::Word: args = {name, "word"}; break;
            case ValueKind::Attached:
                args = {name + (name == "-f" ? "ad" : name == "-ah" ? "m" : "vd")};
                break;
            case ValueKind::Custom: args = {name, name == "-ap" ? "map.pm" : "0.5"}; break;
        }
        if (name == "-tI" || name == "-tE" || name == "-aI" || name == "-aE") continue;  // files
        args.push_back("scene.rad");
        CommandLine cl;
        std::vector<std::string> warnings;
        EXPECT_NO_THROW(cl = Parse(args, &warnings)) << name;
        EXPECT_EQ(cl.sceneFiles, std::vector<std::string>{"scene.rad"}) << name;
        EXPECT_FALSE(info.help.empty()) << name;
        EXPECT_FALSE(info.status.empty()) << name;
        // Glued values are errors for every option that takes separate ones.
        if (info.kind == ValueKind::Int || info.kind == ValueKind::Real ||
            info.kind == ValueKind::Word) {
            EXPECT_EQ(ErrorOf({name + "2", "x.rad"}), "command line error at '" + name + "2'");
        }
        // A missing value is an error at the option.
        if (info.kind != ValueKind::Toggle && info.kind != ValueKind::Attached &&
            name != "-am") {
            EXPECT_EQ(ErrorOf({name}), "command line error at '" + name + "'") << name;
        }
    }
}

TEST(RtraceOptionsParse, ValuesLandInTheirFields) {
    RtraceOptions o = ParseOptions(
        {"-dt", ".1", "-dc", ".2", "-dj", ".3", "-ds", ".4", "-dr", "5", "-dp", "6", "-ss", ".7",
         "-st", ".8", "-lr", "-3", "-lw", "1e-2", "-av", "1", "2", "3", "-aw", "9", "-ab", "4",
         "-aa", ".05", "-ar", "64", "-ad", "128", "-as", "32", "-af", "amb.amb", "-me", "1", "2",
         "3", "-ma", ".1", ".2", ".3", "-mg", ".6", "-ms", ".9", "-x", "7", "-y", "8", "-n", "2",
         "-e", "err.log", "-ffc", "-oovw", "-am", "3"});
    const ShadingOptions& s = o.shading;
    EXPECT_EQ(s.direct.threshold, .1);
    EXPECT_EQ(s.direct.certainty, .2);
    EXPECT_EQ(s.direct.jitter, .3);
    EXPECT_EQ(s.direct.sampling, .4);
    EXPECT_EQ(s.direct.relays, 5);
    EXPECT_EQ(s.direct.pretest, 6);
    EXPECT_EQ(s.specular.sampling, .7);
    EXPECT_EQ(s.specular.threshold, .8);
    EXPECT_EQ(s.limits.reflections, -3);
    EXPECT_EQ(s.limits.weight, 1e-2);
    EXPECT_EQ(o.ambient.value, Rgb(1, 2, 3));
    EXPECT_EQ(o.ambient.valueWeight, 9);
    EXPECT_EQ(o.ambient.bounces, 4);
    EXPECT_EQ(o.ambient.accuracy, .05);
    EXPECT_EQ(o.ambient.resolution, 64);
    EXPECT_EQ(o.ambient.divisions, 128);
    EXPECT_EQ(o.ambient.superSamples, 32);
    EXPECT_EQ(o.ambient.file, "amb.amb");
    EXPECT_EQ(s.medium.extinction, Rgb(1, 2, 3));
    EXPECT_EQ(s.medium.albedo, Rgb(.1, .2, .3));
    EXPECT_EQ(s.medium.eccentricity, .6);
    EXPECT_EQ(s.medium.samplingDistance, .9);
    EXPECT_EQ(o.xResolution, 7);
    EXPECT_EQ(o.yResolution, 8);
    EXPECT_EQ(o.processes, 2);
    EXPECT_EQ(o.errorFile, "err.log");
    EXPECT_EQ(o.inputFormat, 'f');
    EXPECT_EQ(o.outputFormat, 'c');
    EXPECT_EQ(o.outputSpec, "ovw");
    EXPECT_EQ(o.photonMaxRadius, 3);
    o = ParseOptions({"-PP", "pfile"});
    EXPECT_EQ(o.persistFile, "pfile");
    EXPECT_TRUE(o.persistParallel);
}

TEST(RtraceOptionsParse, TogglesFollowRadianceSuffixes) {
    EXPECT_FALSE(ParseOptions({"-h"}).header);
    EXPECT_TRUE(ParseOptions({"-h", "-h"}).header);
    for (const char* on : {"+", "1", "y", "Y", "t", "T"}) {
        EXPECT_TRUE(ParseOptions({"-h-", std::string("-h") + on}).header) << on;
        EXPECT_TRUE(ParseOptions({std::string("-ld") + on}).limitDistance) << on;
        EXPECT_TRUE(ParseOptions({"-bv-", std::string("-bv") + on}).shading.backfaceVisible);
    }
    for (const char* off : {"-", "0", "n", "N", "f", "F"}) {
        EXPECT_FALSE(ParseOptions({std::string("-w") + off}).warnings) << off;
        EXPECT_FALSE(ParseOptions({std::string("-dv") + off}).shading.direct.sourcesVisible);
        EXPECT_FALSE(ParseOptions({std::string("-u") + off}).shading.uncorrelated);
    }
    EXPECT_EQ(ErrorOf({"-hx", "s.rad"}), "command line error at '-hx'");
    // Radiance's check_bool() reads the one character after the name and
    // ignores the rest: 5.4a takes -Iyes, -h++ and -ld+- as "on".
    EXPECT_TRUE(ParseOptions({"-Iyes"}).immediateIrradiance);
    EXPECT_TRUE(ParseOptions({"-h-", "-h++"}).header);
    EXPECT_TRUE(ParseOptions({"-ld+-"}).limitDistance);
    EXPECT_FALSE(ParseOptions({"-wno"}).warnings);
    EXPECT_EQ(ErrorOf({"-hxy", "s.rad"}), "command line error at '-hxy'");
}

/// An option after the scene is an error named after the first scene, as
/// Radiance names its octree when more than one argument follows the options.
TEST(RtraceOptionsParse, OptionAfterTheSceneNamesTheScene) {
    EXPECT_EQ(ErrorOf({"-h", "a.oct", "-ab", "1"}), "command line error at 'a.oct'");
    EXPECT_EQ(ErrorOf({"a.rad", "b.rad", "-ab"}), "command line error at 'a.rad'");
    EXPECT_EQ(ErrorOf({"-ld", "2", "a.oct"}).find("command line error"), std::string::npos);
}

/// -ah (lazyrad's record methods): mixed by default, + Hessian, - classic,
/// m mixed, a bare -ah Hessian; a bad suffix is a one-line error, and -defaults
/// does not list it.
TEST(RtraceOptionsParse, RecordMethodsOption) {
    EXPECT_EQ(ParseOptions({}).ambient.recordMethods, RecordMethods::Mixed);
    EXPECT_EQ(ParseOptions({"-ah+"}).ambient.recordMethods, RecordMethods::Hessian);
    EXPECT_EQ(ParseOptions({"-ah"}).ambient.recordMethods, RecordMethods::Hessian);
    EXPECT_EQ(ParseOptions({"-ah-"}).ambient.recordMethods, RecordMethods::Classic);
    EXPECT_EQ(ParseOptions({"-ah+", "-ah-"}).ambient.recordMethods, RecordMethods::Classic);
    EXPECT_EQ(ParseOptions({"-ah-", "-ahm"}).ambient.recordMethods, RecordMethods::Mixed);
    EXPECT_EQ(ErrorOf({"-ahx", "s.rad"}), "command line error at '-ahx'");
    EXPECT_EQ(ErrorOf({"-ah++", "s.rad"}), "command line error at '-ah++'");
    EXPECT_EQ(FormatDefaults(ParseOptions({"-ah+"})).find("-ah"), std::string::npos);
}

TEST(RtraceOptionsParse, IrradianceModes) {
    EXPECT_EQ(ParseOptions({}).shading.irradiance, IrradianceMode::Off);
    EXPECT_EQ(ParseOptions({"-i"}).shading.irradiance, IrradianceMode::AtHit);
    EXPECT_EQ(ParseOptions({"-I+"}).shading.irradiance, IrradianceMode::Immediate);
    EXPECT_EQ(ParseOptions({"-i", "-I", "-I"}).shading.irradiance, IrradianceMode::AtHit);
}

/// Issue 18: -ad 2147483647 ended in "internal - std::bad_alloc"; -ad above
/// the division limit is a one-line error naming the option and the limit.
TEST(RtraceOptionsParse, DivisionsAboveTheLimitAreAnError) {
    EXPECT_EQ(ParseOptions({"-ad", std::to_string(kMaxAmbientDivisions)}).ambient.divisions,
              kMaxAmbientDivisions);
    EXPECT_EQ(ErrorOf({"-ad", "2147483647", "s.rad"}),
              "-ad 2147483647 is above the limit of 4194304 hemisphere divisions");
    EXPECT_EQ(ErrorOf({"-ad", "500000000", "s.rad"}),
              "-ad 500000000 is above the limit of 4194304 hemisphere divisions");
    // -as has no limit of its own: each hemisphere clamps it to its divisions.
    EXPECT_EQ(ParseOptions({"-as", "2147483647"}).ambient.superSamples, 2147483647);
}

TEST(RtraceOptionsParse, RejectsBadValuesAndUnknownOptions) {
    EXPECT_EQ(ErrorOf({"-ab2", "s.rad"}), "command line error at '-ab2'");
    EXPECT_EQ(ErrorOf({"-ab", "2.5", "s.rad"}), "command line error at '-ab'");
    EXPECT_EQ(ErrorOf({"-aa", "x", "s.rad"}), "command line error at '-aa'");
    EXPECT_EQ(ErrorOf({"-aa", ".", "s.rad"}), "command line error at '-aa'");
    EXPECT_EQ(ErrorOf({"-aa", "1e", "s.rad"}), "command line error at '-aa'");
    EXPECT_EQ(ErrorOf({"-av", "1", "2", "s.rad"}), "command line error at '-av'");
    EXPECT_EQ(ErrorOf({"-zz", "s.rad"}), "command line error at '-zz'");
    EXPECT_EQ(ErrorOf({"-fc", "s.rad"}), "command line error at '-fc'");
    EXPECT_EQ(ErrorOf({"-fax", "s.rad"}), "command line error at '-fax'");
    EXPECT_EQ(ErrorOf({"-fadd", "s.rad"}), "command line error at '-fadd'");
    EXPECT_EQ(ErrorOf({"-n", "0", "s.rad"}), "bad number of processes");
    EXPECT_EQ(ErrorOf({"-am", "0", "s.rad"}), "invalid max photon search radius");  // Radiance 5.4a's words
    // Any -am... with more letters, with or without a number (Radiance 5.4a).
    EXPECT_EQ(ErrorOf({"-amx", "1", "s.rad"}), "invalid max photon search radius");
    EXPECT_EQ(ErrorOf({"-amm", "s.rad"}), "invalid max photon search radius");
    EXPECT_EQ(ErrorOf({"-apx", "f", "s.rad"}), "command line error at '-apx'");
    EXPECT_EQ(ErrorOf({"-ab", "2"}), "missing octree argument");
    EXPECT_EQ(ErrorOf({"s.rad", "-ab", "2"}), "command line error at 's.rad'");
    EXPECT_EQ(ErrorOf({"-n", "2", "-P", "pf", "s.rad"}),
              "multiprocessing incompatible with persist file");
    // Octrees, octree commands and standard input are scene arguments.
    EXPECT_EQ(ErrorOf({"scene.oct"}), "(no error)");
    EXPECT_EQ(ErrorOf({"!oconv x.rad"}), "(no error)");
    EXPECT_EQ(ErrorOf({"-"}), "(no error)");
    EXPECT_EQ(ErrorOf({"s.rad", "-x"}), "command line error at 's.rad'");
    // Radiance's validation accepts these forms.
    EXPECT_EQ(ParseOptions({"-aa", "+.5e-1"}).ambient.accuracy, 0.05);
    EXPECT_EQ(ParseOptions({"-ab", "-0"}).ambient.bounces, 0);
    EXPECT_EQ(ParseOptions({"-aa", "5."}).ambient.accuracy, 5.0);
}

TEST(RtraceOptionsParse, ErrorKindsAndExitCodes) {
    try {
        Parse({"-ab2", "s.rad"});
        FAIL();
    } catch (const Error& e) {
        EXPECT_EQ(e.ExitCode(), 1);
    }
    try {
        Parse({"@/nonexistent/options/file", "s.rad"});
        FAIL();
    } catch (const Error& e) {
        EXPECT_EQ(e.ExitCode(), 2);
        EXPECT_EQ(std::string(e.what()).rfind("cannot expand '@/nonexistent/options/file'", 0), 0u);
    }
}

TEST(RtraceOptionsParse, OutputAndFormatWords) {
    RtraceOptions o = ParseOptions({"-o"});
    EXPECT_EQ(o.outputSpec, "");  // validated later: "empty output specification"
    o = ParseOptions({"-fd"});
    EXPECT_EQ(o.inputFormat, 'd');
    EXPECT_EQ(o.outputFormat, 'd');
    o = ParseOptions({"-ffa"});
    EXPECT_EQ(o.inputFormat, 'f');
    EXPECT_EQ(o.outputFormat, 'a');
}

TEST(RtraceOptionsParse, AmbientListsRestartOnTheOtherKind) {
    RtraceOptions o = ParseOptions({"-ae", "a", "-ae", "b"});
    EXPECT_FALSE(o.ambient.listIsInclude);
    EXPECT_EQ(o.ambient.modifierList, (std::vector<std::string>{"a", "b"}));
    o = ParseOptions({"-ae", "a", "-ai", "b", "-ai", "c"});
    EXPECT_TRUE(o.ambient.listIsInclude);
    EXPECT_EQ(o.ambient.modifierList, (std::vector<std::string>{"b", "c"}));
    o = ParseOptions({"-ai", "b", "-ae", "c"});
    EXPECT_FALSE(o.ambient.listIsInclude);
    EXPECT_EQ(o.ambient.modifierList, std::vector<std::string>{"c"});
    o = ParseOptions({"-te", "x", "-ti", "y"});
    EXPECT_TRUE(o.traceListSet);
    EXPECT_TRUE(o.traceListIsInclude);
    EXPECT_EQ(o.traceModifiers, std::vector<std::string>{"y"});
}

TEST(RtraceOptionsParse, ListFiles) {
    std::string path = std::string(RT_BINARY_DIR) + "/rtrace_test_mods.txt";
    std::ofstream(path) << "wall floor\n  ceiling\n";
    RtraceOptions o = ParseOptions({"-ai", "x", "-aE", path});
    EXPECT_FALSE(o.ambient.listIsInclude);
    EXPECT_EQ(o.ambient.modifierList, (std::vector<std::string>{"wall", "floor", "ceiling"}));
    o = ParseOptions({"-tI", path});
    EXPECT_EQ(o.traceModifiers.size(), 3u);
    EXPECT_EQ(ErrorOf({"-aI", "/nonexistent/mods", "s.rad"}),
              "cannot open ambient include file \"/nonexistent/mods\": No such file or directory");
}

TEST(RtraceOptionsParse, PhotonMapOption) {
    std::vector<std::string> warnings;
    CommandLine cl = Parse({"-ap", "g.pm", "s.rad"}, &warnings);
    ASSERT_EQ(cl.options.photonMaps.size(), 1u);
    EXPECT_EQ(cl.options.ambient.bounces, 1);  // a photon map implies -ab 1
    EXPECT_EQ(warnings, std::vector<std::string>{"missing photon lookup bandwidth, defaulting to 40"});
    cl = Parse({"-ab", "3", "-ap", "g.pm", "50", "100", "s.rad"});
    EXPECT_EQ(cl.options.ambient.bounces, 3);
    EXPECT_EQ(cl.options.photonMaps[0].minGather, 50);
    EXPECT_EQ(cl.options.photonMaps[0].maxGather, 100);
    EXPECT_EQ(ErrorOf({"-ap", "g.pm", "100", "50", "s.rad"}), "command line error at '-ap'");
}

TEST(RtraceOptionsParse, AtFileAndEnvironmentExpansion) {
    std::string path = std::string(RT_BINARY_DIR) + "/rtrace_test_opts.txt";
    std::ofstream(path) << "-ab 3\n-aa .2 \"-av\" 1 1 1\n";
    CommandLine cl = Parse({"-h", "@" + path, "-ad", "64", "s.rad"});
    EXPECT_EQ(cl.options.ambient.bounces, 3);
    EXPECT_EQ(cl.options.ambient.accuracy, .2);
    EXPECT_EQ(cl.options.ambient.value, Rgb(1, 1, 1));
    EXPECT_EQ(cl.options.ambient.divisions, 64);
    EXPECT_EQ(cl.args, (std::vector<std::string>{"rtrace", "-h", "-ab", "3", "-aa", ".2", "-av",
                                                 "1", "1", "1", "-ad", "64", "s.rad"}));
    EXPECT_EQ(cl.firstScene, 12u);

    setenv("RTRACE_TEST_OPTS", "-ab 5 -u-", 1);
    cl = Parse({"$RTRACE_TEST_OPTS", "s.rad"});
    EXPECT_EQ(cl.options.ambient.bounces, 5);
    EXPECT_FALSE(cl.options.shading.uncorrelated);
    unsetenv("RTRACE_TEST_OPTS_MISSING");
    EXPECT_EQ(ErrorOf({"$RTRACE_TEST_OPTS_MISSING", "s.rad"}),
              "cannot expand '$RTRACE_TEST_OPTS_MISSING'");
}

}  // namespace
}  // namespace rt
