// SPDX-License-Identifier: MIT
//
// Fuzz target: arbitrary bytes as a Radiance mesh file through ReadMesh, and
// every triangle it returns through BarycentricWeights, checking what the
// reader promises: vertex and material indices in range, unit or zero normals,
// per-vertex arrays of the vertex count. rt::Error is the expected way to
// reject input; any other exception, a crash, UB, a hang or memory out of
// proportion to the input is a finding.
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>

#include "core/error.h"
#include "scene/mesh_file.h"
#include "tests/fuzz/fuzz_entry.h"

extern "C" int RT_FUZZ_ENTRY(const std::uint8_t* data, std::size_t size) {
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    std::istringstream in(bytes);
    try {
        if (!rt::LooksLikeMesh(in)) return 0;
        const rt::MeshFile mesh = rt::ReadMesh(in, "fuzz.rtm");
        const std::size_t nv = mesh.vertices.size();
        if (!mesh.normals.empty() && mesh.normals.size() != nv) std::abort();
        if (!mesh.uvs.empty() && (mesh.uvs.size() != nv || mesh.hasUv.size() != nv)) std::abort();
        for (const rt::Vec3& n : mesh.normals) {
            if (n != rt::Vec3{} && std::fabs(rt::Length(n) - 1) > 1e-9) std::abort();
        }
        const int nm = static_cast<int>(mesh.materials.size());
        for (const rt::MeshFile::Triangle& t : mesh.triangles) {
            for (const int v : t.v) {
                if (v < 0 || static_cast<std::size_t>(v) >= nv) std::abort();
            }
            if (t.material < -1 || t.material >= nm) std::abort();
            const rt::Vec3 centre =
                (mesh.vertices[t.v[0]] + mesh.vertices[t.v[1]] + mesh.vertices[t.v[2]]) / 3;
            static_cast<void>(rt::BarycentricWeights(mesh.vertices[t.v[0]], mesh.vertices[t.v[1]],
                                                     mesh.vertices[t.v[2]], centre));
        }
    } catch (const rt::Error& e) {
        rt::fuzz::ExpectRefusal(e);
        // Rejected input: expected.
    }
    return 0;
}
