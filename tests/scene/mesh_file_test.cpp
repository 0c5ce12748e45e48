// SPDX-License-Identifier: MIT
//
// The mesh-file reader (scene/mesh_file.h) on meshes made by real Radiance's
// obj2mesh (tests/data/mesh/, make_meshes.sh there): radiance-functions.md
// §13.3's worked example byte for byte and value for value, the same faces
// without vt/vn, a mesh without materials, a bumpy sphere of 2160 triangles
// over several patches checked against its OBJ, and damage of every kind
// giving a one-line error with the byte offset.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <tuple>

#include "core/error.h"
#include "scene/mesh_file.h"

namespace rt {
namespace {

const std::string kData = RT_SOURCE_DIR "/tests/data/mesh/";
constexpr double kTwo32 = 4294967296.0;

std::string Bytes(const std::string& file) {
    std::ifstream in(kData + file, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

MeshFile Read(const std::string& bytes) {
    std::istringstream in(bytes);
    return ReadMesh(in, "test.rtm");
}

/// The error ReadMesh gives for `bytes`, or "" if it reads them.
std::string ErrorOf(const std::string& bytes) {
    try {
        Read(bytes);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

std::string At(std::size_t offset, const std::string& what) {
    return "test.rtm: byte " + std::to_string(offset) + ": " + what;
}

/// Offset of the first byte after the header's blank line.
std::size_t BinaryStart(const std::string& bytes) { return bytes.find("\n\n") + 2; }

std::string Hex(const std::string& hex) {
    std::string out;
    std::istringstream in(hex);
    for (std::string b; in >> b;) out.push_back(static_cast<char>(std::stoi(b, nullptr, 16)));
    return out;
}

std::string Z(const char* s) { return std::string(s) + '\0'; }

// tri.rtm's layout (radiance-functions.md §13.3), as offsets from its end.
constexpr std::size_t kLocalCountFromEnd = 18;  // 00 02, then 00 01 02, 03 00 02
constexpr std::size_t kMaterialsFromEnd = 8;    // 00 02 (blue), 00 01 (red)
constexpr std::size_t kJoinersFromEnd = 4;      // 00 00 single, 00 00 double

TEST(MeshFile, WorkedExampleBytesAreTheSpecs) {
    const std::string bytes = Bytes("tri.rtm");
    const std::size_t bin = BinaryStart(bytes);
    EXPECT_EQ(bytes.substr(0, bin),
              "#?RADIANCE\nobj2mesh -a mats.rad tri.obj\nFORMAT=Radiance_tmesh\n\n");
    // The spec's 788 bytes have a header whose command line is longer (the
    // program's path); everything after the header is the same 706 bytes.
    ASSERT_EQ(bytes.size() - bin, 706u);
    const std::string head =
        Hex("01 43") + Z("-1.00000000001e-05") + Z("-1.00000000001e-05") + Z("-0.25001") +
        Z("1.00002") +
        Hex("bd e7 21 0d f2  40 00 84 31 01  bd e7 21 0d f2  40 00 84 31 01") +
        Hex("01 00 00 00 02 00 00 00 00 00 00 00 01");
    EXPECT_EQ(bytes.substr(bin, head.size()), head);
    // 53 type names, "polygon" to "ashik2", then the empty string.
    std::size_t at = bin + head.size();
    std::vector<std::string> types;
    while (bytes[at] != '\0') {
        const std::size_t end = bytes.find('\0', at);
        types.push_back(bytes.substr(at, end - at));
        at = end + 1;
    }
    ++at;
    ASSERT_EQ(types.size(), 53u);
    EXPECT_EQ(types.front(), "polygon");
    EXPECT_EQ(types.back(), "ashik2");
    const std::string one = Hex("3f ff ff ff 01");
    const std::string tail =
        Hex("29 ff ff ff ff") + Z("uvf") + Hex("00 04") + Z("Lu") + Z("Lv") + Z("0") + Z(".") +
        Hex("00 00") + Hex("1d 00 00 00 00") + Z("red") + Hex("00 00 00 03") + one + one + one +
        Hex("1d ff ff ff ff") + Z("blue") + Hex("00 00 00 03 00 00 00 00 00 00 00 00 00 00") +
        one + Hex("ff") + Hex("00 00 00 01") + Hex("07 00 04") +
        Hex("ff ff 58 3b 00 00 a7 c4 40 00 53 e2") + Hex("ff ff 58 3b ff ff 58 3b bf ff ac 1d") +
        Hex("00 00 a7 c4 ff ff 58 3b 40 00 53 e2") + Hex("00 00 a7 c4 00 00 a7 c4 40 00 53 e2") +
        Hex("6c 9c 00 00  00 00 00 08  6c 9c 00 08  00 00 00 08") +
        Hex("ff fd ef 41 00 02 10 be  ff fd ef 41 ff fd ef 41") +
        Hex("00 02 10 be ff fd ef 41  00 02 10 be 00 02 10 be") +
        Hex("00 02  00 01 02  03 00 02") + Hex("00 02  00 02 00 01") + Hex("00 00  00 00");
    EXPECT_EQ(bytes.substr(at), tail);
}

/// Within the quantisation of a mesh coordinate: half a step of size/2^32,
/// plus what the double arithmetic adds.
void ExpectQuantised(const Vec3& got, const Vec3& want, double cubeSize) {
    const double step = cubeSize / kTwo32;
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(got[i], want[i], 0.5 * step + 1e-15) << i;
}

// dircode.c: maximum angular error 0.0058° ≈ 1.0e-4 rad.
constexpr double kNormalTolerance = 1.1e-4;

void ExpectNormal(const Vec3& got, const Vec3& want) {
    EXPECT_NEAR(Length(got), 1.0, 1e-12);
    EXPECT_LT(Length(got - Normalize(want)), kNormalTolerance) << got << " vs " << want;
}

TEST(MeshFile, WorkedExampleValues) {
    const std::string bytes = Bytes("tri.rtm");
    std::istringstream probe(bytes);
    EXPECT_TRUE(LooksLikeMesh(probe));
    EXPECT_EQ(probe.tellg(), 0);
    const MeshFile m = Read(bytes);
    EXPECT_EQ(m.headerLines, std::vector<std::string>{"obj2mesh -a mats.rad tri.obj"});
    EXPECT_EQ(m.cubeOrigin.x, -1.00000000001e-05);
    EXPECT_EQ(m.cubeOrigin.y, -1.00000000001e-05);
    EXPECT_EQ(m.cubeOrigin.z, -0.25001);
    EXPECT_EQ(m.cubeSize, 1.00002);
    // obj2mesh widens the (u,v) range [0,1] by 2/65536 of itself + 1e-6.
    const double widen = 2.0 / 65536 + 1e-6;
    EXPECT_NEAR(m.uMin, -widen, 1e-7);
    EXPECT_NEAR(m.uMax, 1 + widen, 1e-7);
    EXPECT_NEAR(m.vMin, -widen, 1e-7);
    EXPECT_NEAR(m.vMax, 1 + widen, 1e-7);

    ASSERT_EQ(m.materials.size(), 3u);
    EXPECT_EQ(m.materials[0].type, "colorfunc");
    EXPECT_EQ(m.materials[0].name, "uvf");
    EXPECT_EQ(m.materials[0].modifier, "void");
    EXPECT_EQ(m.materials[0].sargs, (std::vector<std::string>{"Lu", "Lv", "0", "."}));
    EXPECT_TRUE(m.materials[0].rargs.empty());
    EXPECT_EQ(m.materials[0].loc.byteOffset, static_cast<long long>(bytes.find("\x29\xff\xff\xff\xff")));
    EXPECT_EQ(m.materials[1].type, "light");
    EXPECT_EQ(m.materials[1].name, "red");
    EXPECT_EQ(m.materials[1].modifier, "uvf");
    ASSERT_EQ(m.materials[1].rargs.size(), 3u);
    for (double c : m.materials[1].rargs) EXPECT_NEAR(c, 1.0, 1e-9);
    EXPECT_EQ(m.materials[2].name, "blue");
    EXPECT_EQ(m.materials[2].modifier, "void");
    EXPECT_EQ(m.materials[2].rargs, (std::vector<double>{0, 0, m.materials[2].rargs[2]}));
    EXPECT_NEAR(m.materials[2].rargs[2], 1.0, 1e-9);

    // Vertex order as obj2mesh assigned it (§13.3): (1,0,0) (1,1,.5) (0,1,0) (0,0,0).
    const Vec3 want[4] = {{1, 0, 0}, {1, 1, 0.5}, {0, 1, 0}, {0, 0, 0}};
    ASSERT_EQ(m.vertices.size(), 4u);
    for (int i = 0; i < 4; ++i) ExpectQuantised(m.vertices[i], want[i], m.cubeSize);
    ASSERT_EQ(m.normals.size(), 4u);
    ExpectNormal(m.normals[0], {0.6, 0, 0.8});
    ExpectNormal(m.normals[1], {0, 0, 1});
    ExpectNormal(m.normals[2], {0, 0.6, 0.8});
    ExpectNormal(m.normals[3], {0, 0, 1});
    ASSERT_EQ(m.uvs.size(), 4u);
    ASSERT_EQ(m.hasUv, (std::vector<std::uint8_t>{1, 1, 1, 1}));
    const double uvStep = (m.uMax - m.uMin) / kTwo32;
    const double wantUv[4][2] = {{1, 0}, {1, 1}, {0, 1}, {0, 0}};
    for (int i = 0; i < 4; ++i) {
        EXPECT_NEAR(m.uvs[i][0], wantUv[i][0], uvStep) << i;
        EXPECT_NEAR(m.uvs[i][1], wantUv[i][1], uvStep) << i;
    }
    // OBJ face 2 (blue) came first: f 2 4 3, then f 1 2 3 (red).
    ASSERT_EQ(m.triangles.size(), 2u);
    EXPECT_EQ(m.triangles[0].v, (std::array<int, 3>{0, 1, 2}));
    EXPECT_EQ(m.materials[m.triangles[0].material].name, "blue");
    EXPECT_EQ(m.triangles[1].v, (std::array<int, 3>{3, 0, 2}));
    EXPECT_EQ(m.materials[m.triangles[1].material].name, "red");
}

/// Radiance's interpolated normal at `p` on triangle `t` (o_mesh.c: Σ wᵢ nᵢ, normalised).
Vec3 ShadingNormal(const MeshFile& m, const MeshFile::Triangle& t, const Vec3& p) {
    const auto w = BarycentricWeights(m.vertices[t.v[0]], m.vertices[t.v[1]], m.vertices[t.v[2]], p);
    EXPECT_TRUE(w.has_value());
    if (!w) return {};
    Vec3 n;
    for (int i = 0; i < 3; ++i) n = n + (*w)[i] * m.normals[t.v[i]];
    return Normalize(n);
}

TEST(MeshFile, InterpolatedNormalsAreRadiances) {
    // radiance-functions.md §13.6 item 5: rtrace -on on tri.rtm, printed to 7 digits.
    const MeshFile m = Read(Bytes("tri.rtm"));
    const MeshFile::Triangle& blue = m.triangles[0];
    const MeshFile::Triangle& red = m.triangles[1];
    const auto expect = [](const Vec3& got, const Vec3& want) {
        for (int i = 0; i < 3; ++i) EXPECT_NEAR(got[i], want[i], 1e-6) << got;
    };
    expect(ShadingNormal(m, red, {0.25, 0.25, 0}), {0.1622297, 0.1622297, 0.9733258});
    expect(ShadingNormal(m, red, {0.5, 0.2, 0}), {0.3265671, 0.1306269, 0.9361039});
    // The blue triangle's plane is z = (x + y − 1)/2: the hit at distance 1.775.
    expect(ShadingNormal(m, blue, {0.75, 0.7, 0.225}), {0.195593, 0.1629941, 0.9670451});
}

TEST(MeshFile, BarycentricWeights) {
    const Vec3 a{0, 0, 0}, b{2, 0, 1}, c{0, 3, 1};
    const auto at = [&](const Vec3& p) { return *BarycentricWeights(a, b, c, p); };
    const auto wa = at(a), wb = at(b), wc = at(c), wm = at((a + b + c) / 3);
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(wa[i], i == 0 ? 1 : 0, 1e-15);
        EXPECT_NEAR(wb[i], i == 1 ? 1 : 0, 1e-15);
        EXPECT_NEAR(wc[i], i == 2 ? 1 : 0, 1e-15);
        EXPECT_NEAR(wm[i], 1.0 / 3, 1e-15);
    }
    // Off the plane along the dropped axis (z here): the same weights.
    const auto wz = at((a + b + c) / 3 + Vec3{0, 0, 5});
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(wz[i], 1.0 / 3, 1e-15);
    EXPECT_FALSE(BarycentricWeights(a, b, 2 * b, a).has_value());  // collinear
}

TEST(MeshFile, WithoutUvAndNormals) {
    // §13.6 item 6: 48 bytes fewer than tri.rtm after the header, patch flags 01.
    const std::string bytes = Bytes("tri_flat.rtm");
    ASSERT_EQ(bytes.size() - BinaryStart(bytes), 706u - 48u);
    const std::string patch = Hex("00 00 00 01 01 00 04");
    EXPECT_NE(bytes.find(patch), std::string::npos);
    EXPECT_EQ(bytes.substr(bytes.size() - kLocalCountFromEnd),
              Hex("00 02 00 01 02 03 00 02 00 02 00 02 00 01 00 00 00 00"));
    const MeshFile m = Read(bytes);
    EXPECT_EQ(m.uMin, 0);
    EXPECT_EQ(m.uMax, 0);
    EXPECT_EQ(m.vMin, 0);
    EXPECT_EQ(m.vMax, 0);
    EXPECT_TRUE(m.normals.empty());
    EXPECT_TRUE(m.uvs.empty());
    EXPECT_TRUE(m.hasUv.empty());
    const MeshFile full = Read(Bytes("tri.rtm"));
    EXPECT_EQ(m.vertices, full.vertices);
    ASSERT_EQ(m.triangles.size(), 2u);
    for (int k = 0; k < 2; ++k) {
        EXPECT_EQ(m.triangles[k].v, full.triangles[k].v);
        EXPECT_EQ(m.triangles[k].material, full.triangles[k].material);
    }
}

TEST(MeshFile, WithoutMaterialsEveryTriangleIsVoid) {
    const MeshFile m = Read(Bytes("tri_void.rtm"));
    EXPECT_TRUE(m.materials.empty());
    ASSERT_EQ(m.triangles.size(), 2u);
    EXPECT_EQ(m.triangles[0].material, -1);
    EXPECT_EQ(m.triangles[1].material, -1);
}

struct Obj {
    std::vector<Vec3> v, vn;
    std::vector<std::array<double, 2>> vt;
    struct Face {
        std::array<int, 3> v, vt, vn;  // 0-based; -1 where absent
        std::string material;
    };
    std::vector<Face> faces;
};

/// Just what make_bumpy_sphere.py writes: v, vn, vt, usemtl, triangles.
Obj ReadObj(const std::string& file) {
    Obj obj;
    std::ifstream in(kData + file);
    std::string material = "void";
    for (std::string line; std::getline(in, line);) {
        std::istringstream words(line);
        std::string key;
        words >> key;
        if (key == "v" || key == "vn") {
            Vec3 p;
            words >> p.x >> p.y >> p.z;
            (key == "v" ? obj.v : obj.vn).push_back(p);
        } else if (key == "vt") {
            std::array<double, 2> t{};
            words >> t[0] >> t[1];
            obj.vt.push_back(t);
        } else if (key == "usemtl") {
            words >> material;
        } else if (key == "f") {
            Obj::Face f{};
            f.material = material;
            for (int i = 0; i < 3; ++i) {
                std::string ref;
                words >> ref;
                const std::size_t s1 = ref.find('/'), s2 = ref.find('/', s1 + 1);
                f.v[i] = std::stoi(ref.substr(0, s1)) - 1;
                f.vt[i] = s2 > s1 + 1 ? std::stoi(ref.substr(s1 + 1, s2 - s1 - 1)) - 1 : -1;
                f.vn[i] = std::stoi(ref.substr(s2 + 1)) - 1;
            }
            obj.faces.push_back(f);
        }
    }
    return obj;
}

TEST(MeshFile, BumpySphereHasTheObjsTriangles) {
    const Obj obj = ReadObj("bumpy_sphere.obj");
    const MeshFile m = Read(Bytes("bumpy_sphere.rtm"));
    ASSERT_EQ(obj.faces.size(), 2160u);
    ASSERT_EQ(m.triangles.size(), obj.faces.size());
    ASSERT_EQ(m.materials.size(), 4u);  // uvf, red, blue from mats.rad; grey
    // The OBJ prints 5 decimals and every vertex is distinct at that precision,
    // so rounding a decoded vertex to 1e-5 names its OBJ vertex.
    using Key = std::tuple<long long, long long, long long>;
    const auto key = [](const Vec3& p) {
        return Key{std::llround(p.x * 1e5), std::llround(p.y * 1e5), std::llround(p.z * 1e5)};
    };
    std::map<Key, int> objIndex;
    for (int i = 0; i < static_cast<int>(obj.v.size()); ++i) objIndex[key(obj.v[i])] = i;
    ASSERT_EQ(objIndex.size(), obj.v.size());
    ASSERT_GT(m.vertices.size(), 256u * 4);  // several patches
    ASSERT_EQ(m.normals.size(), m.vertices.size());
    ASSERT_EQ(m.uvs.size(), m.vertices.size());
    int withUv = 0, withNormal = 0;
    std::vector<int> objOf(m.vertices.size());
    for (std::size_t i = 0; i < m.vertices.size(); ++i) {
        const auto it = objIndex.find(key(m.vertices[i]));
        ASSERT_NE(it, objIndex.end()) << m.vertices[i];
        objOf[i] = it->second;
        ExpectQuantised(m.vertices[i], obj.v[it->second], m.cubeSize);
        // make_bumpy_sphere.py gives vertex k normal k and (u,v) k.
        if (m.normals[i] != Vec3{}) {
            ++withNormal;
            ExpectNormal(m.normals[i], obj.vn[it->second]);
        }
        if (m.hasUv[i]) {
            ++withUv;
            EXPECT_NEAR(m.uvs[i][0], obj.vt[it->second][0], 1e-9);
            EXPECT_NEAR(m.uvs[i][1], obj.vt[it->second][1], 1e-9);
        }
    }
    EXPECT_GT(withNormal, 0);
    EXPECT_GT(withUv, 0);
    EXPECT_LT(withUv, static_cast<int>(m.vertices.size()));  // the equator bands have none

    // Triangles as a multiset of (vertices rotated to start at the smallest,
    // material): same orientation, same material, nothing lost or doubled.
    using Tri = std::tuple<int, int, int, std::string>;
    const auto canonical = [](std::array<int, 3> v, const std::string& material) {
        std::rotate(v.begin(), std::min_element(v.begin(), v.end()), v.end());
        return Tri{v[0], v[1], v[2], material};
    };
    std::vector<Tri> want, got;
    for (const Obj::Face& f : obj.faces) want.push_back(canonical(f.v, f.material));
    int spanning = 0;
    for (const MeshFile::Triangle& t : m.triangles) {
        ASSERT_GE(t.material, 0);
        got.push_back(canonical({objOf[t.v[0]], objOf[t.v[1]], objOf[t.v[2]]},
                                m.materials[t.material].name));
        // obj2mesh fills each patch to 256 vertices before the next, so a
        // triangle whose vertices lie in different blocks of 256 is a joiner.
        if (t.v[0] / 256 != t.v[1] / 256 || t.v[1] / 256 != t.v[2] / 256) ++spanning;
    }
    std::sort(want.begin(), want.end());
    std::sort(got.begin(), got.end());
    EXPECT_EQ(got, want);
    EXPECT_GT(spanning, 0);
}

TEST(MeshFile, EveryTruncationIsAnErrorWithAByteOffset) {
    for (const char* file : {"tri.rtm", "tri_flat.rtm", "tri_void.rtm"}) {
        const std::string bytes = Bytes(file);
        for (std::size_t n = 0; n < bytes.size(); ++n) {
            const std::string e = ErrorOf(bytes.substr(0, n));
            ASSERT_FALSE(e.empty()) << file << " cut to " << n << " bytes was read";
            EXPECT_NE(e.find("test.rtm"), std::string::npos) << e;
            EXPECT_EQ(e.find('\n'), std::string::npos) << e;
            if (n >= BinaryStart(bytes)) {
                EXPECT_NE(e.find(": byte " + std::to_string(n) + ": truncated mesh file"),
                          std::string::npos)
                    << n << ": " << e;
            }
        }
        EXPECT_EQ(ErrorOf(bytes), "");
    }
}

TEST(MeshFile, DamageIsNamedWithItsOffset) {
    const std::string good = Bytes("tri.rtm");
    const std::size_t bin = BinaryStart(good);
    const std::size_t end = good.size();
    const auto with = [&good](std::size_t at, const std::string& replacement) {
        std::string bad = good;
        bad.replace(at, replacement.size(), replacement);
        return bad;
    };
    EXPECT_EQ(ErrorOf(with(bin + 1, "\x30")), At(bin, "incompatible mesh format (magic number 304)"));
    EXPECT_NE(ErrorOf("not a mesh").find("not a Radiance mesh"), std::string::npos);
    // Cube size 0.
    const std::size_t sizeAt = good.find(Z("1.00002"), bin);
    EXPECT_EQ(ErrorOf(with(sizeAt, Z("0.00000"))), At(sizeAt, "illegal octree bounds in mesh"));

    // The leaf "01 | 00 00 00 02 | 00 00 00 00 | 00 00 00 01" after the (u,v) limits.
    const std::size_t leaf = sizeAt + 8 + 20;
    ASSERT_EQ(good.substr(leaf, 5), Hex("01 00 00 00 02"));
    EXPECT_EQ(ErrorOf(with(leaf, "\x03")), At(leaf, "bad octree node type"));
    EXPECT_EQ(ErrorOf(with(leaf + 9, Hex("00 00 00 02"))),
              At(leaf + 9, "mesh octree leaf names triangle 2, which does not exist"));
    EXPECT_EQ(ErrorOf(with(leaf + 9, Hex("00 00 04 00"))),  // patch 1, local 0
              At(leaf + 9, "mesh octree leaf names triangle 1024, which does not exist"));
    EXPECT_EQ(ErrorOf(with(leaf + 9, Hex("00 00 02 00"))),  // single joiner 0
              At(leaf + 9, "mesh octree leaf names triangle 512, which does not exist"));

    // Material "blue" made a polygon (type index 0): surfaces may not be materials.
    const std::size_t blue = good.find(Hex("1d ff ff ff ff") + "blue");
    EXPECT_EQ(ErrorOf(with(blue, Hex("00"))), At(blue, "non-modifier in mesh (polygon \"blue\")"));
    // "red" modified by a later material.
    const std::size_t red = good.find(Hex("1d 00 00 00 00") + "red");
    EXPECT_EQ(ErrorOf(with(red, Hex("1d 00 00 00 02"))), At(red, "bad modifier index 2"));

    const std::size_t flags = good.find(Hex("ff 00 00 00 01 07 00 04")) + 5;
    EXPECT_EQ(ErrorOf(with(flags, "\x0f")), At(flags, "bad patch flags 15"));
    EXPECT_EQ(ErrorOf(with(flags, "\x06")), At(flags, "bad patch flags 6"));  // no positions
    EXPECT_EQ(ErrorOf(with(flags + 1, Hex("01 01"))), At(flags + 1, "bad number of patch vertices 257"));
    EXPECT_EQ(ErrorOf(with(flags + 1, Hex("00 00"))), At(flags + 1, "bad number of patch vertices 0"));

    const std::size_t local = end - kLocalCountFromEnd;
    EXPECT_EQ(ErrorOf(with(local, Hex("02 01"))), At(local, "bad number of local triangles 513"));
    EXPECT_EQ(ErrorOf(with(local + 2, "\x04")),
              At(local + 2, "bad local triangle index (vertex 4 of 4)"));
    EXPECT_EQ(ErrorOf(with(local + 7, "\xff")),
              At(local + 7, "bad local triangle index (vertex 255 of 4)"));
    const std::size_t mats = end - kMaterialsFromEnd;
    EXPECT_EQ(ErrorOf(with(mats + 2, Hex("00 03"))),
              At(mats + 2, "bad local triangle material (3, 3 materials)"));
    // Void is not allowed among materials: obj2mesh itself refuses to write it.
    EXPECT_EQ(ErrorOf(with(mats, Hex("ff ff"))),
              At(mats, "bad local triangle material (-1, 3 materials)"));
    EXPECT_EQ(ErrorOf(with(end - kJoinersFromEnd, Hex("01 01"))),
              At(end - kJoinersFromEnd, "bad number of joiner triangles 257"));
    EXPECT_EQ(ErrorOf(with(end - 2, Hex("ff ff"))),
              At(end - 2, "bad number of double joiner triangles -1"));

    // Without a material section, only void.
    const std::string flat = Bytes("tri_void.rtm");
    std::string bad = flat;
    bad[flat.size() - 5] = 0;  // the sole material ff ff -> ff 00
    EXPECT_EQ(ErrorOf(bad), At(flat.size() - 6, "bad local triangle material (-256, 0 materials)"));
    // (u,v) in a patch of a mesh whose (u,v) limits are all 0.
    const std::string noUv = Bytes("tri_flat.rtm");
    const std::size_t flatFlags = noUv.find(Hex("ff 00 00 00 01 01 00 04")) + 5;
    bad = noUv;
    bad[flatFlags] = 5;
    EXPECT_EQ(ErrorOf(bad), At(flatFlags, "unreferenced uv coordinates"));
}

/// tri.rtm with its two trailing joiner counts replaced by `joiners`.
std::string WithJoiners(const std::string& joiners) {
    const std::string good = Bytes("tri.rtm");
    return good.substr(0, good.size() - kJoinersFromEnd) + joiners;
}

TEST(MeshFile, JoinerTriangles) {
    const std::size_t at = Bytes("tri.rtm").size() - kJoinersFromEnd;
    // One single joiner: vertex ID 3 (patch 0, local 3), local 0 and 1, material 1 (red).
    MeshFile m = Read(WithJoiners(Hex("00 01  00 00 00 03  00 01  00 01  00 00")));
    ASSERT_EQ(m.triangles.size(), 3u);
    EXPECT_EQ(m.triangles[2].v, (std::array<int, 3>{3, 0, 1}));
    EXPECT_EQ(m.triangles[2].material, 1);
    // One double joiner: IDs 2 and 0, local 1, material 0.
    m = Read(WithJoiners(Hex("00 00  00 01  00 00 00 02  00 00 00 00  01  00 00")));
    ASSERT_EQ(m.triangles.size(), 3u);
    EXPECT_EQ(m.triangles[2].v, (std::array<int, 3>{2, 0, 1}));
    EXPECT_EQ(m.triangles[2].material, 0);
    // Vertex ID 256 names patch 1, which does not exist; ID 4 is past patch 0's 4 vertices.
    EXPECT_EQ(ErrorOf(WithJoiners(Hex("00 01  00 00 01 00  00 01  00 01  00 00"))),
              At(at + 2, "bad j1 triangle joiner (no vertex 256)"));
    EXPECT_EQ(ErrorOf(WithJoiners(Hex("00 00  00 01  00 00 00 02  00 00 00 04  01  00 00"))),
              At(at + 8, "bad j2 triangle joiner (no vertex 4)"));
    EXPECT_EQ(ErrorOf(WithJoiners(Hex("00 01  00 00 00 03  00 09  00 01  00 00"))),
              At(at + 7, "bad j1 triangle local index (vertex 9 of 4)"));
    EXPECT_EQ(ErrorOf(WithJoiners(Hex("00 00  00 01  00 00 00 02  00 00 00 00  01  00 07"))),
              At(at + 13, "bad j2 triangle material (7, 3 materials)"));
    // A leaf may name a joiner once it exists: 0x200 is the first single joiner.
    const std::string good = Bytes("tri.rtm");
    std::string named = WithJoiners(Hex("00 01  00 00 00 03  00 01  00 01  00 00"));
    const std::size_t leaf = good.find(Z("1.00002")) + 8 + 20;
    named.replace(leaf + 9, 4, Hex("00 00 02 00"));
    EXPECT_EQ(ErrorOf(named), "");
}

TEST(MeshFile, HostilePatchCountIsNotTrusted) {
    // 2^22 patches announced, none present: an error at the missing data, no
    // allocation from the count.
    const std::string good = Bytes("tri.rtm");
    const std::size_t count = good.find(Hex("ff 00 00 00 01 07 00 04")) + 1;
    std::string bad = good.substr(0, count) + Hex("00 40 00 00");
    EXPECT_EQ(ErrorOf(bad), At(count + 4, "truncated mesh file (reading patch flags)"));
    bad = good.substr(0, count) + Hex("00 40 00 01");
    EXPECT_EQ(ErrorOf(bad), At(count, "bad patch count 4194305"));
    bad = good.substr(0, count) + Hex("ff ff ff ff");
    EXPECT_EQ(ErrorOf(bad), At(count, "bad patch count -1"));
}

TEST(MeshFile, LooksLikeMesh) {
    const auto looks = [](const std::string& bytes) {
        std::istringstream in(bytes);
        const bool mesh = LooksLikeMesh(in);
        EXPECT_EQ(in.tellg(), 0);
        return mesh;
    };
    EXPECT_TRUE(looks(Bytes("tri.rtm")));
    // rtrace goes by the magic number, not the FORMAT line.
    EXPECT_TRUE(looks("#?RADIANCE\nFORMAT=other\n\n" + Hex("01 43")));
    EXPECT_TRUE(looks("#?RADIANCE\n\n" + Hex("01 43")));
    EXPECT_FALSE(looks("#?RADIANCE\nFORMAT=Radiance_octree\n\n" + Hex("01 1f")));
    EXPECT_FALSE(looks("#?RADIANCE\n\n" + Hex("01 3f")));
    EXPECT_FALSE(looks("void plastic red 0 0 5 1 0 0 0 0\n"));
    EXPECT_FALSE(looks(""));
}

}  // namespace
}  // namespace rt
