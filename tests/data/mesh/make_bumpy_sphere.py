#!/usr/bin/env python3
"""Writes bumpy_sphere.obj for make_meshes.sh: a sphere of radius about 1 with a
bump pattern, NLAT x NLON vertices, outward-facing triangles (counter-clockwise
seen from outside), analytic per-vertex normals of the bumpy surface and (u,v).
Enough triangles to need several 256-vertex mesh patches, so obj2mesh writes
joiner triangles. Latitude bands take the materials red, blue, grey and uvf (a
pattern) in turn; the band around the equator has no vt, so its vertices
have no (u,v). Deterministic: no randomness, fixed-precision output."""
import math

NLAT, NLON = 28, 40


def radius(th, ph):
    return 1.0 + 0.08 * math.sin(5 * th) * math.cos(4 * ph)


def point(th, ph):
    r = radius(th, ph)
    return (r * math.sin(th) * math.cos(ph), r * math.sin(th) * math.sin(ph), r * math.cos(th))


def normal(th, ph):
    # Normal of the surface r(th, ph)·ŝ: the cross product of the two tangents,
    # from central differences (the exact value does not matter, only that
    # obj2mesh keeps it because it differs from the faces' normals).
    h = 1e-5
    a, b = point(th + h, ph), point(th - h, ph)
    c, d = point(th, ph + h), point(th, ph - h)
    t1 = [x - y for x, y in zip(a, b)]
    t2 = [x - y for x, y in zip(c, d)]
    n = (t1[1] * t2[2] - t1[2] * t2[1], t1[2] * t2[0] - t1[0] * t2[2], t1[0] * t2[1] - t1[1] * t2[0])
    m = math.sqrt(sum(x * x for x in n))
    return tuple(x / m for x in n)


def main():
    out = ["# bumpy sphere for lazyrad's mesh reader tests (make_bumpy_sphere.py)"]
    # Rings i = 1..NLAT-1 (poles excluded), plus one vertex per pole.
    index = {}
    for i in range(1, NLAT):
        th = math.pi * i / NLAT
        for j in range(NLON):
            ph = 2 * math.pi * j / NLON
            index[i, j] = len(index) + 1
            out.append("v %.5f %.5f %.5f" % point(th, ph))
            out.append("vn %.5f %.5f %.5f" % normal(th, ph))
            out.append("vt %.5f %.5f" % (j / NLON, i / NLAT))
    north, south = len(index) + 1, len(index) + 2
    out.append("v 0 0 %.5f" % radius(0, 0))
    out.append("vn 0 0 1")
    out.append("vt 0.5 0")
    out.append("v 0 0 %.5f" % -radius(math.pi, 0))
    out.append("vn 0 0 -1")
    out.append("vt 0.5 1")
    nv = len(index) + 2
    materials = ["red", "blue", "grey", "uvf"]

    def ref(k, uv):
        return "%d/%d/%d" % (k, k, k) if uv else "%d//%d" % (k, k)

    for band in range(NLAT):
        mat = materials[band % len(materials)]
        out.append("usemtl " + mat)
        uv = band not in (NLAT // 2 - 1, NLAT // 2)
        for j in range(NLON):
            j1 = (j + 1) % NLON
            if band == 0:
                tri = [(north,), (index[1, j],), (index[1, j1],)]
                out.append("f " + " ".join(ref(t[0], uv) for t in tri))
            elif band == NLAT - 1:
                tri = [(index[band, j],), (south,), (index[band, j1],)]
                out.append("f " + " ".join(ref(t[0], uv) for t in tri))
            else:
                a, b = index[band, j], index[band, j1]
                c, d = index[band + 1, j], index[band + 1, j1]
                out.append("f %s %s %s" % (ref(a, uv), ref(c, uv), ref(d, uv)))
                out.append("f %s %s %s" % (ref(a, uv), ref(d, uv), ref(b, uv)))
    with open("bumpy_sphere.obj", "w") as f:
        f.write("\n".join(out) + "\n")
    print("bumpy_sphere.obj: %d vertices" % nv)


main()
