// SPDX-License-Identifier: MIT
//
// Radiance's triangle-mesh files (.rtm, written by obj2mesh, read by
// readmesh.c and checked by mesh.c's checkmesh; radiance-functions.md §13.3)
// as plain data: the header, the mesh cube, the (u,v) limits, the material
// section, and every triangle with its vertices flattened out of the
// 256-vertex patches. The file's own octree is only checked (every leaf names
// an existing triangle), not kept: lazyrad builds its own acceleration.
//
//   std::ifstream in("tri.rtm", std::ios::binary);
//   const MeshFile mesh = ReadMesh(in, "tri.rtm");
#pragma once

#include <array>
#include <cstdint>
#include <istream>
#include <optional>
#include <string>
#include <vector>

#include "core/vecmath.h"
#include "scene/scene.h"

namespace rt {

struct MeshFile {
    /// Header lines between "#?RADIANCE" and the blank line, without FORMAT.
    std::vector<std::string> headerLines;
    Vec3 cubeOrigin;     // the mesh octree's cube, in mesh (object) coordinates
    double cubeSize = 0;  // > kFtiny
    /// (u,v) limits; all 0 when no vertex has (u,v).
    double uMin = 0, uMax = 0, vMin = 0, vMax = 0;
    /// The material section, in order. Modifier names are resolved within it
    /// ("void" for -1); loc is the file name and the byte offset of the object.
    /// Only modifiers (materials, patterns, textures, mixtures, aliases).
    std::vector<SceneObject> materials;
    /// Dequantised positions x = org + (q + 0.5)·size/2^32, patch by patch.
    std::vector<Vec3> vertices;
    /// Per vertex, unit length; (0,0,0) where a vertex has none. Empty when no
    /// patch stores normals.
    std::vector<Vec3> normals;
    /// Per vertex (u, v); (0, 0) where hasUv is 0. Empty when no patch stores (u,v).
    std::vector<std::array<double, 2>> uvs;
    /// Per vertex when uvs is not empty: 1 if the vertex has (u,v) (q_u != 0).
    std::vector<std::uint8_t> hasUv;
    struct Triangle {
        std::array<int, 3> v;  // indices into vertices, in the file's vertex order
        int material;          // index into materials, -1 = void
    };
    /// Patch by patch: its local triangles, single joiners, double joiners.
    std::vector<Triangle> triangles;
};

/// True if `in` starts with a Radiance header that says FORMAT=Radiance_tmesh
/// or, lacking that, is followed by a mesh magic number (rtrace itself goes by
/// the magic number alone). Leaves the stream at its start.
bool LooksLikeMesh(std::istream& in);

/// Reads a whole mesh file. `name` is used in error locations. Throws rt::Error
/// "name: byte N: ..." for anything malformed or truncated, with Radiance's
/// wording where it has one; never allocates out of proportion to the input.
MeshFile ReadMesh(std::istream& in, const std::string& name);

/// Radiance's barycentric weights of `p` in triangle (v0, v1, v2) (tmesh.c
/// comp_baryc/eval_baryc, radiance-functions.md §13.4): computed in the
/// coordinate plane that drops the largest component of the triangle's
/// normal, so `p` is in effect projected along that axis onto the triangle's
/// plane. The weights sum to 1 and give `p` back for points in the plane.
/// std::nullopt for a triangle that is degenerate in that plane (Radiance's
/// "bad triangle", where it interpolates nothing).
std::optional<std::array<double, 3>> BarycentricWeights(const Vec3& v0, const Vec3& v1,
                                                        const Vec3& v2, const Vec3& p);

}  // namespace rt
