// SPDX-License-Identifier: MIT
//
// Finding function files (radiance-functions.md §9.12): RAYPATH order, the
// current directory only when listed, names used as given, lazyrad's
// built-in files last, context names, and loading each context once.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "cal/builtin_files.h"
#include "tests/cal/cal_test_util.h"

namespace rt::cal {
namespace {

namespace fs = std::filesystem;
using testing::ErrorOf;

class CalSearch : public ::testing::Test {
  protected:
    void SetUp() override {
        root_ = fs::temp_directory_path() / ("lazyrad_cal_search_" + std::to_string(getpid()));
        fs::create_directories(root_ / "one");
        fs::create_directories(root_ / "two");
        Write("one/a.cal", "v = 1;");
        Write("two/a.cal", "v = 2;");
        Write("two/b.cal", "v = 3;");
        Write("two/rayinit.cal", "PI : 3;");
        previous_ = fs::current_path();
        fs::current_path(root_);
    }
    void TearDown() override {
        fs::current_path(previous_);
        fs::remove_all(root_);
    }
    void Write(const std::string& name, const std::string& text) {
        std::ofstream(root_ / name) << text;
    }
    double Value(Program& program, const std::string& ctx) {
        Context context(program);
        context.NextEvaluation();
        return program.Evaluate(*program.FindVariable("v", ctx), context);
    }
    fs::path root_, previous_;
};

TEST_F(CalSearch, RaypathOrder) {
    const SearchPath path = SearchPath::FromRaypath("one:two");
    ASSERT_EQ(path.entries, (std::vector<std::string>{"one", "two"}));
    EXPECT_EQ(FindFunctionFile("a.cal", path)->text, "v = 1;");
    EXPECT_EQ(FindFunctionFile("a.cal", path)->name, "one/a.cal");
    EXPECT_EQ(FindFunctionFile("a.cal", SearchPath::FromRaypath("two:one"))->text, "v = 2;");
    EXPECT_EQ(FindFunctionFile("b.cal", path)->text, "v = 3;");
    EXPECT_FALSE(FindFunctionFile("c.cal", path).has_value());
}

TEST_F(CalSearch, CurrentDirectoryOnlyWhenListed) {
    Write("here.cal", "v = 4;");
    EXPECT_FALSE(FindFunctionFile("here.cal", SearchPath::FromRaypath("one:two")).has_value());
    EXPECT_TRUE(FindFunctionFile("here.cal", SearchPath::FromRaypath(".:one")).has_value());
    EXPECT_TRUE(FindFunctionFile("here.cal", SearchPath::FromRaypath("one::two")).has_value());
    // Radiance's default when RAYPATH is unset starts with the current directory.
    const SearchPath defaults = SearchPath::FromRaypath(":/usr/local/lib/ray");
    EXPECT_EQ(defaults.entries, (std::vector<std::string>{"", "/usr/local/lib/ray"}));
    EXPECT_TRUE(FindFunctionFile("here.cal", defaults).has_value());
    // Names starting with '.' or '/' are not searched.
    EXPECT_TRUE(FindFunctionFile("./here.cal", SearchPath::FromRaypath("one")).has_value());
    EXPECT_FALSE(FindFunctionFile("./b.cal", SearchPath::FromRaypath("two")).has_value());
    const std::string absolute = (root_ / "two" / "b.cal").string();
    EXPECT_EQ(FindFunctionFile(absolute, SearchPath::FromRaypath("one"))->text, "v = 3;");
}

TEST_F(CalSearch, BuiltinsComeLastAndFallbackDirectoriesBeforeThem) {
    SearchPath path = SearchPath::FromRaypath("one");
    const std::optional<SourceText> builtin = FindFunctionFile("rayinit.cal", path);
    ASSERT_TRUE(builtin.has_value());
    EXPECT_EQ(builtin->name, "rayinit.cal");
    EXPECT_EQ(builtin->text, *FindBuiltinFile("rayinit.cal"));
    path.fallbackDirs = {"two"};
    EXPECT_EQ(FindFunctionFile("rayinit.cal", path)->text, "PI : 3;");
    EXPECT_EQ(FindFunctionFile("rayinit.cal", SearchPath::FromRaypath("two"))->text, "PI : 3;");
    path.fallbackDirs.clear();
    path.builtins = false;
    EXPECT_FALSE(FindFunctionFile("rayinit.cal", path).has_value());
}

TEST_F(CalSearch, ContextNames) {
    EXPECT_EQ(ContextNameForFile("skybright.cal"), "skybright");
    EXPECT_EQ(ContextNameForFile("dir/x.cal"), "dir_x");
    EXPECT_EQ(ContextNameForFile("./a.cal"), "._a");
    EXPECT_EQ(ContextNameForFile(".cal"), ".cal");
    EXPECT_EQ(ContextNameForFile("my-sky.v2.cal"), "my_sky.v2");
    EXPECT_EQ(ContextNameForFile("a`b.cal"), "a_b");
}

TEST_F(CalSearch, EachContextLoadsOnce) {
    Program program;
    const SearchPath path = SearchPath::FromRaypath("one:two");
    EXPECT_EQ(program.LoadFile("a.cal", path), "a");
    EXPECT_EQ(program.LoadFile("b.cal", path), "b");
    EXPECT_EQ(program.LoadFile("a.cal", SearchPath::FromRaypath("two")), "a");  // already loaded
    EXPECT_DOUBLE_EQ(Value(program, "a"), 1.0);
    EXPECT_DOUBLE_EQ(Value(program, "b"), 3.0);
    EXPECT_EQ(program.LoadFile(".", path), "");
    EXPECT_EQ(program.LoadFile("./one/a.cal", path), "._one_a");  // another spelling
}

TEST_F(CalSearch, MissingFileNamesWhoAskedForIt) {
    Program program;
    try {
        program.LoadFile("nosuch.cal", SearchPath::FromRaypath("one:two"), "sky.rad:3:1");
        FAIL() << "expected rt::Error";
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "sky.rad:3:1: cannot find function file \"nosuch.cal\"");
        EXPECT_EQ(e.ExitCode(), 2);  // a system error, as in Radiance
    }
}

TEST_F(CalSearch, ErrorsInAFileNameThePathOpened) {
    Write("two/bad.cal", "v = 1;\nw = 2 +;\n");
    Program program;
    EXPECT_EQ(ErrorOf([&] { program.LoadFile("bad.cal", SearchPath::FromRaypath("one:two")); }),
              "two/bad.cal:2:8: unexpected character");
}

}  // namespace
}  // namespace rt::cal
