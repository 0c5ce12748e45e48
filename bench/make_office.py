#!/usr/bin/env python3
"""Writes office.rad (to stdout) for bench/big_scene.sh: an open-plan office
floor of about 100 000 polygons, the size of model a daylighting tool exports
whole (every chair, plant and blind slat as plain polygons, no instances).

A 40 x 24 x 3.5 m floor plate with window bands along both long sides behind
exterior blind slats, a suspended ceiling of 0.6 m tiles, 32 round columns,
160 desks with monitors and chairs, and 40 plants. The sky and the ground are
not included (big_scene.sh adds gensky's). Deterministic: no randomness.
"""
import math

out = []
count = 0


def polygon(mod, pts):
    global count
    count += 1
    out.append("%s polygon p%d\n0\n0\n%d\n" % (mod, count, 3 * len(pts)) +
               "".join("  %.9g %.9g %.9g\n" % p for p in pts))


def box(mod, x0, y0, z0, x1, y1, z1):
    """An outward-facing box (genbox's vertex order)."""
    c = lambda i, j, k: ((x0, x1)[i], (y0, y1)[j], (z0, z1)[k])
    polygon(mod, [c(0, 0, 0), c(0, 1, 0), c(1, 1, 0), c(1, 0, 0)])  # bottom
    polygon(mod, [c(0, 0, 1), c(1, 0, 1), c(1, 1, 1), c(0, 1, 1)])  # top
    polygon(mod, [c(0, 0, 0), c(1, 0, 0), c(1, 0, 1), c(0, 0, 1)])  # -y
    polygon(mod, [c(0, 1, 0), c(0, 1, 1), c(1, 1, 1), c(1, 1, 0)])  # +y
    polygon(mod, [c(0, 0, 0), c(0, 0, 1), c(0, 1, 1), c(0, 1, 0)])  # -x
    polygon(mod, [c(1, 0, 0), c(1, 1, 0), c(1, 1, 1), c(1, 0, 1)])  # +x


def cylinder(mod, cx, cy, z0, z1, r, sides):
    """A vertical tessellated cylinder with its top cap."""
    ring = [(cx + r * math.cos(2 * math.pi * k / sides), cy + r * math.sin(2 * math.pi * k / sides))
            for k in range(sides)]
    for k in range(sides):
        (ax, ay), (bx, by) = ring[k], ring[(k + 1) % sides]
        polygon(mod, [(ax, ay, z0), (bx, by, z0), (bx, by, z1), (ax, ay, z1)])
    polygon(mod, [(x, y, z1) for x, y in ring])


def sphere(mod, cx, cy, cz, r, rings, segments):
    """A tessellated sphere: quads, and triangles at the poles."""
    def p(i, j):
        t, f = math.pi * i / rings, 2 * math.pi * j / segments
        return (cx + r * math.sin(t) * math.cos(f), cy + r * math.sin(t) * math.sin(f),
                cz + r * math.cos(t))
    for i in range(rings):
        for j in range(segments):
            a, b, c, d = p(i, j), p(i + 1, j), p(i + 1, j + 1), p(i, j + 1)
            if i == 0:
                polygon(mod, [a, b, c])
            elif i == rings - 1:
                polygon(mod, [a, b, d])
            else:
                polygon(mod, [a, b, c, d])


W, D, H = 40.0, 24.0, 3.5       # floor plate
SILL, HEAD = 0.9, 2.7           # window band
CEIL = 3.0                      # suspended ceiling

out.append("""void plastic wall 0 0 5 .6 .6 .6 0 0
void plastic floor 0 0 5 .2 .2 .2 0 0
void plastic ceiling 0 0 5 .8 .8 .8 0 0
void plastic tile 0 0 5 .75 .75 .75 0 0
void glass window 0 0 3 .7 .7 .7
void metal slat 0 0 5 .7 .7 .7 .5 .05
void plastic desk 0 0 5 .5 .4 .3 0 0
void plastic screen 0 0 5 .05 .05 .05 .03 0
void plastic fabric 0 0 5 .2 .25 .4 0 0
void metal chrome 0 0 5 .6 .6 .6 .9 .02
void plastic leaf 0 0 5 .1 .35 .08 0 0
void plastic pot 0 0 5 .4 .2 .1 0 0
""")

# Shell: floor, slab above the ceiling void, end walls, and the long walls
# around a window band in 5 m bays.
polygon("floor", [(0, 0, 0), (0, D, 0), (W, D, 0), (W, 0, 0)])
polygon("ceiling", [(0, 0, H), (W, 0, H), (W, D, H), (0, D, H)])
polygon("wall", [(0, 0, 0), (0, 0, H), (0, D, H), (0, D, 0)])
polygon("wall", [(W, 0, 0), (W, D, 0), (W, D, H), (W, 0, H)])
for y, outward in ((0.0, -1), (D, 1)):
    for x0 in range(0, int(W), 5):
        x1 = x0 + 5
        for z0, z1 in ((0, SILL), (HEAD, H)):
            pts = [(x0, y, z0), (x1, y, z0), (x1, y, z1), (x0, y, z1)]
            polygon("wall", pts if outward > 0 else pts[::-1])
        pts = [(x0 + 0.05, y, SILL), (x1 - 0.05, y, SILL), (x1 - 0.05, y, HEAD), (x0 + 0.05, y, HEAD)]
        polygon("window", pts)
        for xa, xb in ((x0, x0 + 0.05), (x1 - 0.05, x1)):
            pts = [(xa, y, SILL), (xb, y, SILL), (xb, y, HEAD), (xa, y, HEAD)]
            polygon("wall", pts if outward > 0 else pts[::-1])
        # Exterior blind: horizontal slats 0.15 m out, every 0.1 m.
        for k in range(18):
            z = SILL + 0.05 + 0.1 * k
            yo = y + outward * 0.15
            box("slat", x0 + 0.05, min(yo, yo + outward * 0.08), z,
                x1 - 0.05, max(yo, yo + outward * 0.08), z + 0.004)

# Suspended ceiling: 0.6 m tiles, a bit smaller than the grid (open joints).
nx, ny = int(W / 0.6), int(D / 0.6)
for i in range(nx):
    for j in range(ny):
        x, y = i * 0.6 + 0.01, j * 0.6 + 0.01
        polygon("tile", [(x, y, CEIL), (x + 0.58, y, CEIL), (x + 0.58, y + 0.58, CEIL),
                         (x, y + 0.58, CEIL)])

# Columns on a 5 x 6 m grid.
for i in range(1, 8):
    for j in range(1, 4):
        cylinder("wall", 5.0 * i, 6.0 * j, 0, CEIL, 0.25, 24)

# Workstations: 8 rows of 20 desks; each a top, two side panels, a modesty
# panel, a monitor on a stand and a chair (seat, back, post, 5 spokes and 5
# castors).
for row in range(8):
    for k in range(20):
        x = 1.0 + k * 1.9
        y = 2.0 + row * 2.6
        box("desk", x, y, 0.72, x + 1.6, y + 0.8, 0.75)
        box("desk", x, y, 0, x + 0.03, y + 0.8, 0.72)
        box("desk", x + 1.57, y, 0, x + 1.6, y + 0.8, 0.72)
        box("desk", x + 0.03, y + 0.75, 0.3, x + 1.57, y + 0.78, 0.72)
        box("screen", x + 0.5, y + 0.6, 0.85, x + 1.1, y + 0.63, 1.2)
        box("chrome", x + 0.77, y + 0.62, 0.75, x + 0.83, y + 0.66, 0.85)
        cx, cy = x + 0.8, y - 0.35
        box("fabric", cx - 0.25, cy - 0.25, 0.45, cx + 0.25, cy + 0.25, 0.52)
        box("fabric", cx - 0.23, cy - 0.3, 0.55, cx + 0.23, cy - 0.26, 1.0)
        cylinder("chrome", cx, cy, 0.1, 0.45, 0.03, 12)
        for s in range(5):
            a = 2 * math.pi * s / 5
            ex, ey = cx + 0.3 * math.cos(a), cy + 0.3 * math.sin(a)
            nx_, ny_ = -0.015 * math.sin(a), 0.015 * math.cos(a)
            polygon("chrome", [(cx + nx_, cy + ny_, 0.1), (ex + nx_, ey + ny_, 0.08),
                               (ex - nx_, ey - ny_, 0.08), (cx - nx_, cy - ny_, 0.1)])
            sphere("chrome", ex, ey, 0.035, 0.035, 6, 10)

# Plants along the windows: a pot and a dense tessellated crown.
for k in range(20):
    for y in (0.6, D - 0.6):
        x = 1.0 + 2.0 * k
        cylinder("pot", x, y, 0, 0.4, 0.2, 16)
        sphere("leaf", x, y, 0.9, 0.45, 24, 48)

print("".join(out), end="")
