// SPDX-License-Identifier: MIT
//
// The octree reader (scene/octree.h) on octrees made by real Radiance's oconv
// (tests/data/octree/, make_octrees.sh there): header, cube, scene file names,
// a frozen scene's objects, and every kind of damage giving a one-line error
// with the byte offset instead of a crash or a hang.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <sstream>

#include "core/error.h"
#include "scene/loader.h"
#include "scene/object_types.h"
#include "scene/octree.h"
#include "scene/reader.h"

namespace rt {
namespace {

const std::string kData = RT_SOURCE_DIR "/tests/data/octree/";

std::string Bytes(const std::string& file) {
    std::ifstream in(kData + file, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

OctreeFile Read(const std::string& bytes, const std::string& name = "test.oct") {
    std::istringstream in(bytes);
    return ReadOctree(in, name);
}

/// The error ReadOctree gives for `bytes`, or "" if it reads them.
std::string ErrorOf(const std::string& bytes) {
    try {
        Read(bytes);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

/// Offset of the first byte after the header's blank line.
std::size_t BinaryStart(const std::string& bytes) { return bytes.find("\n\n") + 2; }

TEST(Octree, NamedScene) {
    const std::string bytes = Bytes("cornell.oct");
    std::istringstream probe(bytes);
    EXPECT_TRUE(LooksLikeOctree(probe));
    EXPECT_EQ(probe.tellg(), 0);
    const OctreeFile o = Read(bytes);
    EXPECT_FALSE(o.frozen());
    ASSERT_EQ(o.headerLines.size(), 1u);
    EXPECT_EQ(o.headerLines[0], "oconv ../../../scenes/cornell/cornell.rad");
    ASSERT_EQ(o.sceneFiles.size(), 1u);
    EXPECT_EQ(o.sceneFiles[0], "../../../scenes/cornell/cornell.rad");
    EXPECT_GT(o.objectCount, 0);
    EXPECT_FALSE(o.leafObjects.empty());
    EXPECT_LT(o.leafObjects.back(), o.objectCount);
    // oconv's cube: the scene's bounds grown by 1e-5, origin printed with %.12g.
    EXPECT_GT(o.cubeSize, 0);
}

TEST(Octree, FrozenSceneHasTheObjectsOfTheNamedOne) {
    const OctreeFile named = Read(Bytes("cornell.oct"));
    const OctreeFile frozen = Read(Bytes("cornell_frozen.oct"));
    EXPECT_TRUE(frozen.frozen());
    EXPECT_EQ(frozen.objectCount, named.objectCount);
    ASSERT_EQ(static_cast<long long>(frozen.objects.size()), frozen.objectCount);
    EXPECT_EQ(frozen.cubeSize, named.cubeSize);
    EXPECT_EQ(frozen.leafObjects, named.leafObjects);
    // The first objects of cornell.rad: the material "white", then surfaces it modifies.
    EXPECT_EQ(frozen.objects[0].type, "plastic");
    EXPECT_EQ(frozen.objects[0].name, "white");
    EXPECT_EQ(frozen.objects[0].modifier, "void");
    ASSERT_EQ(frozen.objects[0].rargs.size(), 5u);
    // 5-byte reals: 0.73 within the format's 2^-31 relative resolution.
    EXPECT_NEAR(frozen.objects[0].rargs[0], 0.73, 1e-9);
    EXPECT_GE(frozen.objects[0].loc.byteOffset, 0);
    // Every object as the scene file has it: modifiers (stored as indices)
    // named right, arguments within the 5-byte reals' resolution.
    std::ifstream text(RT_SOURCE_DIR "/scenes/cornell/cornell.rad");
    const std::vector<SceneObject> source = ReadSceneObjects(text, "cornell.rad", {}, nullptr);
    ASSERT_EQ(source.size(), frozen.objects.size());
    for (std::size_t i = 0; i < source.size(); ++i) {
        EXPECT_EQ(frozen.objects[i].modifier, source[i].modifier) << i;
        EXPECT_EQ(frozen.objects[i].name, source[i].name) << i;
        ASSERT_EQ(frozen.objects[i].rargs.size(), source[i].rargs.size()) << i;
        for (std::size_t k = 0; k < source[i].rargs.size(); ++k) {
            EXPECT_NEAR(frozen.objects[i].rargs[k], source[i].rargs[k], 1e-8) << i;
        }
    }
}

TEST(Octree, LeavesListEverySurfaceOnce) {
    // oconv puts every surface inside the cube in some leaf, and nothing
    // else; the reader lists each listed object once, ascending.
    const OctreeFile frozen = Read(Bytes("cornell_frozen.oct"));
    std::vector<long long> surfaces;
    for (std::size_t i = 0; i < frozen.objects.size(); ++i) {
        if (IsSurfaceObjectType(frozen.objects[i].type)) surfaces.push_back(static_cast<long long>(i));
    }
    ASSERT_GT(surfaces.size(), 10u);
    EXPECT_EQ(frozen.leafObjects, surfaces);
}

TEST(Octree, StreamedObjectsAreTheKeptOnes) {
    const std::string bytes = Bytes("cornell_frozen.oct");
    const OctreeFile kept = Read(bytes);
    std::vector<SceneObject> streamed;
    std::istringstream in(bytes);
    const OctreeFile rest = ReadOctree(in, "test.oct", false,
                                       [&streamed](SceneObject& o) { streamed.push_back(o); });
    EXPECT_TRUE(rest.objects.empty());
    EXPECT_EQ(rest.leafObjects, kept.leafObjects);
    ASSERT_EQ(streamed.size(), kept.objects.size());
    for (std::size_t i = 0; i < streamed.size(); ++i) {
        EXPECT_EQ(streamed[i].type, kept.objects[i].type) << i;
        EXPECT_EQ(streamed[i].modifier, kept.objects[i].modifier) << i;
        EXPECT_EQ(streamed[i].name, kept.objects[i].name) << i;
        EXPECT_EQ(streamed[i].sargs, kept.objects[i].sargs) << i;
        EXPECT_EQ(streamed[i].rargs, kept.objects[i].rargs) << i;
        EXPECT_EQ(streamed[i].loc.byteOffset, kept.objects[i].loc.byteOffset) << i;
    }
}

/// Offset of a frozen octree's object count, and its object size (bytes).
std::size_t CountOffset(const std::string& bytes, int& objsize) {
    std::size_t at = BinaryStart(bytes);
    objsize = ((static_cast<std::uint8_t>(bytes[at]) << 8) |
               static_cast<std::uint8_t>(bytes[at + 1])) - 283;
    at += 2;
    for (int nul = 0; nul < 5; ++at) nul += bytes[at] == '\0';  // cube, empty file list
    return at;
}

/// `bytes` (an octree) with its tree's first leaf entry naming object `index`.
std::string WithFirstLeafNaming(std::string bytes, std::uint8_t index) {
    int objsize = 0;
    std::size_t at = CountOffset(bytes, objsize) + static_cast<std::size_t>(objsize);
    // Pre-order: interior (2) and empty (0) node bytes up to the first leaf.
    while (bytes[at] == 0 || bytes[at] == 2) ++at;
    EXPECT_EQ(bytes[at], 1);
    at += 1 + static_cast<std::size_t>(objsize);  // its type and size
    for (int k = 0; k < objsize; ++k) bytes[at + static_cast<std::size_t>(k)] = 0;
    bytes[at + static_cast<std::size_t>(objsize) - 1] = static_cast<char>(index);
    return bytes;
}

TEST(Octree, HugeClaimedObjectCountIsAnError) {
    // Lists are sized from the count before the objects arrive; a file that
    // claims 2^30 of them (22 in truth) must fail on the count, reserving only
    // a bounded amount, whether its objects are kept or streamed.
    std::string bytes = Bytes("cornell_frozen.oct");
    int objsize = 0;
    const std::size_t at = CountOffset(bytes, objsize);
    ASSERT_EQ(objsize, 4);
    bytes.replace(at, 4, std::string("\x40\0\0\0", 4));
    const std::string expected = "the octree holds 22 objects, its count says 1073741824";
    const std::string kept = ErrorOf(bytes);
    EXPECT_NE(kept.find(expected), std::string::npos) << kept;
    // As rtrace reads it (LoadScene streams a frozen octree's objects).
    const std::string path = ::testing::TempDir() + "huge_count.oct";
    std::ofstream(path, std::ios::binary) << bytes;
    try {
        LoadScene({path}, SceneLoadOptions{}, nullptr);
        FAIL() << "accepted a count of 2^30";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
}

TEST(Octree, FrozenLeafNamingAMaterialIsStale) {
    // Object 0 of cornell.rad is the material "white"; a leaf that names it
    // is Radiance's "modifier in tree", however the objects are read.
    const std::string bad = WithFirstLeafNaming(Bytes("cornell_frozen.oct"), 0);
    const std::string expected = "test.oct: modifier in tree; octree stale? (object 0, \"white\")";
    try {
        std::istringstream in(bad);
        SceneAssembler assembler(nullptr);
        ReadOctree(in, "test.oct", false, [&assembler](SceneObject& o) { assembler.Add(o); });
        FAIL() << "accepted a leaf naming a material";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()), expected);
    }
    OctreeFile kept = Read(bad);
    try {
        CheckOctreeObjects(kept, kept.objects, "test.oct");
        FAIL() << "accepted a leaf naming a material";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()), expected);
    }
    // The untouched file passes both ways.
    const std::string good = WithFirstLeafNaming(Bytes("cornell_frozen.oct"), 4);
    std::istringstream in(good);
    SceneAssembler assembler(nullptr);
    EXPECT_NO_THROW(
        ReadOctree(in, "test.oct", false, [&assembler](SceneObject& o) { assembler.Add(o); }));
}

TEST(Octree, ForcedCubeIsTheScenesCube) {
    // oconv -b -10 -10 -10 40 (which, like every cube, oconv grows by 1e-5
    // on each side): -ar and every other use of the cube follow it.
    const Scene s = LoadScene({kData + "cornell_cube40.oct"}, SceneLoadOptions{}, nullptr);
    EXPECT_EQ(s.cubeSize, 40.00002);
    EXPECT_EQ(s.cubeOrigin, Vec3(-10.00001, -10.00001, -10.00001));
    ASSERT_EQ(s.headerLines.size(), 1u);
    EXPECT_EQ(s.headerLines[0], "oconv -f -b -10 -10 -10 40 ../../../scenes/cornell/cornell.rad");
}

TEST(Octree, OconvIncrementalKeepsBothHeadersAndFiles) {
    const OctreeFile o = Read(Bytes("cornell_plus_lamp.oct"));
    ASSERT_EQ(o.headerLines.size(), 2u);
    EXPECT_EQ(o.headerLines[1], "oconv -i cornell.oct lamp.rad");
    ASSERT_EQ(o.sceneFiles.size(), 2u);
    EXPECT_EQ(o.sceneFiles[1], "lamp.rad");
}

TEST(Octree, EveryTruncationIsAnErrorWithAByteOffset) {
    for (const char* file : {"cornell.oct", "cornell_frozen.oct"}) {
        const std::string bytes = Bytes(file);
        for (std::size_t n = 0; n < bytes.size(); ++n) {
            const std::string e = ErrorOf(bytes.substr(0, n));
            ASSERT_FALSE(e.empty()) << file << " cut to " << n << " bytes was read";
            EXPECT_NE(e.find("test.oct"), std::string::npos) << e;
            if (n >= BinaryStart(bytes)) {
                EXPECT_NE(e.find(": byte "), std::string::npos) << n << ": " << e;
                EXPECT_NE(e.find("truncated"), std::string::npos) << n << ": " << e;
            }
        }
        EXPECT_EQ(ErrorOf(bytes), "");
    }
}

TEST(Octree, DamageIsNamedWithItsOffset) {
    const std::string good = Bytes("cornell_frozen.oct");
    const std::size_t bin = BinaryStart(good);
    std::string bad = good;
    bad[bin + 1] = 0x30;  // magic 0x0130 = 283 + 21: no such object size
    EXPECT_EQ(ErrorOf(bad), "test.oct: byte " + std::to_string(bin) + ": bad octree magic number 304");
    EXPECT_NE(ErrorOf("#?RADIANCE\nFORMAT=Radiance_picture\n\n").find("not a Radiance octree"),
              std::string::npos);
    EXPECT_NE(ErrorOf("not even a header").find("not a Radiance octree"), std::string::npos);
    // A node type other than 0, 1, 2 right after the object count.
    const OctreeFile o = Read(good);
    std::string node = good;
    // The tree starts after the cube strings, the empty file list and the 4-byte count.
    std::size_t at = bin + 2;
    for (int k = 0; k < 4; ++k) at = node.find('\0', at) + 1;
    at += 1 + 4;  // the empty file list's NUL, then the object count
    node[at] = 7;
    EXPECT_EQ(ErrorOf(node), "test.oct: byte " + std::to_string(at) + ": bad octree node type");
    EXPECT_GT(o.objectCount, 0);
}

TEST(Octree, OctreeMustBeTheOnlySceneArgument) {
    try {
        LoadScene({kData + "cornell_frozen.oct", kData + "lamp.rad"}, SceneLoadOptions{}, nullptr);
        FAIL() << "loaded an octree with another scene file";
    } catch (const Error& e) {
        // The name as messages show it: a checkout's long path is cut at 60
        // characters (PrintableWord), so the expectation is built the same way.
        EXPECT_EQ(std::string(e.what()),
                  "command line error at '" + PrintableWord(kData + "cornell_frozen.oct") + "'");
        EXPECT_EQ(e.ExitCode(), 1);
    }
    // Radiance names the first argument after the options, whatever it is:
    // `rtrace -u 1 scene.oct` (-u takes no value) is an error at '1'.
    for (const std::string& first : {std::string("1"), kData + "lamp.rad"}) {
        try {
            LoadScene({first, kData + "cornell_frozen.oct"}, SceneLoadOptions{}, nullptr);
            FAIL() << "loaded an octree after " << first;
        } catch (const Error& e) {
            EXPECT_EQ(std::string(e.what()), "command line error at '" + PrintableWord(first) + "'");
        }
    }
    // A !command argument must print an octree.
    try {
        LoadScene({"!echo void plastic p 0 0 5 1 1 1 0 0"}, SceneLoadOptions{}, nullptr);
        FAIL() << "took a command's scene text as an octree";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()),
                  "the output of \"!echo void plastic p 0 0 5 1 1 1 0 0\" is not an octree");
    }
}

TEST(Octree, StaleObjectCount) {
    OctreeFile o = Read(Bytes("cornell.oct"));
    std::vector<SceneObject> objects(static_cast<std::size_t>(o.objectCount) + 1);
    try {
        CheckOctreeObjects(o, objects, "cornell.oct");
        FAIL() << "accepted a stale octree";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("bad object count; octree stale?"), std::string::npos);
    }
    // Same count, but a leaf names a material: "modifier in tree".
    objects.pop_back();
    for (auto& obj : objects) obj.type = "polygon";
    objects[static_cast<std::size_t>(o.leafObjects.front())].type = "plastic";
    EXPECT_THROW(CheckOctreeObjects(o, objects, "cornell.oct"), Error);
}

}  // namespace
}  // namespace rt
