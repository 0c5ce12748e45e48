#!/usr/bin/env python3
# Generates the text pattern cases (tests/data/text/) for
# tests/direct/direct_matrix_test.cpp, with REAL Radiance 5.4a's answers. A
# developer's tool: it needs ../shared/reference/radiance-5.4a (or
# RADIANCE=<its folder>); the test only reads what this writes. Same
# expected.txt format as generate.py (see there).
#
#   tests/direct/generate_text.py
#
# Covers brighttext, colortext and mixtext (Radiance's text.c and font.c)
# with a small font of our own (block.fnt, written here: Radiance's fonts
# are not ours to ship): uniform, proportional and squeezed spacing, a
# spacing argument of 0 (cells of the font's mean width), one line of words
# and a text file of several lines (an empty one, characters without
# glyphs, glyphs followed by two, three and four spaces), right and down
# vectors skewed, of other lengths and out of the plane, glyphs with holes,
# slanted edges and extents inside one half of the cell, characters the
# font lacks, on a light seen straight and on plastic under a lamp, a
# mixtext of two lights, of a pattern and void, the pattern inside an
# instance and on a distant source, and the load errors. Each case traces
# a grid of rays over the text at -ab 0, so every answer is exact.
import os
import subprocess

from generate_patterns import BIN, ENV, radiance
from matrix_data import fresh_folder, run_and_write

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
OUT = os.path.join(ROOT, "tests", "data", "text")
DET = "-u- -dj 0 -dt 0"

# code, vertices (x y, 0-255, y up). 'O' has a hole joined to the outside by
# a doubled edge; 'A' and 'V' have slanted edges; '.' and ''' lie in one half
# of the cell, so their extents (which Radiance starts at 128) are wider than
# they are; the space has no vertices.
FONT = {
    32: [],
    73: [100, 0, 155, 0, 155, 255, 100, 255],                                   # I
    79: [20, 0, 235, 0, 235, 255, 20, 255, 20, 0, 80, 60, 80, 200, 175, 200,
         175, 60, 80, 60],                                                        # O
    65: [0, 0, 255, 0, 128, 255],                                                 # A
    86: [0, 255, 70, 255, 128, 70, 186, 255, 255, 255, 150, 0, 106, 0],          # V
    46: [40, 0, 90, 0, 90, 50, 40, 50],                                           # .
    39: [150, 180, 200, 180, 200, 255, 150, 255],                                 # '
    76: [30, 0, 200, 0, 200, 40, 80, 40, 80, 255, 30, 255],                      # L
    45: [20, 100, 140, 100, 140, 150, 20, 150],                                   # -
}

LIGHT = "light bright 0 0 3 2 2 2\n"
PLANE = "polygon p 0 0 12 -1 -6 0  14 -6 0  14 3 0  -1 3 0\n"
LAMP = "void light lamp 0 0 3 40 40 40\nlamp sphere bulb 0 0 4 6 -1 4 .3\n"

# The text as words (one line) and as a file of lines.
WORDS = "IO A.V xL-' OVAL"
LINES = ["IO A.V", "", "L-'    V.A", "xA  V.   OIL", "  AVOIL. yz", "A" * 40]


def font_text():
    lines = ["# A small test font for lazyrad's text patterns (not one of Radiance's).",
             "# code nverts x1 y1 ... xn yn, 0-255, y up"]
    for code, xy in FONT.items():
        lines.append(f"{code} {len(xy) // 2}  " + " ".join(str(v) for v in xy) +
                     ("  # " + chr(code) if code != 32 else "  # space"))
    return "\n".join(lines) + "\n"


def grid(x0, x1, y0, y1, nx, ny, z=2.0, d=(0, 0, -1)):
    """Rays straight down onto z = 0 over [x0, x1] x [y0, y1]; the steps are
    not multiples of a glyph unit, so the points fall all over the glyphs."""
    rows = []
    for j in range(ny):
        y = y0 + (y1 - y0) * (j + 0.37) / ny
        for i in range(nx):
            x = x0 + (x1 - x0) * (i + 0.61) / nx
            rows.append(f"{x:.6f} {y:.6f} {z} {d[0]} {d[1]} {d[2]}")
    return "\n".join(rows) + "\n"


def main():
    write = fresh_folder(OUT)
    runs = []  # (group, name, files, rays, repeat, options, check)
    write("block.fnt", font_text())
    write("lines.txt", "\n".join(LINES) + "\n")
    # One line, 17 characters (uniform cells reach x = 15), one line high.
    write("line.rays", grid(-0.2, 15.5, -0.1, 1.05, 100, 8))
    # Six lines.
    write("lines.rays", grid(-0.2, 13.5, -5.2, 1.05, 64, 20))

    # 1. brighttext on a light, one line, every spacing.
    frame = "0 1 0  1 0 0  0 -1 0"
    spacings = {"uniform": "", "zero": " 0", "prop": " 0.2", "squeeze": " -0.1",
                "prop_wide": " 0.6", "squeeze_tight": " -0.02"}
    for name, sp in spacings.items():
        reals = 11 + (1 if sp else 0)
        write(f"bright_{name}.rad", f"void brighttext t {2 + len(WORDS.split())} block.fnt . "
              f"{WORDS}\n0\n{reals} {frame} 5 .5{sp}\nt " + LIGHT + "bright " + PLANE)
        runs.append(("textbright", name, [f"bright_{name}.rad"], "line.rays", 1, "-ab 0",
                     "exact"))

    # Finely over "OVA" (cells 11 to 14 of WORDS in uniform cells: x has no
    # glyph and takes no cell): the
    # glyphs' slanted edges, the hole and the doubled edge, point by point.
    write("fine.rays", grid(10.95, 14.05, -0.02, 1.02, 110, 36))
    runs.append(("textbright", "fine", ["bright_uniform.rad"], "fine.rays", 1, "-ab 0", "exact"))

    # 2. colortext from a file of lines, skewed and scaled frames.
    frames = {
        "square": "0 1 0  1 0 0  0 -1 0",
        "skewed": "0 1 0  .9 .2 0  .3 -1.1 0",
        "tilted": "0 1 0  1 0 .4  0 -1 -.3",   # parts out of the plane are ignored
        "small": "0 1 0  .35 0 0  0 -.5 0",
    }
    cases = [(f, "uniform") for f in frames] + [("square", "prop"), ("square", "squeeze"),
                                                  ("skewed", "prop")]
    for fname, sname in cases:
        fr, sp = frames[fname], {"uniform": "", "prop": " .15", "squeeze": " -.05"}[sname]
        name = f"{fname}_{sname}"
        reals = 15 + (1 if sp else 0)
        write(f"color_{name}.rad", f"void colortext t 2 block.fnt lines.txt\n0\n"
              f"{reals} {fr} 3 2 1 .2 .4 .6{sp}\nt " + LIGHT + "bright " + PLANE)
        runs.append(("textcolor", name, [f"color_{name}.rad"], "lines.rays", 1, "-ab 0",
                     "exact"))

    # 3. On plastic under a lamp, after a colour pattern; and an alias.
    write("plastic.rad", LAMP + "void colorfunc c 4 .8 .6+.1*sin(Px) .7 . 0 0\n"
          f"c brighttext t 6 block.fnt . {' '.join(WORDS.split()[:4])}\n0\n12 {frame} .9 .2 .1\n"
          "t plastic m 0 0 5 .6 .6 .6 .02 .05\nm " + PLANE)
    runs.append(("textchain", "plastic", ["plastic.rad"], "line.rays", 1, DET + " -ab 0",
                 "exact"))
    write("alias.rad", "void brighttext t0 4 block.fnt . OVAL AV\n0\n11 0 1 0 1 0 0 0 -1 0 4 1\n"
          "void colorfunc c 4 .5 1 1.5 . 0 0\nc alias t t0\nt " + LIGHT + "bright " + PLANE)
    runs.append(("textchain", "alias", ["alias.rad"], "line.rays", 1, "-ab 0", "exact"))

    # 4. mixtext: two lights; a pattern and void (a hole where it is void).
    write("mix_lights.rad", "void light red 0 0 3 3 0 0\nvoid light blue 0 0 3 0 .5 4\n"
          f"void mixtext mt {4 + len(WORDS.split())} red blue block.fnt . {WORDS}\n0\n"
          f"10 {frame} .2\nmt " + PLANE)
    runs.append(("textmix", "lights", ["mix_lights.rad"], "line.rays", 1, "-ab 0", "exact"))
    write("mix_pattern.rad", "void light under 0 0 3 1 1 1\n"
          "under polygon below 0 0 12 -1 -6 -1  14 -6 -1  14 3 -1  -1 3 -1\n"
          "void colorfunc c 4 2 1 .5 . 0 0\n"
          "void mixtext mt 4 c void block.fnt lines.txt\n0\n9 0 1 0 1 0 0 0 -1 0\n"
          "mt light top 0 0 3 1 2 3\ntop " + PLANE)
    runs.append(("textmix", "pattern_void", ["mix_pattern.rad"], "lines.rays", 1, "-ab 0",
                 "exact"))

    # 5. Inside an instance: the text's frame is in the object's space.
    write("inst_obj.rad", f"void brighttext t {2 + len(WORDS.split())} block.fnt . {WORDS}\n0\n"
          f"12 {frame} 6 .3 .1\nt " + LIGHT + "bright " + PLANE)
    with open(os.path.join(OUT, "inst_obj.oct"), "wb") as f:
        subprocess.run([os.path.join(BIN, "oconv"), "-f", "inst_obj.rad"], stdout=f,
                       check=True, env=ENV, cwd=OUT)
    write("instance.rad", "void instance i1 9 inst_obj.oct -rz 8 -t .5 -.3 0 -s .9\n0\n0\n")
    runs.append(("textinstance", "instance", ["instance.rad"], "line.rays", 1, "-ab 0", "exact"))

    # On a distant source: the point is the ray's origin, in both programs.
    write("sky.rad", f"void brighttext t 3 block.fnt . IO\n0\n11 {frame} 5 .5\n"
          "t glow g 0 0 4 1 1 1 0\ng source s 0 0 4 0 0 -1 180\n")
    write("sky.rays", "0.5 0.5 0 0 0 -1\n0.1 0.5 0 0 0 -1\n1.5 0.5 3 0 0 -1\n"
          "0.5 0.5 2 0.1 0 -1\n1.45 0.2 -4 0.3 0.2 -1\n")
    runs.append(("textsky", "source", ["sky.rad"], "sky.rays", 1, "-ab 0", "exact"))

    # 6. Errors.
    errors = {
        "parallel": f"void brighttext t 3 block.fnt . IO\n0\n11 0 1 0 1 0 0 2 0 0 5 .5\n",
        "reals": f"void brighttext t 3 block.fnt . IO\n0\n10 0 1 0 1 0 0 0 -1 0 5\n",
        "strings": "void mixtext t 3 void void block.fnt\n0\n9 0 1 0 1 0 0 0 -1 0\n",
        "nofont": "void brighttext t 3 nosuch.fnt . IO\n0\n11 0 1 0 1 0 0 0 -1 0 5 .5\n",
        "notext": "void colortext t 2 block.fnt nosuch.txt\n0\n15 0 1 0 1 0 0 0 -1 0 1 1 1 0 0 0\n",
        "badfont": "void brighttext t 3 bad.fnt . IO\n0\n11 0 1 0 1 0 0 0 -1 0 5 .5\n",
    }
    write("bad.fnt", "73 4 100 0 155 0 155 300 100 255\n")
    for name, text in errors.items():
        write(f"error_{name}.rad", text + "t " + LIGHT + "bright " + PLANE)
        runs.append(("texterror", name, [f"error_{name}.rad"], "line.rays", 1, "-ab 0",
                     "exact"))

    run_and_write(runs, radiance, OUT,
                  "# Real Radiance 5.4a's answers for the text pattern cases of\n"
                  "# tests/direct/direct_matrix_test.cpp, written by\n"
                  "# tests/direct/generate_text.py (format as in generate.py).\n")


if __name__ == "__main__":
    main()
