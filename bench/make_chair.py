#!/usr/bin/env python3
"""Writes chair.obj (to stdout) for bench/mesh_room.sh: a chair of about 1200
triangles - a seat and a back rest as boxes, four legs and two back posts as
24-sided cylinders with smooth vertex normals - with materials seat, frame."""
import math

out = []
verts = []
normals = []

def vertex(p, n):
    verts.append(p)
    normals.append(n)
    return len(verts)

def face(a, b, c):
    out.append("f %d//%d %d//%d %d//%d" % (a, a, b, b, c, c))

def box(x0, y0, z0, x1, y1, z1):
    corners = [(x, y, z) for z in (z0, z1) for y in (y0, y1) for x in (x0, x1)]
    sides = [((0, 2, 3, 1), (0, 0, -1)), ((4, 5, 7, 6), (0, 0, 1)), ((0, 1, 5, 4), (0, -1, 0)),
             ((2, 6, 7, 3), (0, 1, 0)), ((0, 4, 6, 2), (-1, 0, 0)), ((1, 3, 7, 5), (1, 0, 0))]
    for quad, n in sides:
        ids = [vertex(corners[k], n) for k in quad]
        face(ids[0], ids[1], ids[2])
        face(ids[0], ids[2], ids[3])

def cylinder(cx, cy, z0, z1, r, sides=24, rings=4):
    ids = []
    for i in range(rings + 1):
        z = z0 + (z1 - z0) * i / rings
        row = []
        for j in range(sides):
            a = 2 * math.pi * j / sides
            row.append(vertex((cx + r * math.cos(a), cy + r * math.sin(a), z),
                              (math.cos(a), math.sin(a), 0)))
        ids.append(row)
    for i in range(rings):
        for j in range(sides):
            a, b = ids[i][j], ids[i][(j + 1) % sides]
            c, d = ids[i + 1][(j + 1) % sides], ids[i + 1][j]
            face(a, b, c)
            face(a, c, d)

out.append("usemtl frame")
for x, y in ((0.04, 0.04), (0.41, 0.04), (0.04, 0.41), (0.41, 0.41)):
    cylinder(x, y, 0, 0.45, 0.02)
for x in (0.04, 0.41):
    cylinder(x, 0.43, 0.45, 0.95, 0.018)
out.append("usemtl seat")
box(0, 0, 0.45, 0.45, 0.45, 0.5)
box(0.02, 0.41, 0.7, 0.43, 0.45, 0.92)
for p in verts:
    print("v %.5f %.5f %.5f" % p)
for n in normals:
    print("vn %.5f %.5f %.5f" % n)
print("\n".join(out))
