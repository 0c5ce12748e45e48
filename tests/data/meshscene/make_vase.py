#!/usr/bin/env python3
"""Writes vase.obj for make_mesh_scenes.sh: a surface of revolution (radius
r(z) = 0.3 + 0.12 sin(3z) for z in [0, 1.2]) with analytic vertex normals and
(u, v) = (angle / 2π, z / 1.2). Three materials in height bands: glaze (plain
plastic), decor (plastic under a colorfunc of Lu, Lv) and rim (mirror-like
metal). Deterministic, fixed precision."""
import math

NZ, NA = 30, 36
R0, A, K, H = 0.3, 0.12, 3.0, 1.2

def radius(z):
    return R0 + A * math.sin(K * z)

with open("vase.obj", "w") as f:
    f.write("# vase for the mesh scene tests (make_vase.py)\n")
    for i in range(NZ + 1):
        z = H * i / NZ
        r, dr = radius(z), A * K * math.cos(K * z)
        for j in range(NA + 1):
            a = 2 * math.pi * j / NA
            f.write("v %.6f %.6f %.6f\n" % (r * math.cos(a), r * math.sin(a), z))
            # Outward normal of the surface of revolution.
            n = (math.cos(a), math.sin(a), -dr)
            l = math.sqrt(sum(c * c for c in n))
            f.write("vn %.6f %.6f %.6f\n" % tuple(c / l for c in n))
            f.write("vt %.6f %.6f\n" % (j / NA, z / H))
    def idx(i, j):
        return i * (NA + 1) + j + 1
    for i in range(NZ):
        band = "glaze" if i < 12 else ("decor" if i < 24 else "rim")
        f.write("usemtl %s\n" % band)
        for j in range(NA):
            a, b, c, d = idx(i, j), idx(i, j + 1), idx(i + 1, j + 1), idx(i + 1, j)
            f.write("f %d/%d/%d %d/%d/%d %d/%d/%d\n" % (a, a, a, b, b, b, c, c, c))
            f.write("f %d/%d/%d %d/%d/%d %d/%d/%d\n" % (a, a, a, c, c, c, d, d, d))
