// SPDX-License-Identifier: MIT
//
// genbox: writes a box (parallelepiped from the origin to xsize ysize zsize) as
// Radiance polygons, with the same identifiers, vertices and number format
// as Radiance 5.4a's genbox, so scenes made with either are interchangeable.
//
//   genbox material name xsize ysize zsize [-i] [-b bevel | -r round [-n nsegs][-s]]
//
// Radiance's genbox writes a rounded box of more than two segments an edge
// (-n above 2, or -r with -i and no -n) and its -o output through its object
// library as a polygon mesh; those are refused here.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "scene/reader.h"

namespace {

// Radiance's vertex naming alphabet: vertex k of a face prints as kLetters[k].
constexpr char kLetters[] = "0123456789._ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz";

struct Box {
    std::string material;
    std::string name;
    double size[3] = {0, 0, 0};
    double bevel = 0;
    bool round = false;
    bool reverse = false;
};

// A vertex code holds one bit per axis for "far side" (bits 0-2) and, with
// bevels, one bit per axis for "inset by the bevel" read as genbox.c does:
// after shifting the code right once per axis, bit 3 selects the inset form.
// -i mirrors every vertex through the box's centre (the far side becomes the
// near one), which turns every face inwards and keeps the vertex order.
void PrintVertex(const Box& box, int code) {
    for (int axis = 0; axis < 3; ++axis) {
        const bool far = ((code & 1) != 0) != box.reverse;
        double value;
        if (code & 010) {
            value = far ? box.size[axis] - box.bevel : box.bevel;
        } else {
            value = far ? box.size[axis] : 0.0;
        }
        std::printf("\t%18.12g", value);
        code >>= 1;
    }
    std::printf("\n");
}

void Side(const Box& box, int a, int b, int c, int d) {
    std::printf("\n%s polygon %s.%c%c%c%c\n0\n0\n12\n", box.material.c_str(), box.name.c_str(),
                kLetters[a], kLetters[b], kLetters[c], kLetters[d]);
    for (const int v : {a, b, c, d}) PrintVertex(box, v);
}

void Corner(const Box& box, int a, int b, int c) {
    std::printf("\n%s polygon %s.%c%c%c\n0\n0\n9\n", box.material.c_str(), box.name.c_str(),
                kLetters[a], kLetters[b], kLetters[c]);
    for (const int v : {a, b, c}) PrintVertex(box, v);
}

// Rounded edges and corners, named by their vertices as the faces are.
void Cylinder(const Box& box, int v0, int v1) {
    std::printf("\n%s cylinder %s.%c%c\n0\n0\n7\n", box.material.c_str(), box.name.c_str(),
                kLetters[v0], kLetters[v1]);
    PrintVertex(box, v0);
    PrintVertex(box, v1);
    std::printf("\t%18.12g\n", box.bevel);
}

void Sphere(const Box& box, int v0) {
    std::printf("\n%s sphere %s.%c\n0\n0\n4\n", box.material.c_str(), box.name.c_str(),
                kLetters[v0]);
    PrintVertex(box, v0);
    std::printf("\t%18.12g\n", box.bevel);
}

int Usage(const char* program) {
    std::fprintf(stderr,
                 "Usage: %s material name xsize ysize zsize [-i] [-b bevel | -r round [-n "
                 "nsegs][-s]] [-o]\n",
                 program);
    return 1;
}

void WriteBox(const Box& box) {
    if (box.bevel > 0) {  // minor faces
        Side(box, 051, 055, 054, 050);
        Side(box, 064, 066, 062, 060);
        Side(box, 032, 033, 031, 030);
        Side(box, 053, 052, 056, 057);
        Side(box, 065, 061, 063, 067);
        Side(box, 036, 034, 035, 037);
    }
    if (box.bevel > 0 && !box.round) {  // bevel faces and corners
        Side(box, 031, 051, 050, 030);
        Side(box, 060, 062, 032, 030);
        Side(box, 050, 054, 064, 060);
        Side(box, 034, 036, 066, 064);
        Side(box, 037, 057, 056, 036);
        Side(box, 052, 062, 066, 056);
        Side(box, 052, 053, 033, 032);
        Side(box, 057, 067, 063, 053);
        Side(box, 061, 031, 033, 063);
        Side(box, 065, 067, 037, 035);
        Side(box, 055, 051, 061, 065);
        Side(box, 034, 054, 055, 035);
        Corner(box, 030, 050, 060);
        Corner(box, 051, 031, 061);
        Corner(box, 032, 062, 052);
        Corner(box, 064, 054, 034);
        Corner(box, 036, 056, 066);
        Corner(box, 065, 035, 055);
        Corner(box, 053, 063, 033);
        Corner(box, 037, 067, 057);
    }
    if (box.bevel > 0 && box.round) {  // rounded edges and corners
        Cylinder(box, 070, 071);
        Cylinder(box, 070, 074);
        Cylinder(box, 070, 072);
        Cylinder(box, 073, 071);
        Cylinder(box, 073, 072);
        Cylinder(box, 073, 077);
        Cylinder(box, 075, 071);
        Cylinder(box, 075, 074);
        Cylinder(box, 075, 077);
        Cylinder(box, 076, 072);
        Cylinder(box, 076, 074);
        Cylinder(box, 076, 077);
        for (int corner = 070; corner <= 077; ++corner) Sphere(box, corner);
    }
    if (box.bevel == 0) {  // only the six major faces
        Side(box, 1, 5, 4, 0);
        Side(box, 4, 6, 2, 0);
        Side(box, 2, 3, 1, 0);
        Side(box, 3, 2, 6, 7);
        Side(box, 5, 1, 3, 7);
        Side(box, 6, 4, 5, 7);
    }
}

}  // namespace

int main(int argc, char** argv) {
    const char* program = argv[0];
    if (argc < 6) return Usage(program);
    Box box;
    box.material = argv[1];
    box.name = argv[2];
    for (int i = 0; i < 3; ++i) {
        const auto value = rt::ParseRealWord(argv[3 + i]);
        if (!value) {
            std::fprintf(stderr, "genbox: bad size '%s'\n", argv[3 + i]);
            return 1;
        }
        box.size[i] = *value;
        if (!(box.size[i] > 0)) return Usage(program);  // as Radiance's
    }
    int segments = 1;  // -n: segments per rounded edge
    for (int i = 6; i < argc; ++i) {
        const std::string option = argv[i];
        if (option == "-i") {
            box.reverse = true;
        } else if (option == "-s") {
            // Smoothed normals, for the polygon meshes only (below).
        } else if (option == "-r" || option == "-b") {
            const auto value = i + 1 < argc ? rt::ParseRealWord(argv[i + 1]) : std::nullopt;
            if (!value || !(*value > 0)) {
                std::fprintf(stderr, "genbox: %s needs a positive number\n", option.c_str());
                return 1;
            }
            box.round = box.round || option == "-r";
            box.bevel = *value;
            ++i;
        } else if (option == "-n") {
            const auto value = i + 1 < argc ? rt::ParseRealWord(argv[i + 1]) : std::nullopt;
            if (!value || !(*value >= 1) || *value != std::floor(*value) || *value > 1e6) {
                std::fprintf(stderr, "genbox: -n needs a whole number of segments, at least 1\n");
                return 1;
            }
            segments = static_cast<int>(*value);
            ++i;
        } else if (option == "-o") {
            std::fprintf(stderr, "genbox: -o (Wavefront .OBJ output) is not supported\n");
            return 1;
        } else {
            return Usage(program);
        }
    }
    // Radiance 5.4a: with -i, a rounded box defaults to 32 segments an edge,
    // and more than two segments are written as a polygon mesh.
    if (box.round && (box.reverse && segments == 1 ? 32 : segments) > 2) {
        std::fprintf(stderr,
                     "genbox: rounded edges of more than two segments (-n above 2, or -r with "
                     "-i) are not supported\n");
        return 1;
    }
    std::printf("#");
    for (int i = 0; i < argc; ++i) std::printf(" %s", argv[i]);
    std::printf("\n");
    WriteBox(box);
    return std::fflush(stdout) == 0 ? 0 : 1;
}
