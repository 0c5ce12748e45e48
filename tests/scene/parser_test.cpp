// SPDX-License-Identifier: MIT
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>

#include "scene/reader.h"
#include "scene_test_util.h"

namespace rt {
namespace {

using testing::ParseError;
using testing::ParseText;

TEST(SceneParser, ReadsPrimitiveWithLocation) {
    const auto objects = ParseText(
        "# a comment\n"
        "void plastic red\n0\n0\n5 .6 .1 .1 0 0\n"
        "\n"
        "red polygon floor 0 0 9\n 0 0 0  1 0 0\n 0 1 0\n");
    ASSERT_EQ(objects.size(), 2u);
    EXPECT_EQ(objects[0].modifier, "void");
    EXPECT_EQ(objects[0].type, "plastic");
    EXPECT_EQ(objects[0].name, "red");
    EXPECT_EQ(objects[0].rargs, (std::vector<double>{.6, .1, .1, 0, 0}));
    EXPECT_EQ(objects[0].loc.ToString(), "t.rad:2");
    EXPECT_EQ(objects[1].modifier, "red");
    EXPECT_EQ(objects[1].rargs.size(), 9u);
    EXPECT_EQ(objects[1].loc.ToString(), "t.rad:7");
}

TEST(SceneParser, QuotedWordsKeepWhiteSpace) {
    const auto objects = ParseText("void colorfunc \"my pat\" 3 'a b' \"c'd\" x 0 0\n");
    ASSERT_EQ(objects.size(), 1u);
    EXPECT_EQ(objects[0].name, "my pat");
    EXPECT_EQ(objects[0].sargs, (std::vector<std::string>{"a b", "c'd", "x"}));
}

TEST(SceneParser, AliasIsFourWords) {
    const auto objects = ParseText("void plastic a 0 0 5 1 1 1 0 0\ninherit alias b a\nvoid alias c b\n");
    ASSERT_EQ(objects.size(), 3u);
    EXPECT_EQ(objects[1].modifier, "inherit");
    EXPECT_EQ(objects[1].type, "alias");
    EXPECT_EQ(objects[1].name, "b");
    EXPECT_EQ(objects[1].sargs, std::vector<std::string>{"a"});
    EXPECT_TRUE(objects[1].rargs.empty());
    EXPECT_EQ(objects[2].loc.line, 3);
}

TEST(SceneParser, AcceptsRadianceNumberForms) {
    const auto objects = ParseText("void glow g 0 0 4 1e3 +.5 -2. 3E-2\n");
    ASSERT_EQ(objects.size(), 1u);
    EXPECT_EQ(objects[0].rargs, (std::vector<double>{1000, 0.5, -2, 0.03}));
    EXPECT_EQ(ParseRealWord("1e-400").value_or(-1), 0.0);  // underflow is harmless
    EXPECT_FALSE(ParseRealWord("1e400"));
    EXPECT_FALSE(ParseRealWord("nan"));
    EXPECT_FALSE(ParseRealWord("inf"));
    EXPECT_FALSE(ParseRealWord("0x10"));
    EXPECT_FALSE(ParseRealWord("."));
    EXPECT_FALSE(ParseRealWord("1e"));
}

TEST(SceneParser, ErrorsNameFileAndLine) {
    EXPECT_EQ(ParseError("void plastic p\n0\n0\n5 1 1 x 0 0\n"),
              "t.rad:4: bad real argument 'x' in plastic \"p\"");
    EXPECT_EQ(ParseError("\n\nvoid plastic p 0 1 5 1 1 1 0 0\n"),
              "t.rad:3: bad integer argument count '1' in plastic \"p\" (must be 0)");
    EXPECT_EQ(ParseError("void plastic p\n-1\n"),
              "t.rad:2: bad string argument count '-1' in plastic \"p\"");
    EXPECT_EQ(ParseError("void plastic p 0 0\nfive\n"),
              "t.rad:2: bad real argument count 'five' in plastic \"p\"");
    EXPECT_EQ(ParseError("void plastic p 0 0 5 1 1\n1\n"),
              "t.rad:3: unexpected end of file in plastic \"p\": expected real argument");
    EXPECT_EQ(ParseError("void plastic\n"),
              "t.rad:2: unexpected end of file in plastic \"\": expected identifier");
    EXPECT_EQ(ParseError("void\n"),
              "t.rad:2: unexpected end of file: expected object type after modifier \"void\"");
    EXPECT_EQ(ParseError("# ok\nvoid plastik p 0 0 5 1 1 1 0 0\n"),
              "t.rad:2: unknown object type 'plastik'");
    EXPECT_EQ(ParseError("inherit polygon p 0 0 9 0 0 0 1 0 0 0 1 0\n"),
              "t.rad:1: inappropriate use of 'inherit' modifier in polygon \"p\"");
    EXPECT_EQ(ParseError("void plastic 'p\n0 0 5 1 1 1 0 0\n"), "t.rad:1: unterminated quoted word");
    EXPECT_EQ(ParseError("\"a\tb\" plastic p 0 0 5 1 1 1 0 0\n"),
              "t.rad:1: illegal tab in modifier \"a\\x09b\"");
    EXPECT_EQ(ParseError("void plastic p 0 0 5 1 1 1 0 0\nvoid alias q\n"),
              "t.rad:3: unexpected end of file in alias \"q\": expected alias reference");
}

TEST(SceneParser, BinaryGarbageGivesCleanErrors) {
    std::mt19937 random(12345);
    int errors = 0;
    for (int trial = 0; trial < 500; ++trial) {
        std::string garbage(1 + random() % 400, '\0');
        for (char& c : garbage) c = static_cast<char>(random() % 256);
        if (trial % 5 == 0) garbage = "void plastic p 0 0 5 " + garbage;  // garbage inside arguments
        garbage.erase(std::remove(garbage.begin(), garbage.end(), '!'), garbage.end());
        try {
            ParseText(garbage);
        } catch (const Error& e) {
            EXPECT_EQ(static_cast<int>(e.kind()), static_cast<int>(Error::Kind::User));
            EXPECT_EQ(std::string(e.what()).rfind("t.rad:", 0), 0u) << e.what();
            ++errors;
        }
    }
    EXPECT_GT(errors, 400);
}

TEST(SceneParser, CommandOutputIsParsedWithItsOrigin) {
    const auto objects =
        ParseText("void plastic a 0 0 5 1 1 1 0 0\n!echo 'a sphere s 0 0 4 1 2 3 1'\n");
    ASSERT_EQ(objects.size(), 2u);
    EXPECT_EQ(objects[1].name, "s");
    EXPECT_EQ(objects[1].loc.ToString(), "t.rad:2: !echo 'a sphere s 0 0 4 1 2 3 1':1");
}

TEST(SceneParser, CommandContinuationLines) {
    const auto objects = ParseText("!echo void plastic \\\n  a 0 0 5 1 1 1 0 0\n");
    ASSERT_EQ(objects.size(), 1u);
    EXPECT_EQ(objects[0].name, "a");
}

TEST(SceneParser, ErrorInsideCommandOutputNamesTheCommand) {
    EXPECT_EQ(ParseError("\n!echo void plastic p 0 0 1 zz\n"),
              "t.rad:2: !echo void plastic p 0 0 1 zz:1: bad real argument 'zz' in plastic \"p\"");
}

TEST(SceneParser, FailingCommandIsAnError) {
    EXPECT_EQ(ParseError("# x\n!exit 3\n"), "t.rad:2: command failed (exit status 3): !exit 3");
    EXPECT_EQ(ParseError("!echo void plastic p 0 0 1 zz; exit 2\n"),
              "t.rad:1: command failed (exit status 2): !echo void plastic p 0 0 1 zz; exit 2");
}

TEST(SceneParser, CommandsCannotReadStandardInput) {
    std::vector<std::string> warnings;
    const auto objects = ParseText("!cat\n", &warnings);
    EXPECT_TRUE(objects.empty());
    ASSERT_EQ(warnings.size(), 2u);
    EXPECT_EQ(warnings[0], "(t.rad:1: !cat): empty file");
    EXPECT_EQ(warnings[1], "(t.rad): empty file");
}

TEST(SceneParser, ToolDirectoryComesFirstOnPath) {
    const auto dir = std::filesystem::temp_directory_path() / "rt_scene_parser_tools";
    std::filesystem::create_directories(dir);
    {
        std::ofstream tool(dir / "genbox");
        tool << "#!/bin/sh\necho void plastic from_tool_dir 0 0 5 1 1 1 0 0\n";
    }
    std::filesystem::permissions(dir / "genbox", std::filesystem::perms::owner_all);
    SceneLoadOptions options;
    options.toolDirectory = dir.string();
    const auto objects = ParseText("!genbox x y 1 1 1\n", nullptr, "t.rad", options);
    ASSERT_EQ(objects.size(), 1u);
    EXPECT_EQ(objects[0].name, "from_tool_dir");
    std::filesystem::remove_all(dir);
}

TEST(SceneParser, SelfIncludingCommandStops) {
    const auto path = std::filesystem::temp_directory_path() / "rt_scene_self.rad";
    {
        std::ofstream file(path);
        file << "void plastic p 0 0 5 1 1 1 0 0\n!cat '" << path.string() << "'\n";
    }
    const std::string message = testing::ErrorMessage([&] {
        std::ifstream in(path);
        ReadSceneObjects(in, "self.rad", {}, {});
    });
    // Reported at the outermost command line, not along the 32-deep chain.
    EXPECT_EQ(message.rfind("self.rad:2: commands nested more than 32 deep", 0), 0u) << message;
    std::filesystem::remove(path);
}

TEST(SceneParser, EmptyInputWarns) {
    std::vector<std::string> warnings;
    EXPECT_TRUE(ParseText("# only a comment\n", &warnings, "e.rad").empty());
    EXPECT_EQ(warnings, std::vector<std::string>{"(e.rad): empty file"});
}

TEST(SceneWords, ShellAndMessageQuoting) {
    EXPECT_EQ(ShellQuote("it's"), "'it'\\''s'");
    EXPECT_EQ(PrintableWord(std::string("a\0b", 3)), "a\\x00b");
}

}  // namespace
}  // namespace rt
