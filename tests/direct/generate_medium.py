#!/usr/bin/env python3
# Generates the participating-medium cases (tests/data/medium/) for
# tests/direct/direct_matrix_test.cpp, with REAL Radiance 5.4a's answers. A
# developer's tool: it needs ../shared/reference/radiance-5.4a (or
# RADIANCE=<its folder>); the test only reads what this writes. Same
# expected.txt format as generate.py (see there).
#
#   tests/direct/generate_medium.py
#
# Covers the global medium (-me extinction, -ma albedo, with the -av
# ambient value it scatters in; radiance-notes.md §2.5's rayparticipate()):
# view rays onto lit and black surfaces, into a lamp, past everything and
# into the sun (extinguished), the shadow rays' loss, -I sensors, -ab 1;
# and a dielectric's absorption over every segment inside it, internal
# reflections included, with and without the global medium.
import os

from generate_patterns import radiance
from matrix_data import fresh_folder, run_and_write

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
OUT = os.path.join(ROOT, "tests", "data", "medium")
DET = "-u- -dj 0 -dt 0"

ROOM = ("void light lamp 0 0 3 100 100 100\nlamp sphere bulb 0 0 4 0 0 2 .3\n"
        "void plastic blk 0 0 5 0 0 0 0 0\n"
        "blk polygon fl 0 0 12 -10 -10 0 10 -10 0 10 10 0 -10 10 0\n"
        "void plastic wh 0 0 5 .5 .5 .5 0 0\n"
        "wh polygon w 0 0 12 5 -10 -1 5 10 -1 5 10 5 5 -10 5\n"
        "wh sphere ball 0 0 4 -2 2 1 .5\n")
SUN = "void light sun 0 0 3 1e4 1e4 1e4\nsun source s 0 0 4 -1 .2 .5 1\n"
# A glass block of dielectric on a floor, under a lamp and a sky.
BLOCK = ("void light lamp 0 0 3 100 100 100\nlamp sphere bulb 0 0 4 0 0 6 .5\n"
         "void glow sky 0 0 4 .5 .8 1.2 0\nsky source s 0 0 4 0 0 1 180\n"
         "void plastic flr 0 0 5 .6 .5 .4 0 0\n"
         "flr polygon f 0 0 12 -10 -10 -1 10 -10 -1 10 10 -1 -10 10 -1\n"
         "void dielectric dg 0 0 5 .6 .8 .9 1.5 0\n" + "".join(
             f"dg polygon cube.{n} 0 0 12 {v}\n" for n, v in (
                 ("1540", "-1 -1 0  -1 -1 2  -1 1 2  -1 1 0"),
                 ("4620", "1 -1 0  1 1 0  1 1 2  1 -1 2"),
                 ("2310", "-1 -1 0  1 -1 0  1 -1 2  -1 -1 2"),
                 ("3267", "-1 1 0  -1 1 2  1 1 2  1 1 0"),
                 ("1326", "-1 -1 0  -1 1 0  1 1 0  1 -1 0"),
                 ("5764", "-1 -1 2  1 -1 2  1 1 2  -1 1 2"))))


def main():
    write = fresh_folder(OUT)
    runs = []  # (group, name, files, rays, repeat, options, check)
    write("room.rad", ROOM)
    write("room_sun.rad", ROOM + SUN)
    write("block.rad", BLOCK)
    # Onto the black floor, the white wall, the ball, into the lamp, past
    # everything, toward the sun.
    write("view.rays", "0 0 1 0 0 -1\n-3 0 1 1 0 0\n0 0 1 0 0 1\n0 0 1 1 0 0\n"
                       "0 0 1 -1 1 0\n2 -3 3 .1 .2 .9\n0 0 1 -1 .2 .5\n1 1 4 0 0 -1\n")
    write("sensor.rays", "4.9 0 1 -1 0 0\n4.9 3 .5 -1 0 0\n-2 2 1.51 0 0 1\n")
    # Down through the block's top, through a side at a slant (internal
    # reflections), and along the floor into it.
    write("block.rays", "0 0 4 0 0 -1\n-3 0.5 1.5 1 0.1 -0.4\n0 -4 0.5 0.05 1 0.3\n"
                        "1.5 0 3 0.3 0 -1\n-0.5 -3 0.2 0.1 1 0.05\n")
    media = {
        "absorbing": "-me .05 .1 .15",
        "scattering": "-me .1 .2 .3 -ma .5 .6 .7 -av 1 2 3",
        "grey": "-me .02 .02 .02 -ma .9 .9 .9 -av .5 .5 .5",
        "albedo_only": "-ma .5 .5 .5 -av 1 1 1",
        "dense": "-me 20 30 40 -ma .1 .1 .1 -av .3 .3 .3",
    }
    for name, opts in media.items():
        for scene in ("room", "room_sun"):
            runs.append(("medium", f"{scene}_{name}", [f"{scene}.rad"], "view.rays", 1,
                         f"{DET} {opts}", "exact"))
        runs.append(("medium", f"sensor_{name}", ["room_sun.rad"], "sensor.rays", 1,
                     f"{DET} -I {opts}", "exact"))
    for name in ("", "absorbing", "scattering"):
        opts = media.get(name, "")
        runs.append(("mediumblock", f"block_{name or 'vacuum'}", ["block.rad"], "block.rays", 1,
                     f"{DET} -lr 12 -lw 1e-5 {opts}".strip(), "exact"))
    write("ab1.rays", "4.9 0 1 -1 0 0\n4.9 3 .5 -1 0 0\n")
    runs.append(("mediumab1", "scattering", ["room_sun.rad"], "ab1.rays", 64,
                 "-u+ -I -ab 1 -aa 0 -ad 256 -as 0 " + media["grey"], "noise"))

    run_and_write(runs, radiance, OUT,
                  "# Real Radiance 5.4a's answers for the participating-medium cases of\n"
                  "# tests/direct/direct_matrix_test.cpp, written by\n"
                  "# tests/direct/generate_medium.py (format as in generate.py).\n")


if __name__ == "__main__":
    main()
