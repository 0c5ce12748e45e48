// SPDX-License-Identifier: MIT
//
// Replays every file of tests/fuzz/corpus/<target>/ and tests/fuzz/regressions/<target>/
// through the fuzz targets' entry functions, so the normal (and sanitizer) builds
// re-check the corpus and every crash the fuzzers found. A finding aborts or fails.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "core/error.h"
#include "scene/loader.h"

extern "C" int FuzzSceneEntry(const std::uint8_t* data, std::size_t size);
extern "C" int FuzzRaysEntry(const std::uint8_t* data, std::size_t size);
extern "C" int FuzzAmbfileEntry(const std::uint8_t* data, std::size_t size);
extern "C" int FuzzCalEntry(const std::uint8_t* data, std::size_t size);
extern "C" int FuzzOctreeEntry(const std::uint8_t* data, std::size_t size);
extern "C" int FuzzMeshEntry(const std::uint8_t* data, std::size_t size);
extern "C" int FuzzDatafileEntry(const std::uint8_t* data, std::size_t size);
extern "C" int FuzzBsdfEntry(const std::uint8_t* data, std::size_t size);
extern "C" int FuzzFontEntry(const std::uint8_t* data, std::size_t size);
extern "C" int FuzzPictureEntry(const std::uint8_t* data, std::size_t size);
extern "C" int FuzzViewEntry(const std::uint8_t* data, std::size_t size);
extern "C" int FuzzOptionsEntry(const std::uint8_t* data, std::size_t size);
extern "C" int FuzzExrEntry(const std::uint8_t* data, std::size_t size);
extern "C" int FuzzRvimageEntry(const std::uint8_t* data, std::size_t size);

namespace {

namespace fs = std::filesystem;
using Entry = int (*)(const std::uint8_t*, std::size_t);

std::vector<fs::path> InputFiles(const std::string& target) {
    std::vector<fs::path> files;
    for (const char* kind : {"corpus", "regressions"}) {
        const fs::path dir = fs::path(RT_SOURCE_DIR) / "tests" / "fuzz" / kind / target;
        if (!fs::is_directory(dir)) continue;
        for (const fs::directory_entry& entry : fs::directory_iterator(dir)) {
            const std::string name = entry.path().filename().string();
            if (entry.is_regular_file() && !name.starts_with(".") && name != "README.md") {
                files.push_back(entry.path());
            }
        }
    }
    std::sort(files.begin(), files.end());
    return files;
}

std::size_t Replay(const std::string& target, Entry entry) {
    const std::vector<fs::path> files = InputFiles(target);
    for (const fs::path& file : files) {
        SCOPED_TRACE(file.string());
        std::ifstream in(file, std::ios::binary);
        EXPECT_TRUE(in.good());
        const std::vector<char> bytes{std::istreambuf_iterator<char>(in),
                                      std::istreambuf_iterator<char>()};
        const std::uint8_t* data =
            bytes.empty() ? nullptr : reinterpret_cast<const std::uint8_t*>(bytes.data());
        EXPECT_EQ(entry(data, bytes.size()), 0);
    }
    return files.size();
}

TEST(FuzzRegression, SceneCorpusAndRegressions) {
    EXPECT_GT(Replay("scene", &FuzzSceneEntry), 0u);
}

TEST(FuzzRegression, RaysCorpusAndRegressions) {
    EXPECT_GT(Replay("rays", &FuzzRaysEntry), 0u);
}

TEST(FuzzRegression, AmbfileCorpusAndRegressions) {
    EXPECT_GT(Replay("ambfile", &FuzzAmbfileEntry), 0u);
}

TEST(FuzzRegression, CalCorpusAndRegressions) {
    EXPECT_GT(Replay("cal", &FuzzCalEntry), 0u);
}

TEST(FuzzRegression, OctreeCorpusAndRegressions) {
    EXPECT_GT(Replay("octree", &FuzzOctreeEntry), 0u);
}

TEST(FuzzRegression, MeshCorpusAndRegressions) {
    EXPECT_GT(Replay("mesh", &FuzzMeshEntry), 0u);
}

TEST(FuzzRegression, DatafileCorpusAndRegressions) {
    EXPECT_GT(Replay("datafile", &FuzzDatafileEntry), 0u);
}

TEST(FuzzRegression, BsdfCorpusAndRegressions) {
    EXPECT_GT(Replay("bsdf", &FuzzBsdfEntry), 0u);
}

TEST(FuzzRegression, FontCorpusAndRegressions) {
    EXPECT_GT(Replay("font", &FuzzFontEntry), 0u);
}

TEST(FuzzRegression, PictureCorpusAndRegressions) {
    EXPECT_GT(Replay("picture", &FuzzPictureEntry), 0u);
}

TEST(FuzzRegression, ViewCorpusAndRegressions) {
    EXPECT_GT(Replay("view", &FuzzViewEntry), 0u);
}

TEST(FuzzRegression, OptionsCorpusAndRegressions) {
    EXPECT_GT(Replay("options", &FuzzOptionsEntry), 0u);
}

TEST(FuzzRegression, ExrCorpusAndRegressions) {
    EXPECT_GT(Replay("exr", &FuzzExrEntry), 0u);
}

TEST(FuzzRegression, RvimageCorpusAndRegressions) {
    EXPECT_GT(Replay("rvimage", &FuzzRvimageEntry), 0u);
}

// The scene fuzzer relies on SceneLoadOptions::runCommands = false never running a
// command: the line is an error naming it, and the command leaves no trace.
TEST(FuzzRegression, SceneCommandsCanBeDisabled) {
    const std::string marker =
        (fs::temp_directory_path() / ("lazyrad_fuzz_cmd_" + std::to_string(getpid()))).string();
    fs::remove(marker);
    std::istringstream in("void plastic red\n0\n0\n5 1 0 0 0 0\n!touch " + marker + "\n");
    rt::SceneLoadOptions options;
    options.runCommands = false;
    try {
        rt::ReadSceneObjects(in, "cmd.rad", options, rt::WarningSink{});
        FAIL() << "expected rt::Error";
    } catch (const rt::Error& e) {
        EXPECT_NE(std::string(e.what()).find("cmd.rad:5: commands disabled: !touch"),
                  std::string::npos)
            << e.what();
    }
    EXPECT_FALSE(fs::exists(marker));
}

}  // namespace
