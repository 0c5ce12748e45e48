// SPDX-License-Identifier: MIT
#include "scene/mesh_file.h"

#include <cmath>

#include "core/conventions.h"
#include "core/dircode.h"
#include "core/error.h"
#include "scene/object_types.h"
#include "scene/radiance_binary.h"

namespace rt {
namespace {

using detail::RadianceBinaryReader;

// MESHMAGIC + sizeof(OBJECT): 311 + 8 + objsize (Radiance's mesh.h).
constexpr long long kMeshMagicBase = 311 + 8;
constexpr int kFlagPositions = 1, kFlagNormals = 2, kFlagUv = 4;  // MT_V, MT_N, MT_UV
constexpr int kMaxPatchVertices = 256;   // a vertex ID keeps the local index in 8 bits
constexpr int kMaxLocalTriangles = 512;  // triangle IDs 0..0x1ff of a patch
constexpr int kMaxJoiners = 256;         // IDs 0x200..0x2ff and 0x300..0x3ff
// Vertex IDs are patch·256 + local in a signed 32-bit integer, and Radiance's
// writer (addmeshvert) stops at 2^22 patches; a larger count is damage.
constexpr long long kMaxPatches = 1LL << 22;
constexpr int kVertexIdShift = 8, kTriangleIdShift = 10;
constexpr long long kSingleJoinerIds = 0x200, kDoubleJoinerIds = 0x300;
constexpr double kQuantum = 4294967296.0;  // 2^32: coordinates are uint32 fractions of the range

struct PatchInfo {
    int firstVertex;  // index in MeshFile::vertices of the patch's vertex 0
    int vertexCount;
    int firstTriangle;  // index in MeshFile::triangles of its first local triangle
    int localCount, singleCount, doubleCount;
};

/// A joiner's vertex in another patch, resolved once every patch is read
/// (it may name a later patch).
struct PendingVertex {
    std::size_t triangle;
    int slot;
    long long vertexId;
    long long offset;
    const char* error;
};

/// Checks a triangle's 2-byte material index the way checkmesh() does: with a
/// material section, an index into it (obj2mesh itself refuses void triangles
/// there); without one, -1 (void) is all obj2mesh writes, and Radiance's
/// behaviour for any other value is undefined, so it is refused.
int Material(RadianceBinaryReader& r, long long materialCount, const char* error) {
    const long long at = r.offset();
    const long long m = r.Int(2, "triangle material");
    const bool ok = materialCount > 0 ? (m >= 0 && m < materialCount) : m == -1;
    if (!ok) {
        r.Fail(at, std::string(error) + " (" + std::to_string(m) + ", " +
                       std::to_string(materialCount) + " materials)");
    }
    return static_cast<int>(m);
}

int LocalVertex(RadianceBinaryReader& r, const PatchInfo& patch, const char* error) {
    const long long at = r.offset();
    const int v = r.Byte("triangle vertex");
    if (v >= patch.vertexCount) {
        r.Fail(at, std::string(error) + " (vertex " + std::to_string(v) + " of " +
                       std::to_string(patch.vertexCount) + ")");
    }
    return patch.firstVertex + v;
}

void ReadPatch(RadianceBinaryReader& r, MeshFile& mesh, std::vector<PatchInfo>& patches,
               std::vector<PendingVertex>& pending, bool uvBounded, double quantumSize) {
    const long long flagsAt = r.offset();
    const int flags = r.Byte("patch flags");
    if (!(flags & kFlagPositions) || (flags & ~(kFlagPositions | kFlagNormals | kFlagUv))) {
        r.Fail(flagsAt, "bad patch flags " + std::to_string(flags));
    }
    // checkmesh(): (u,v) need limits to be decoded against.
    if ((flags & kFlagUv) && !uvBounded) r.Fail(flagsAt, "unreferenced uv coordinates");
    const long long countAt = r.offset();
    const long long n = r.Int(2, "patch vertex count");
    if (n <= 0 || n > kMaxPatchVertices) {
        r.Fail(countAt, "bad number of patch vertices " + std::to_string(n));
    }
    PatchInfo patch{};
    patch.firstVertex = static_cast<int>(mesh.vertices.size());
    patch.vertexCount = static_cast<int>(n);
    for (long long k = 0; k < n; ++k) {
        Vec3 p;
        for (int i = 0; i < 3; ++i) {
            const auto q = static_cast<double>(r.Unsigned(4, "vertex coordinate"));
            p[i] = mesh.cubeOrigin[i] + (q + 0.5) * quantumSize;
        }
        mesh.vertices.push_back(p);
    }
    // Normals and (u,v) are per vertex across the whole mesh once any patch
    // has them; vertices of patches without them get the "none" value.
    if ((flags & kFlagNormals) || !mesh.normals.empty()) mesh.normals.resize(mesh.vertices.size());
    if (flags & kFlagNormals) {
        for (long long k = 0; k < n; ++k) {
            // Any code decodes to a unit vector (the two stored magnitudes are
            // at most 8191/11584.5 each), or to (0,0,0) for code 0.
            const auto code = static_cast<std::uint32_t>(r.Unsigned(4, "vertex normal"));
            mesh.normals[patch.firstVertex + k] = DecodeDirection(code);
        }
    }
    if ((flags & kFlagUv) || !mesh.uvs.empty()) {
        mesh.uvs.resize(mesh.vertices.size());
        mesh.hasUv.resize(mesh.vertices.size());
    }
    if (flags & kFlagUv) {
        for (long long k = 0; k < n; ++k) {
            const auto qu = r.Unsigned(4, "vertex u");
            const auto qv = r.Unsigned(4, "vertex v");
            // The writer widens the limits so that a real (u,v) never encodes
            // as q_u = 0: that value marks a vertex without (u,v).
            if (qu == 0) continue;
            mesh.uvs[patch.firstVertex + k] = {
                mesh.uMin + (mesh.uMax - mesh.uMin) * (static_cast<double>(qu) + 0.5) / kQuantum,
                mesh.vMin + (mesh.vMax - mesh.vMin) * (static_cast<double>(qv) + 0.5) / kQuantum};
            mesh.hasUv[patch.firstVertex + k] = 1;
        }
    }
    const long long materialCount = static_cast<long long>(mesh.materials.size());
    patch.firstTriangle = static_cast<int>(mesh.triangles.size());

    const long long localAt = r.offset();
    const long long local = r.Int(2, "local triangle count");
    if (local < 0 || local > kMaxLocalTriangles) {
        r.Fail(localAt, "bad number of local triangles " + std::to_string(local));
    }
    patch.localCount = static_cast<int>(local);
    for (long long k = 0; k < local; ++k) {
        MeshFile::Triangle t{};
        for (int& v : t.v) v = LocalVertex(r, patch, "bad local triangle index");
        mesh.triangles.push_back(t);
    }
    // Radiance reads per-triangle materials whenever this count exceeds 1,
    // one per local triangle whatever the count says; else one for all.
    if (r.Int(2, "local material count") > 1) {
        for (long long k = 0; k < local; ++k) {
            mesh.triangles[patch.firstTriangle + k].material =
                Material(r, materialCount, "bad local triangle material");
        }
    } else {
        const int sole = Material(r, materialCount, "bad local triangle material");
        for (long long k = 0; k < local; ++k) mesh.triangles[patch.firstTriangle + k].material = sole;
    }

    const long long singleAt = r.offset();
    const long long single = r.Int(2, "joiner triangle count");
    if (single < 0 || single > kMaxJoiners) {
        r.Fail(singleAt, "bad number of joiner triangles " + std::to_string(single));
    }
    patch.singleCount = static_cast<int>(single);
    for (long long k = 0; k < single; ++k) {
        MeshFile::Triangle t{};
        const long long idAt = r.offset();
        pending.push_back({mesh.triangles.size(), 0, r.Int(4, "joiner vertex"), idAt,
                           "bad j1 triangle joiner"});
        t.v[1] = LocalVertex(r, patch, "bad j1 triangle local index");
        t.v[2] = LocalVertex(r, patch, "bad j1 triangle local index");
        t.material = Material(r, materialCount, "bad j1 triangle material");
        mesh.triangles.push_back(t);
    }

    const long long doubleAt = r.offset();
    const long long twice = r.Int(2, "double joiner triangle count");
    if (twice < 0 || twice > kMaxJoiners) {
        r.Fail(doubleAt, "bad number of double joiner triangles " + std::to_string(twice));
    }
    patch.doubleCount = static_cast<int>(twice);
    for (long long k = 0; k < twice; ++k) {
        MeshFile::Triangle t{};
        for (int slot = 0; slot < 2; ++slot) {
            const long long idAt = r.offset();
            pending.push_back({mesh.triangles.size(), slot, r.Int(4, "joiner vertex"), idAt,
                               "bad j2 triangle joiner"});
        }
        t.v[2] = LocalVertex(r, patch, "bad j2 triangle local index");
        t.material = Material(r, materialCount, "bad j2 triangle material");
        mesh.triangles.push_back(t);
    }
    patches.push_back(patch);
}

}  // namespace

bool LooksLikeMesh(std::istream& in) {
    const auto start = in.tellg();
    std::string line;
    bool mesh = false;
    if (std::getline(in, line) && line == "#?RADIANCE") {
        bool blank = false;
        // Header lines are short text; stop at the blank line or after a bound.
        for (int k = 0; k < 4096 && std::getline(in, line); ++k) {
            if (line.empty()) {
                blank = true;
                break;
            }
            if (line == "FORMAT=Radiance_tmesh") mesh = true;
        }
        if (!mesh && blank) {
            const int hi = in.get();
            const int lo = in.get();
            if (hi != std::char_traits<char>::eof() && lo != std::char_traits<char>::eof()) {
                const long long objsize = (hi << 8 | lo) - kMeshMagicBase;
                mesh = objsize >= 1 && objsize <= detail::kMaxObjectSize;
            }
        }
    }
    in.clear();
    in.seekg(start);
    return mesh;
}

MeshFile ReadMesh(std::istream& in, const std::string& name) {
    RadianceBinaryReader r(in, name, 0, "truncated mesh file");
    MeshFile mesh;
    // readmesh.c ignores the header's FORMAT: the magic number decides.
    mesh.headerLines = detail::ReadRadianceHeader(r, false, nullptr, "not a Radiance mesh",
                                                  "truncated mesh file header")
                           .lines;
    const long long magicAt = r.offset();
    const long long magic = r.Int(2, "magic number");
    const long long objsize = magic - kMeshMagicBase;
    if (objsize < 1 || objsize > detail::kMaxObjectSize) {
        r.Fail(magicAt, "incompatible mesh format (magic number " + std::to_string(magic) + ")");
    }
    const int size = static_cast<int>(objsize);
    mesh.cubeOrigin.x = detail::ReadCubeNumber(r, "cube origin");
    mesh.cubeOrigin.y = detail::ReadCubeNumber(r, "cube origin");
    mesh.cubeOrigin.z = detail::ReadCubeNumber(r, "cube origin");
    const long long sizeAt = r.offset();
    mesh.cubeSize = detail::ReadCubeNumber(r, "cube size");
    if (!(mesh.cubeSize > kFtiny)) r.Fail(sizeAt, "illegal octree bounds in mesh");
    mesh.uMin = r.Real("u limit");
    mesh.uMax = r.Real("u limit");
    mesh.vMin = r.Real("v limit");
    mesh.vMax = r.Real("v limit");
    const bool uvBounded = mesh.uMax - mesh.uMin > kFtiny && mesh.vMax - mesh.vMin > kFtiny;

    // Leaf entries are triangle IDs; which exist is known only after the patches.
    const std::vector<detail::LeafEntry> leaves = detail::ReadTreeLeaves(r, size, -1);

    detail::ReadObjectSection(r, size, -1, mesh.materials);
    for (const SceneObject& m : mesh.materials) {
        if (!IsKnownObjectType(m.type)) {
            r.Fail(m.loc.byteOffset, "unknown object type \"" + m.type + "\" in mesh");
        }
        if (IsSurfaceObjectType(m.type)) {
            r.Fail(m.loc.byteOffset, "non-modifier in mesh (" + m.type + " \"" + m.name + "\")");
        }
    }

    const long long patchCountAt = r.offset();
    const long long patchCount = r.Int(4, "patch count");
    if (patchCount < 0 || patchCount > kMaxPatches) {
        r.Fail(patchCountAt, "bad patch count " + std::to_string(patchCount));
    }
    // No reserve() from the count: it is only trusted as far as the data goes.
    std::vector<PatchInfo> patches;
    std::vector<PendingVertex> pending;
    const double quantumSize = mesh.cubeSize / kQuantum;
    for (long long p = 0; p < patchCount; ++p) {
        ReadPatch(r, mesh, patches, pending, uvBounded, quantumSize);
    }

    for (const PendingVertex& j : pending) {
        const long long patch = j.vertexId >> kVertexIdShift;
        const long long local = j.vertexId & (kMaxPatchVertices - 1);
        if (j.vertexId < 0 || patch >= static_cast<long long>(patches.size()) ||
            local >= patches[patch].vertexCount) {
            r.Fail(j.offset, std::string(j.error) + " (no vertex " + std::to_string(j.vertexId) + ")");
        }
        mesh.triangles[j.triangle].v[j.slot] =
            patches[patch].firstVertex + static_cast<int>(local);
    }

    for (const detail::LeafEntry& leaf : leaves) {
        const long long patch = leaf.index >> kTriangleIdShift;
        const long long k = leaf.index & ((1 << kTriangleIdShift) - 1);
        bool ok = patch < static_cast<long long>(patches.size());
        if (ok) {
            const PatchInfo& info = patches[patch];
            ok = k < kSingleJoinerIds   ? k < info.localCount
                 : k < kDoubleJoinerIds ? k - kSingleJoinerIds < info.singleCount
                                        : k - kDoubleJoinerIds < info.doubleCount;
        }
        if (!ok) {
            r.Fail(leaf.offset,
                   "mesh octree leaf names triangle " + std::to_string(leaf.index) + ", which does not exist");
        }
    }
    return mesh;
}

std::optional<std::array<double, 3>> BarycentricWeights(const Vec3& v0, const Vec3& v1,
                                                        const Vec3& v2, const Vec3& p) {
    // comp_baryc(): the dominant axis of the normal is dropped; a and b are
    // the two remaining coordinates in cyclic order.
    const Vec3 n = Cross(v0 - v1, v2 - v1);
    int axis = std::fabs(n.x) > std::fabs(n.y) ? 0 : 1;
    if (!(std::fabs(n[axis]) > std::fabs(n.z))) axis = 2;
    const int a = (axis + 1) % 3, b = (axis + 2) % 3;
    // For each vertex in turn, the 2-D vector that gives its weight as an
    // affine function of (p_a, p_b): perpendicular to the opposite edge,
    // scaled so that the weight is 1 at the vertex.
    const Vec3* vs[3] = {&v0, &v1, &v2};
    double w[3];
    for (int i = 0; i < 2; ++i) {
        const Vec3& va = *vs[i];
        const Vec3& vb = *vs[(i + 1) % 3];
        const Vec3& vc = *vs[(i + 2) % 3];
        const double ab0 = va[a] - vb[a], ab1 = va[b] - vb[b];
        const double cb0 = vc[a] - vb[a], cb1 = vc[b] - vb[b];
        double d = cb0 * cb0 + cb1 * cb1;
        if (d <= kFtiny * kFtiny) return std::nullopt;
        d = (cb0 * ab0 + cb1 * ab1) / d;
        double t0 = ab0 - cb0 * d, t1 = ab1 - cb1 * d;
        d = t0 * t0 + t1 * t1;
        if (d <= kFtiny * kFtiny) return std::nullopt;
        t0 /= d;
        t1 /= d;
        w[i] = (p[a] - vb[a]) * t0 + (p[b] - vb[b]) * t1;
    }
    w[2] = 1.0 - w[0] - w[1];
    return std::array<double, 3>{w[0], w[1], w[2]};
}

}  // namespace rt
