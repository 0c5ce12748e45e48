#!/usr/bin/env python3
# Generates the tensor-tree BSDF and aBSDF cases (tests/data/bsdf_tree/) for
# tests/direct/direct_matrix_test.cpp, with REAL Radiance 5.4a's answers. A
# developer's tool: it needs ../shared/reference/radiance-5.4a (or
# RADIANCE=<its folder>); the test only reads what this writes. Same
# expected.txt format as generate.py (see there); the conventions (groups,
# "exact" and "noise" checks, repeats, DET) are generate_bsdf.py's.
#
#   tests/direct/generate_bsdf_tree.py
#
# The BSDF files are written here too, as variable-resolution tensor trees
# (IncidentDataStructure TensorTree3 / TensorTree4, AngleBasis
# LBNL/Shirley-Chiu, libBSDF's bsdf_t.c), built from functions of the cell
# centres and written with variable depth: constant leaves, grid leaves of
# 2 and 4 per dimension, and branches down to the finest level where the
# function varies (the peaks):
#   tt4_glaze.xml    TensorTree4: a straight-through peak in the finest cells
#                    over a Lambertian floor, both sides different;
#                    reflection on either side with a broad lobe around the
#                    mirror direction (Radiance's front one with a mirror
#                    peak too); Solar blocks (first, and different) that
#                    Radiance skips.
#   tt4_redirect.xml TensorTree4: transmission sent toward +y, stronger for
#                    light from +x (so the up vector and which of the two
#                    directions is the incident one matter), given for one
#                    side only (reciprocity for the other); a front
#                    reflection that depends on both directions.
#   tt3_gloss.xml    TensorTree3 (isotropic): a glossy reflection lobe
#                    around the mirror direction on either side, and a broad
#                    transmitted lobe around the straight-through direction;
#                    the unused half of the first coordinate holds zeros.
#                    The lobes' directional-hemispherical values straddle
#                    -st 0.15 (m_bsdf.c samples a component only above it,
#                    direction by direction).
#   tt4_clear.xml    TensorTree4: nothing but a strong straight-through peak
#                    (aBSDF's through component).
#   err_*.xml        a leaf of 5 values, a missing '}', an unknown AngleBasis,
#                    characters after the tree, an unknown
#                    IncidentDataStructure.
# How Radiance 5.4a reads them (bsdf_t.c's SDqueryTre as m_bsdf.c calls it;
# check_trees() below confirms it on every block: --check): the tree's
# incident direction `in` is the one toward the VIEWER (the reversed ray),
# `out` the one toward the light, both in the BSDF frame (z the surface
# normal, y the up vector). Reflection uses the block of the viewer's side,
# transmission the block given for light arriving on the viewer's side
# (WINDOW's front is Radiance's back: "Transmission Back" and "Reflection
# Back" for a viewer in front); where only the other side's transmission is
# given, that block with the two exchanged (`in` toward the light).
# TensorTree4's dimensions 0, 1 are the Shirley-Chiu square of
# (-in.x, -in.y), 2, 3 that of (out.x, out.y): the straight-through and the
# mirror direction both lie where the two squares agree. TensorTree3's
# dimension 0 is 0.5 - 0.5 sin(theta_in) (only [0, 0.5) used), 1, 2 the
# square of `out` turned about z so that (-in.x, -in.y) lies along +x.
# Values list dimension 0 slowest; branch child n holds the upper half of
# dimension i where bit i of n is set.
# Covers: each file on a plane under five kinds of source, seen from both
# sides; up vectors (constant, from the position); aBSDF's through peak for
# view and shadow rays; a BSDF proxy with detail behind it; -i; the sampled
# rays at -ss 1 and 4 (means of repeats under a sky that colours every
# direction); the direct light's view jitter at -ss 1 and 2 over a tree
# whose resolution differs between the two directions (tt4_varres.xml,
# also over 100 % front reflection: Radiance's warning); -ab 1; load errors.
import itertools
import math
import os
import random
import subprocess
import sys
import tempfile

from generate_aniso import LAMPS, PLANE, SKY
from generate_bsdf import material
from generate_patterns import BIN, ENV, radiance
from matrix_data import LIT_BOX, fresh_folder, run_and_write

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
OUT = os.path.join(ROOT, "tests", "data", "bsdf_tree")
# -ss 0: no jitter of the view direction, and a sampled ray's direction
# fixed (up to libBSDF's finest cell): deterministic.
DET = "-u- -dj 0 -dt 0 -ss 0"


# --- Shirley-Chiu square <-> disk (libBSDF's SDsquare2disk, SDdisk2square)

def square2disk(sx, sy):
    a, b = 2 * sx - 1, 2 * sy - 1
    if a > -b:
        if a > b:
            r, phi = a, math.pi / 4 * (b / a)
        else:
            r, phi = b, math.pi / 4 * (2 - a / b)
    else:
        if a < b:
            r, phi = -a, math.pi / 4 * (4 + b / a)
        else:
            r = -b
            phi = math.pi / 4 * (6 - a / b) if b != 0 else 0.0
    return r * math.cos(phi), r * math.sin(phi)


def disk2square(x, y):
    r = math.hypot(x, y)
    phi = math.atan2(y, x)
    if phi < -math.pi / 4:
        phi += 2 * math.pi
    if phi < math.pi / 4:
        a = r
        b = phi * a / (math.pi / 4)
    elif phi < 3 * math.pi / 4:
        b = r
        a = -(phi - math.pi / 2) * b / (math.pi / 4)
    elif phi < 5 * math.pi / 4:
        a = -r
        b = (phi - math.pi) * a / (math.pi / 4)
    else:
        b = -r
        a = -(phi - 3 * math.pi / 2) * b / (math.pi / 4)
    return (a + 1) / 2, (b + 1) / 2


# --- Trees: a function on the finest grid, written with variable depth

def fmt(v):
    return "%.5g" % v if v > 0 else "0"


def cell_disks(level):
    """Disk point (x, y) of the centre of each square cell at `level`, by
    index i*n + j (i along the square's x)."""
    n = 1 << level
    return [square2disk((i + .5) / n, (j + .5) / n) for i in range(n) for j in range(n)]


def tree_text(values, dims, level, sep=" ", close=""):
    """The tree of `values` (strings, one per finest cell, dimension 0
    slowest, 2**level cells per dimension): a constant leaf where a node's
    cells are all equal; else of a grid leaf of 2 or 4 per dimension (where
    that holds them exactly) and branches, the shorter. `close` follows
    each '}'."""
    # uni[k][block]: the value of every finest cell in the block, or None.
    uni = [None] * (level + 1)
    uni[level] = values
    for k in range(level - 1, -1, -1):
        n, fine, child = 1 << k, uni[k + 1], 1 << (k + 1)
        offs = []
        for bits in range(1 << dims):
            o = 0
            for i in range(dims):
                o = o * child + ((bits >> i) & 1)
            offs.append(o)
        row = []
        for b in itertools.product(range(n), repeat=dims):
            base = 0
            for c in b:
                base = base * child + 2 * c
            v = fine[base + offs[0]]
            if v is not None:
                for o in offs[1:]:
                    if fine[base + o] != v:
                        v = None
                        break
            row.append(v)
        uni[k] = row

    def index(k, b):
        i = 0
        for c in b:
            i = i * (1 << k) + c
        return i

    def node(k, b):
        """(number of tokens, text) of the shortest form of this node."""
        v = uni[k][index(k, b)]
        if v is not None:
            return 3, "{" + v + "}" + close
        best = None
        for r in (1, 2):
            if k + r > level:
                break
            res = 1 << r
            cells = [uni[k + r][index(k + r, [bi * res + ci for bi, ci in zip(b, c)])]
                     for c in itertools.product(range(res), repeat=dims)]
            if None not in cells:
                best = (len(cells) + 2, "{" + sep.join(cells) + "}" + close)
                break
        if best is None or best[0] > 2 + 3 * (1 << dims):
            kids = [node(k + 1, [2 * bi + ((n >> i) & 1) for i, bi in enumerate(b)])
                    for n in range(1 << dims)]
            cost = 2 + sum(c for c, _ in kids)
            if best is None or cost < best[0]:
                best = (cost, "{\n" + "\n".join(t for _, t in kids) + "\n}" + close)
        return best

    return node(0, [0] * dims)[1]


def tt4(level, f):
    """TensorTree4 values: f(u, v, iu, iv) at each finest cell, u the disk
    point of (-in.x, -in.y), v that of (out.x, out.y), iu, iv the square
    cells' indices (i*n + j)."""
    disks = cell_disks(level)
    m = len(disks)
    return [fmt(f(disks[iu], disks[iv], iu, iv)) for iu in range(m) for iv in range(m)]


def tt3(level, f):
    """TensorTree3 values: f(s, i0, v, iv) at each finest cell, s =
    sin(theta_in) and i0 its cell's index, v the disk point of `out` turned
    so that (-in.x, -in.y) lies along +x and iv its square cell's index;
    zeros in the unused half of dimension 0."""
    n = 1 << level
    disks = cell_disks(level)
    vals = []
    for i0 in range(n):
        s = 1 - 2 * (i0 + .5) / n
        vals += [fmt(f(s, i0, v, iv)) if s > 0 else "0" for iv, v in enumerate(disks)]
    return vals


def lobe(d, width, cut):
    return math.exp(-(d / width) ** 2) if d < cut else 0.0


def coarse(level, fine_level):
    """Index map from a finest square cell to its ancestor at `level`."""
    n, shift = 1 << fine_level, fine_level - level
    return [((i // n) >> shift) * (1 << level) + ((i % n) >> shift) for i in range(n * n)]


def window_xml(structure, blocks, basis="LBNL/Shirley-Chiu"):
    """blocks: [(wavelength, WINDOW direction, tree text)]."""
    s = ['<?xml version="1.0" encoding="UTF-8"?>',
         '<WindowElement xmlns="http://windows.lbl.gov" version="1.1">',
         '<WindowElementType>System</WindowElementType>', '<Optical>', '<Layer>',
         '<Material><Name>test</Name><Thickness unit="Millimeter">6</Thickness></Material>',
         '<DataDefinition>', f'<IncidentDataStructure>{structure}</IncidentDataStructure>',
         '</DataDefinition>']
    for wavelength, direction, tree in blocks:
        s += ['<WavelengthData>', '<LayerNumber>System</LayerNumber>',
              f'<Wavelength unit="Integral">{wavelength}</Wavelength>',
              '<WavelengthDataBlock>',
              f'<WavelengthDataDirection>{direction}</WavelengthDataDirection>',
              f'<AngleBasis>{basis}</AngleBasis>',
              '<ScatteringDataType>%s</ScatteringDataType>' % (
                  "BRDF" if direction.startswith("Reflection") else "BTDF"),
              '<ScatteringData>', tree, '</ScatteringData>',
              '</WavelengthDataBlock>', '</WavelengthData>']
    s += ['</Layer>', '</Optical>', '</WindowElement>']
    return "\n".join(s) + "\n"


def dist(u, v):
    return math.hypot(u[0] - v[0], u[1] - v[1])


def glaze_trees():
    L = 5  # finest cells 1/32: branches to depth 4, then grids of 2
    n = 1 << L
    ohm = math.pi / (n * n)  # projected solid angle of a finest square cell
    up3 = coarse(3, L)
    d3 = cell_disks(3)

    def through(tau, floor):
        def f(u, v, iu, iv):
            r2 = u[0] ** 2 + u[1] ** 2
            return floor + (tau * (1 - 0.6 * r2 * r2) / ohm if iu == iv else 0.0)
        return f

    def mirror(floor, amp, width, peak):
        def f(u, v, iu, iv):
            val = floor + amp * lobe(dist(d3[up3[iu]], d3[up3[iv]]), width, 2.5 * width)
            return val + (peak / ohm if peak and iu == iv else 0.0)
        return f

    return {
        "Transmission Front": tt4(L, through(0.55, 0.02)),
        "Transmission Back": tt4(L, through(0.45, 0.03)),
        "Reflection Front": tt4(L, mirror(0.05, 0.5, 0.35, 0.0)),
        "Reflection Back": tt4(L, mirror(0.04, 1.2, 0.25, 0.06)),
    }


def redirect_trees():
    L = 4
    up2, up3 = coarse(2, L), coarse(3, L)
    d2, d3 = cell_disks(2), cell_disks(3)

    def xmit(u, v, iu, iv):
        # Toward +y (out), more of it for light from +x (in = -u).
        vy = d3[up3[iv]][1]
        return 0.01 + 1.2 * (1 - 0.5 * d2[up2[iu]][0]) * max(0.0, vy) ** 2

    def refl(u, v, iu, iv):
        ux, vx = d2[up2[iu]][0], d2[up2[iv]][0]
        return 0.03 + 0.12 * (1 + ux) * (1.2 + vx)

    return {"Transmission Back": tt4(L, xmit), "Reflection Back": tt4(L, refl)}


def gloss_trees():
    L, lv = 6, 4  # the glossy lobe at the finest level, the broad ones at 1/16
    up = coarse(lv, L)
    dl = cell_disks(lv)
    shift = L - lv

    def glossy(floor, amp, width):
        return lambda s, i0, v, iv: floor + amp * lobe(dist(v, (s, 0.0)), width, 2.5 * width)

    def broad(floor, amp, width):
        def f(s, i0, v, iv):
            sc = 1 - 2 * ((i0 >> shift) + .5) / (1 << lv)  # s at 1/16 too
            return floor + amp * (1 - 0.5 * sc) * lobe(dist(dl[up[iv]], (sc, 0.0)), width,
                                                      2.5 * width)
        return f

    return {
        "Reflection Back": tt3(L, glossy(0.03, 8.0, 0.12)),
        "Reflection Front": tt3(L, broad(0.06, 1.0, 0.3)),
        "Transmission Front": tt3(L, broad(0.04, 0.7, 0.35)),
        "Transmission Back": tt3(L, broad(0.05, 0.6, 0.45)),
    }


def clear_trees():
    L = 5
    ohm = math.pi / (1 << 2 * L)
    f = lambda u, v, iu, iv: 0.8 / ohm if iu == iv else 0.0  # noqa: E731
    t = tt4(L, f)
    return {"Transmission Front": t, "Transmission Back": t}


def varres_tree():
    """A reflection tree three levels deep where both incident coordinates
    are in their lower half and shallower elsewhere, random values 0.05 to
    0.65 (seeded: the same file every time)."""
    rng = random.Random(5)

    def leaf(values):
        return "{ " + " ".join("%.4g" % v for v in values) + " }"

    def node(depth):
        if depth >= 3:
            return leaf([0.05 + rng.random() * 0.6])
        kids = []
        for n in range(16):
            if (n & 3) == 0 and rng.random() < 0.8:
                kids.append(node(depth + 1))
            elif rng.random() < 0.3:
                kids.append(leaf([0.05 + rng.random() * 0.6 for _ in range(16)]))
            else:
                kids.append(leaf([0.05 + rng.random() * 0.6]))
        return "{ " + " ".join(kids) + " }"
    return node(0)


def write_trees(write):
    """Writes the four tree files."""
    glaze = glaze_trees()
    glaze_text = {k: tree_text(v, 4, 5) for k, v in glaze.items()}
    # Solar blocks first, scaled and coarser: Radiance reads Visible only.
    solar = {k: tree_text([fmt(0.8 * float(x)) for x in v], 4, 5)
             for k, v in glaze.items() if k.startswith("Transmission")}
    write("tt4_glaze.xml", window_xml("TensorTree4", [("Solar", k, t) for k, t in solar.items()] +
                                      [("Visible", k, t) for k, t in glaze_text.items()]))
    redirect = {k: tree_text(v, 4, 4, sep=", ", close=",") for k, v in redirect_trees().items()}
    write("tt4_redirect.xml", window_xml("TensorTree4",
                                         [("Visible", k, t) for k, t in redirect.items()]))
    gloss = {k: tree_text(v, 3, 6, sep=", ") for k, v in gloss_trees().items()}
    write("tt3_gloss.xml", window_xml("TensorTree3", [("Visible", k, t) for k, t in gloss.items()]))
    clear = {k: tree_text(v, 4, 5) for k, v in clear_trees().items()}
    write("tt4_clear.xml", window_xml("TensorTree4", [("Visible", k, t) for k, t in clear.items()]))


# --- Reading the files back (check_trees)

def parse_tree(text):
    """Nested lists: a branch is a list of 2**D nodes, a leaf a tuple of values."""
    tokens = text.replace(",", " ").replace("{", " { ").replace("}", " } ").split()
    pos = 0

    def node():
        nonlocal pos
        assert tokens[pos] == "{"
        pos += 1
        if tokens[pos] == "{":
            kids = []
            while tokens[pos] == "{":
                kids.append(node())
            assert tokens[pos] == "}"
            pos += 1
            return kids
        vals = []
        while tokens[pos] != "}":
            vals.append(max(0.0, float(tokens[pos])))
            pos += 1
        pos += 1
        return tuple(vals)

    tree = node()
    assert pos == len(tokens)
    return tree


def lookup(tree, pos, dims):
    """bsdf_t.c's SDlookupTre."""
    pos = list(pos)
    while isinstance(tree, list):
        n = 0
        for i in range(dims):
            t = 1 if 2 * pos[i] >= 1 else 0
            n |= t << i
            pos[i] = 2 * pos[i] - t
        tree = tree[n]
    res = round(len(tree) ** (1 / dims))
    index = 0
    for p in pos:
        index = index * res + int(res * p)
    return tree[index]


def tree_value(tree, dims, vin, vout):
    """The tree's value for `vin` toward the light, `vout` toward the viewer
    (local frame), as bsdf_t.c's SDqueryTre reads them."""
    if dims == 4:
        return lookup(tree, disk2square(-vin[0], -vin[1]) + disk2square(vout[0], vout[1]), 4)
    a = -math.atan2(-vin[1], -vin[0])
    rx = vout[0] * math.cos(a) - vout[1] * math.sin(a)
    ry = vout[0] * math.sin(a) + vout[1] * math.cos(a)
    return lookup(tree, ((.5 - 1e-6) - .5 * math.hypot(vin[0], vin[1]),) +
                  disk2square(rx, ry), 3)


def unit(v):
    n = math.sqrt(sum(c * c for c in v))
    return tuple(c / n for c in v)


def check_trees(out=OUT):
    """Reads each tree file back (its Visible blocks) and compares real
    Radiance's direct light on a plane (normal +z, up +y: the BSDF frame is
    the world's) from a distant source with L * omega * cos * f, f the
    tree's value at the cell the two directions select as Radiance 5.4a
    reads it: the block given for light arriving on the VIEWER's side, its
    `in` the direction toward the viewer and `out` that toward the light;
    for transmission given for the other side only, that block with `in`
    toward the light (reciprocity). Also the physical reading (the light's
    side picks the block, `in` toward the light), to show the difference."""
    import random
    import xml.etree.ElementTree as ET
    rng = random.Random(7)
    ns = {"w": "http://windows.lbl.gov"}
    # WINDOW direction of the block for light arriving on a side (+1: Radiance's front).
    refl = {1: "Reflection Back", -1: "Reflection Front"}
    xmit = {1: "Transmission Back", -1: "Transmission Front"}
    omega = 2 * math.pi * (1 - math.cos(math.radians(0.25)))  # a 0.5 degree source

    def pick(blocks, first, second, here, there):
        """(tree, in, out): the block for light arriving on `here`'s side."""
        if first in blocks:
            return blocks[first], here, there
        if second and second in blocks:
            return blocks[second], there, here
        return None, here, there

    worst = {}
    with tempfile.TemporaryDirectory() as tmp:
        for name in ("tt4_glaze.xml", "tt4_redirect.xml", "tt3_gloss.xml", "tt4_clear.xml"):
            root = ET.parse(os.path.join(out, name)).getroot()
            dims = 3 if root.find(".//w:IncidentDataStructure", ns).text == "TensorTree3" else 4
            blocks = {}
            for wd in root.iter("{http://windows.lbl.gov}WavelengthData"):
                if wd.find("w:Wavelength", ns).text != "Visible":
                    continue
                b = wd.find("w:WavelengthDataBlock", ns)
                blocks[b.find("w:WavelengthDataDirection", ns).text] = parse_tree(
                    b.find("w:ScatteringData", ns).text)
            for ls, vs in ((1, 1), (-1, -1), (1, -1), (-1, 1)):
                for trial in range(3):
                    z = rng.uniform(0.2, 1)
                    a = rng.uniform(0, 2 * math.pi)
                    s = math.sqrt(1 - z * z)
                    light = (s * math.cos(a), s * math.sin(a), ls * z)
                    views = [(-light[0], -light[1], vs * abs(light[2]))]  # peak or mirror
                    for _ in range(7):
                        z = rng.uniform(0.15, 1)
                        a = rng.uniform(0, 2 * math.pi)
                        s = math.sqrt(1 - z * z)
                        views.append((s * math.cos(a), s * math.sin(a), vs * z))
                    scene = os.path.join(tmp, "s.rad")
                    with open(scene, "w") as f:
                        f.write("void light sun 0 0 3 100 100 100\n"
                                "sun source s 0 0 4 %r %r %r 0.5\n" % light +
                                material("BSDF", os.path.join(out, name)) + "m " + PLANE)
                    rays = "".join("%r %r %r %r %r %r\n" % (
                        5 * v[0], 5 * v[1], 5 * v[2], -v[0], -v[1], -v[2]) for v in views)
                    oct_ = os.path.join(tmp, "s.oct")
                    with open(oct_, "wb") as f:
                        subprocess.run([os.path.join(BIN, "oconv"), scene], stdout=f, check=True,
                                       env=ENV, cwd=out)
                    r = subprocess.run([os.path.join(BIN, "rtrace"), "-h", "-ab", "0"] +
                                       DET.split() + [oct_], input=rays, capture_output=True,
                                       text=True, env=ENV, cwd=out, check=True)
                    got = [float(line.split()[0]) for line in r.stdout.splitlines()]
                    for v, g in zip(views, got):
                        if ls == vs:
                            kind, first, second = "reflection", refl[vs], None
                            phys = (refl[ls], None)
                        else:
                            kind, first, second = "transmission", xmit[vs], xmit[-vs]
                            phys = (xmit[ls], xmit[-ls])
                        for reading, (tree, vin, vout) in (
                                ("radiance", pick(blocks, first, second, v, light)),
                                ("physical", pick(blocks, *phys, light, v))):
                            want = 0.0 if tree is None else (
                                100 * omega * abs(light[2]) * tree_value(tree, dims, vin, vout))
                            err = abs(g - want) / max(abs(want), abs(g), 1e-9)
                            k = (name, f"{kind} light {'front' if ls > 0 else 'back'}", reading)
                            worst[k] = max(worst.get(k, 0.0), err)
                            if v is views[0] and reading == "radiance":
                                print(f"{name} {k[1]}: toward {light[0]:.3f} {light[1]:.3f} "
                                      f"{light[2]:.3f}, viewed from the peak: Radiance {g:.5g}, "
                                      f"tree {want:.5g}", file=sys.stderr)
    for k, err in sorted(worst.items()):
        print("%-17s %-30s %-8s reading: worst relative difference %.1e" % (k + (err,)),
              file=sys.stderr)


def main():
    write = fresh_folder(OUT)
    runs = []  # (group, name, files, rays, repeat, options, check)
    write_trees(write)
    # Load errors: the value count of a leaf, a missing '}', an unknown
    # angle basis, characters after the tree, an unknown structure.
    small = tree_text([fmt(0.1 + 0.01 * i) for i in range(256)], 4, 2)
    write("err_count.xml", window_xml("TensorTree4", [
        ("Visible", "Transmission Front", "{ {.1 .2 .3 .4 .5} " + "{.1} " * 15 + "}")]))
    write("err_brace.xml", window_xml("TensorTree4", [
        ("Visible", "Transmission Front", small[:-1])]))
    write("err_basis.xml", window_xml("TensorTree4", [("Visible", "Transmission Front", small)],
                                      basis="LBNL/Klems Full"))
    write("err_extra.xml", window_xml("TensorTree4", [
        ("Visible", "Transmission Front", small + " {.2}")]))
    write("err_structure.xml", window_xml("TensorTree5", [
        ("Visible", "Transmission Front", small)]))

    # As generate_bsdf.py's, and (last) one each the sun's mirror and
    # straight-through direction.
    write("down.rays", "1 2 5 0.6 0 -0.8\n0 0 5 0 0 -1\n-3 4 2 0.3 -0.2 -1\n"
                       "2.5 -1 7 0 0 -1\n0.2 0.3 5 -0.1 -0.15 -1\n3 3 2 -0.6 -0.6 -0.5\n"
                       "-1 -1 4 0.3 0.2 -1\n")
    write("up.rays", "1 2 -5 0 0 1\n-1 0.5 -3 0.2 0.1 1\n0.6 0.6 -2 0.2 0.2 1\n"
                     "-0.8 -0.6 -4 0.3 0.28 1\n0.5 -0.5 -3 0.3 0.2 1\n")
    # Straight through the plane at the centre of the sphere lamp (from
    # below) and of the lamp below (from above), and beside them.
    through = []
    for centre, hit in (((1, 1, 4), (0.2, -0.3, 0)), ((1, 1, 4), (1.4, 0.6, 0)),
                        ((-1, .5, -4), (0.3, 0.2, 0)), ((-1, .5, -4), (-1.2, 1.1, 0))):
        d = [c - h for c, h in zip(centre, hit)]
        through.append(" ".join("%g" % x for x in [h - k for h, k in zip(hit, d)] + d))
    through += ["0.2 -0.3 -4 0.83 1.3 4", "0.3 0.2 4 -1.3 0.33 -4"]
    write("through.rays", "\n".join(through) + "\n")
    below = "void light under 0 0 3 80 80 80\nunder sphere ubulb 0 0 4 -1 .5 -4 .5\n"
    big = "void light lamp 0 0 3 10 10 10\nlamp sphere bulb 0 0 4 1 1 4 1.5\n"
    lamps = dict(LAMPS, below=below, big=big)

    # 1. Each file on a plane under each kind of source, seen from both sides
    # (tt4_redirect has no reflection for Radiance's back: black from below
    # with the lamp below).
    for body in ("tt4_glaze", "tt4_redirect", "tt3_gloss"):
        for lamp in lamps:
            name = f"{body[4:]}_{lamp}"
            write(f"plane_{name}.rad", lamps[lamp] + material("BSDF", f"{body}.xml") +
                  "m " + PLANE)
            for side in ("down", "up"):
                runs.append(("treeplane", f"{name}_{side}", [f"plane_{name}.rad"],
                             f"{side}.rays", 1, DET, "exact"))
    # Straight through at two lamps, one on either side.
    write("plane_clear_both.rad", lamps["sphere"] + below + material("BSDF", "tt4_clear.xml") +
          "m " + PLANE)
    write("plane_glaze_both.rad", lamps["sphere"] + below + material("BSDF", "tt4_glaze.xml") +
          "m " + PLANE)
    for body in ("clear", "glaze"):
        runs.append(("treeplane", f"{body}_through", [f"plane_{body}_both.rad"], "through.rays",
                     1, DET, "exact"))
    # 2. Up vectors other than +y on the redirecting file: constant, from the
    # position (its reflection seen from above, its transmission from below
    # and above).
    for key, up in {"x": "1 0 0 .", "position": "Py 1+Px 0 ."}.items():
        for lamp, side in (("sphere", "down"), ("sphere", "up"), ("below", "down")):
            name = f"{key}_{lamp}"
            write(f"up_{name}.rad", lamps[lamp] + material("BSDF", "tt4_redirect.xml", up) +
                  "m " + PLANE)
            runs.append(("treeup", f"{name}_{side}", [f"up_{name}.rad"], f"{side}.rays", 1,
                         DET, "exact"))
    # 3. aBSDF's through peak (view rays and shadow rays pass it), a proxy
    # with detail behind it, -i.
    floor = "void plastic grey 0 0 5 .6 .6 .6 0 0\ngrey polygon floor 0 0 12 " \
            "-10 -10 -2  10 -10 -2  10 10 -2  -10 10 -2\n"
    detail = "void plastic red 0 0 5 .7 .2 .1 0 0\nred polygon slat 0 0 12 " \
             "-10 -10 -.03  10 -10 -.03  10 10 -.03  -10 10 -.03\n"
    cases = {
        "absclear": (LAMPS["sphere"] + material("aBSDF", "tt4_clear.xml") + "m " + PLANE + floor,
                     "down.rays"),
        "absclear_up": (big + material("aBSDF", "tt4_clear.xml") + "m " + PLANE, "up.rays"),
        "absclear_through": (lamps["sphere"] + below + material("aBSDF", "tt4_clear.xml") +
                             "m " + PLANE, "through.rays"),
        "absglaze": (big + material("aBSDF", "tt4_glaze.xml") + "m " + PLANE + floor,
                     "down.rays"),
        "absglaze_up": (big + material("aBSDF", "tt4_glaze.xml") + "m " + PLANE, "up.rays"),
        "absgloss": (big + material("aBSDF", "tt3_gloss.xml") + "m " + PLANE + floor,
                     "down.rays"),
        "proxy": (LAMPS["sphere"] + material("BSDF", "tt4_glaze.xml", thick=".05") + "m " +
                  PLANE + detail + floor, "down.rays"),
        "proxy_neg": (below + material("BSDF", "tt4_glaze.xml", thick="-.05") + "m " + PLANE +
                      detail.replace("-.03", ".03") + floor, "up.rays"),
    }
    for name, (text, rays) in cases.items():
        write(f"kind_{name}.rad", text)
        runs.append(("treekinds", name, [f"kind_{name}.rad"], rays, 1, DET, "exact"))
    runs.append(("treekinds", "irradiance_proxy", ["kind_proxy.rad"], "down.rays", 1,
                 DET + " -i", "exact"))
    runs.append(("treekinds", "irradiance_abs", ["kind_absglaze.rad"], "down.rays", 1,
                 DET + " -i", "exact"))

    # 4. The sampled rays: means of repeats under a sky whose colour encodes
    # the direction, a BSDF above an aBSDF.
    write("sky_rays.rays", "0 0 2 0.5 0 -1\n1 1 2 -0.2 0.3 -1\n0 0 -1 0 0.3 1\n"
                           "0 0 -5 0.2 0 1\n0 0 1 0.98 0 -0.17\n0 0 -1 0 -0.3 1\n")
    for body in ("tt4_glaze", "tt4_redirect", "tt3_gloss"):
        write(f"sky_{body[4:]}.rad", SKY + material("BSDF", f"{body}.xml") + "m " + PLANE +
              material("aBSDF", "tt4_glaze.xml") +
              "m polygon p2 0 0 12 -10 -10 -3  10 -10 -3  10 10 -3  -10 10 -3\n")
        for ss in ("1", "4"):
            runs.append(("treesampled", f"{body[4:]}_ss{ss}", [f"sky_{body[4:]}.rad"],
                         "sky_rays.rays", 300, f"-u+ -dj 0 -dt 0 -ss {ss}", "noise"))
    # Near the -lw limit (-lr 8: no Russian roulette) the first of -ss 4's
    # rays is refused, and Radiance starts again with fewer, heavier ones.
    runs.append(("treesampled", "glaze_lw", ["sky_glaze.rad"], "sky_rays.rays", 300,
                 "-u+ -dj 0 -dt 0 -ss 4 -lr 8 -lw 0.2", "noise"))
    # 5. -ab 1 without a cache: the box's top a tensor-tree window, its lamp
    # above.
    window = LIT_BOX.replace("wall polygon ceiling", "win polygon ceiling").replace(
        "void light l 0 0 3 20 20 20\nl sphere bulb 0 0 4 0 0 1.5 .2\n",
        "void light l 0 0 3 200 200 200\nl sphere bulb 0 0 4 .5 .3 4 .4\n")
    write("ab1.rays", "0.3 0.2 1 0 0 -1\n-0.5 0.4 1 0.2 0 -1\n0 0 0 0 0 1\n")
    for body in ("tt4_glaze", "tt3_gloss"):
        write(f"ab1_{body[4:]}.rad", window.replace(
            "void plastic wall", material("BSDF", f"{body}.xml").replace(" m ", " win ") +
            "void plastic wall"))
        runs.append(("treeab1", f"window_{body[4:]}", [f"ab1_{body[4:]}.rad"], "ab1.rays", 48,
                     "-u+ -ab 1 -aa 0 -ad 512 -as 0", "noise"))
    # The glazing's peak makes the lamp's light through it rare and strong
    # (a noisy mean); the same window under the sky alone, no lamp.
    write("ab1_glaze_sky.rad", SKY + LIT_BOX.replace(
        "wall polygon ceiling", "win polygon ceiling").replace(
        "void light l 0 0 3 20 20 20\nl sphere bulb 0 0 4 0 0 1.5 .2\n", "").replace(
        "void plastic wall", material("BSDF", "tt4_glaze.xml").replace(" m ", " win ") +
        "void plastic wall"))
    runs.append(("treeab1", "window_glaze_sky", ["ab1_glaze_sky.rad"], "ab1.rays", 48,
                 "-u+ -ab 1 -aa 0 -ad 512 -as 0", "noise"))
    # 5b. The direct light's view jitter at -ss 2 over a reflection tree
    # whose cells are finer where the incident coordinates are low: which
    # direction sizes the view's cell (Radiance 5.4a: the view's, as the
    # incident one) decides the jitter's width and which samples count.
    write("tt4_varres.xml", window_xml("TensorTree4", [
        ("Visible", "Reflection Back", varres_tree())]))
    write("jitter.rad", "void light lamp 0 0 3 1000 1000 1000\nlamp sphere bulb 0 0 4 1 2 5 .3\n" +
          material("BSDF", "tt4_varres.xml") + "m " + PLANE)
    write("jitter.rays", "1 2 5 0.6 0.1 -0.8\n-3 4 2 0.3 -0.2 -1\n2.5 -1 7 -0.1 0.3 -1\n"
                         "0 0 3 0.2 0.5 -1\n")
    for ss in ("1", "2"):
        runs.append(("treejitter", f"varres_ss{ss}", ["jitter.rad"], "jitter.rays", 300,
                     f"-u+ -dj 0 -dt 0 -ss {ss} -st 1", "noise"))
    # 6. Errors in the files: fatal, nothing written.
    for name in ("count", "brace", "basis", "extra", "structure"):
        write(f"error_{name}.rad", LAMPS["sphere"] + material("BSDF", f"err_{name}.xml") +
              "m " + PLANE)
        runs.append(("treeerror", name, [f"error_{name}.rad"], "down.rays", 1, DET, "exact"))

    # lazyrad's side of the noise runs: 64 repeats, not 16. The sampled
    # peaks give heavy-tailed outputs, whose standard error 16 repeats
    # estimate too low: glaze_ss4's second ray, 16 repeats 3 standard
    # errors from Radiance's mean with an estimate half the true one, where
    # 3000 repeats of each program agree within 2.
    run_and_write(runs, radiance, OUT,
                  "# Real Radiance 5.4a's answers for the tensor-tree BSDF and aBSDF\n"
                  "# cases of tests/direct/direct_matrix_test.cpp, written by\n"
                  "# tests/direct/generate_bsdf_tree.py (format as in generate.py).\n",
                  lazy_noise_repeat=64)
    if "--check" in sys.argv[1:]:
        check_trees()


if __name__ == "__main__":
    main()
