#!/usr/bin/env python3
# Generates the antimatter cases (tests/data/clip/) for
# tests/direct/direct_matrix_test.cpp, with REAL Radiance 5.4a's answers. A
# developer's tool: it needs ../shared/reference/radiance-5.4a (or
# RADIANCE=<its folder>); the test only reads what this writes. Same
# expected.txt format as generate.py (see there).
#
#   tests/direct/generate_clip.py
#
# Covers antimatter (m_clip.c; radiance-notes.md §2.8): a window cut in a
# thin and a thick wall (also flush with its faces), seen by view rays from
# both sides and by the shadow rays of the floor behind it, under a lamp and the sun; a first
# modifier that is a material (5.4a never shades with it); several
# modifiers; an alias and a redefinition (clipped by definition, not by
# name); overlapping antimatter; glass and a mirror inside the cut; a ball
# with a bite; rays starting inside; an instance; -i, -I, -ab 1; the
# warnings and errors.
import os
import subprocess

from generate_patterns import BIN, ENV, radiance
from matrix_data import box, fresh_folder, run_and_write

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
OUT = os.path.join(ROOT, "tests", "data", "clip")
DET = "-u- -dj 0 -dt 0"


def wall(mod, name, x, facing=1, y=(-5, 5), z=(-1, 5)):
    """The plane x = const over y, z; its normal +x (facing=1) or -x."""
    vs = [(x, y[0], z[0]), (x, y[1], z[0]), (x, y[1], z[1]), (x, y[0], z[1])]
    if facing < 0:
        vs.reverse()
    return (f"{mod} polygon {name} 0 0 12 " +
            "  ".join(" ".join(f"{c:g}" for c in v) for v in vs) + "\n")


MATS = ("void plastic wallmat 0 0 5 .6 .6 .6 0 0\n"
        "void plastic red 0 0 5 .8 .1 .1 0 0\n"
        "void plastic grey 0 0 5 .4 .4 .4 0 0\n")
LAMP = "void light lamp 0 0 3 100 100 100\nlamp sphere bulb 0 0 4 -3 0 1.5 .3\n"
SUN = "void light sun 0 0 3 4e4 4e4 4e4\nsun source s 0 0 4 -1 .2 .6 1\n"
FLOOR = "grey polygon floor 0 0 12 -5 -5 -1  5 -5 -1  5 5 -1  -5 5 -1\n"
HOLE = box("hole", "cut", (-.3, -.5, 0), (.3, .5, 1))


def main():
    write = fresh_folder(OUT)
    runs = []  # (group, name, files, rays, repeat, options, check)
    # From the room (x > 0) through the cut and beside it, from outside
    # back in, along the cut's edges, and down through it to the floor.
    write("view.rays", "2 0 .5 -1 0 0\n2 0 .5 -1 .1 -.3\n2 .3 .8 -1 -.1 -.3\n"
                       "2 0 .5 -1 0 -.35\n1 .2 .7 -1 -.1 -.5\n2 2 .5 -1 0 0\n"
                       "2 .49 .5 -1 0 0\n2 .51 .5 -1 0 0\n2 0 1.01 -1 0 0\n"
                       "-2 0 .5 1 0 0\n-2 .2 .3 1 -.1 -.2\n-4 0 2 1 0 -.4\n"
                       "1 0 3 -.5 0 -1\n")
    # Floor points behind the wall, lit through the cut (shadow rays).
    write("floor.rays", "".join(f"{x} {y} 0 0 0 -1\n" for x, y in (
        (1.8, 0), (2.2, 0), (3, 0), (4, .3), (4, .9), (3, 1.1), (2.5, -.6), (6, 0),
        (1, 0), (4.5, 2), (-1, 0))))
    write("sensor.rays", "".join(f"{x} {y} -1 0 0 1\n" for x, y in (
        (2.2, 0), (3, .4), (4, -.9), (1, 0), (4.5, 2))))
    write("both.rays", open(os.path.join(OUT, "view.rays")).read() +
          open(os.path.join(OUT, "floor.rays")).read())

    scenes = {
        # A window cut in a thin wall.
        "thin": MATS + "void antimatter hole 1 wallmat 0 0\n" + wall("wallmat", "w", 0) + HOLE,
        # A first modifier that is a material: Radiance means it to shade the
        # cut, 5.4a never does.
        "first_material": MATS + "void antimatter hole 2 red wallmat 0 0\n" +
                          wall("wallmat", "w", 0) + wall("red", "r", -.1, -1) + HOLE,
        # A thick wall: two faces, the cut through both.
        "thick": MATS + "void antimatter hole 1 wallmat 0 0\n" + wall("wallmat", "w", 0) +
                 wall("wallmat", "wb", -.2, -1) + box("hole", "cut", (-.4, -.5, 0), (.3, .5, 1)),
        # The cut flush with both faces of a thick wall: hits on the wall and
        # the antimatter coincide, the later modifier (antimatter) wins.
        "flush": MATS + "void antimatter hole 1 wallmat 0 0\n" + wall("wallmat", "w", 0) +
                 wall("wallmat", "wb", -.2, -1) + box("hole", "cut", (-.2, -.5, 0), (0, .5, 1)),
        # The same with the antimatter defined before the wall's material: an
        # unknown modifier, and the wall wins the coincident hits.
        "flush_first": "void antimatter hole 1 wallmat 0 0\n" + MATS + wall("wallmat", "w", 0) +
                       wall("wallmat", "wb", -.2, -1) +
                       box("hole", "cut", (-.2, -.5, 0), (0, .5, 1)),
        # Two modifiers; and void among the names.
        "two": MATS + "void plastic pane 0 0 5 .2 .2 .7 0 0\n"
                      "void antimatter hole 3 void wallmat pane 0 0\n" +
               wall("wallmat", "w", 0) + wall("pane", "p", -.15, 1, (-1, 1), (-1, 3)) + HOLE,
        # An alias is a modifier of its own: the lower wall, in the alias,
        # keeps no cut.
        "alias": MATS + "void alias wall2 wallmat\n"
                        "void antimatter hole 1 wallmat 0 0\n" +
                 wall("wallmat", "w", 0, 1, (-5, 5), (.6, 5)) +
                 wall("wall2", "w2", 0, 1, (-5, 5), (-1, .6)) + HOLE,
        # Clipped by the definition before the antimatter, not by name.
        "redefined": MATS + "void antimatter hole 1 wallmat 0 0\n" + wall("wallmat", "w", 0) +
                     "void plastic wallmat 0 0 5 .3 .6 .3 0 0\n" +
                     wall("wallmat", "w2", -1, 1) + HOLE,
        # Two overlapping cuts clipping the same modifier: leaving one
        # unclips it, inside the other too (the set is not counted).
        "nested": MATS + "void antimatter hole 1 wallmat 0 0\n" + wall("wallmat", "w", 0) +
                  HOLE + box("hole", "cut2", (-.3, .2, .3), (.3, .9, 1.3)),
        # Glass in the cut (not clipped): transmitted and shadow rays go on
        # inside the antimatter.
        "glass": MATS + "void glass clear 0 0 3 .9 .9 .9\n"
                        "void antimatter hole 1 wallmat 0 0\n" + wall("wallmat", "w", 0) +
                 wall("clear", "g", .1, 1, (-.6, .6), (-.1, 1.1)) + HOLE,
        # A mirror inside the cut: the reflected ray keeps the clipped set.
        "mirror": MATS + "void mirror mir 0 0 3 .9 .9 .9\n"
                         "void antimatter hole 1 wallmat 0 0\n" + wall("wallmat", "w", 0) +
                  "mir polygon m 0 0 12 .25 -.4 .05  .25 .4 .05  -.2 .4 .9  -.2 -.4 .9\n" +
                  box("hole", "cut", (-.3, -.5, 0), (.3, .5, 1.2)),
        # A lamp inside the cut, behind the wall, and a ball in front of it:
        # shadow rays from the ball cross the clipped wall and no antimatter.
        "lamp_inside": MATS + "void antimatter hole 1 wallmat 0 0\n" + wall("wallmat", "w", 0) +
                       "void light bulb2 0 0 3 200 200 200\nbulb2 sphere b2 0 0 4 -.15 0 .85 .05\n"
                       "red sphere rb 0 0 4 .15 0 .2 .08\n" + HOLE,
        # A ball with a spherical bite: its inside seen through the bite.
        "ball": MATS + "void antimatter bite 1 red 0 0\n"
                       "red sphere ball 0 0 4 .8 0 .5 .6\nbite sphere b 0 0 4 1.3 0 .6 .45\n" +
                wall("wallmat", "w", 0),
    }
    for name, text in scenes.items():
        for light, ltext in (("lamp", LAMP), ("sun", SUN)):
            if light == "sun" and name not in ("thin", "thick", "glass", "two"):
                continue
            write(f"{name}_{light}.rad", ltext + text + FLOOR)
            runs.append(("cut", f"{name}_{light}", [f"{name}_{light}.rad"], "both.rays", 1,
                         DET, "exact"))
    # Rays that start inside the antimatter: nothing clipped yet.
    write("ball.rays", "2 0 1 -1.85 0 -.72\n2 .03 1 -1.85 0 -.74\n2 -.02 .95 -1.9 0 -.7\n")
    runs.append(("cut", "lamp_inside_ball", ["lamp_inside_lamp.rad"], "ball.rays", 1, DET,
                 "exact"))
    write("inside.rays", "0 0 .5 -1 0 0\n.2 0 .5 -1 0 0\n.2 .3 .2 -1 0 .1\n-.2 0 .5 1 0 0\n")
    runs.append(("cut", "start_inside", ["thin_lamp.rad"], "inside.rays", 1, DET, "exact"))
    runs.append(("cut", "backfaces", ["thick_lamp.rad"], "both.rays", 1, DET + " -bv-",
                 "exact"))
    # -i meters the floor through the cut; -I: sensors behind the wall.
    for scene in ("thin_lamp", "glass_sun"):
        runs.append(("cut", f"irradiance_{scene}", [f"{scene}.rad"], "both.rays", 1,
                     DET + " -i", "exact"))
        runs.append(("cut", f"sensor_{scene}", [f"{scene}.rad"], "sensor.rays", 1,
                     DET + " -I", "exact"))

    # An instance holding a wall with its cut, turned and moved.
    write("inst_obj.rad", MATS + "void antimatter hole 1 wallmat 0 0\n" +
          wall("wallmat", "w", 0) + HOLE)
    with open(os.path.join(OUT, "inst_obj.oct"), "wb") as f:
        subprocess.run([os.path.join(BIN, "oconv"), "-f", "inst_obj.rad"], stdout=f,
                       check=True, env=ENV, cwd=OUT)
    write("instance.rad", LAMP + MATS + FLOOR +
          "void instance i1 7 inst_obj.oct -rz 10 -t 0 .1 0 0 0\n")
    runs.append(("cut", "instance", ["instance.rad"], "both.rays", 1, DET, "exact"))
    # With no top-level modifier of that name the instance's own is cut; with
    # one (above), Radiance's lastmod() takes the scene's, and the instance's
    # own wall stays whole. (A scene surface cut by an instance's antimatter
    # is not compared: Radiance's obstructor cache, which only knows the
    # scene's own antimatter, still lets it block its sources; README.)
    write("instance_own.rad", LAMP + "void plastic grey 0 0 5 .4 .4 .4 0 0\n" + FLOOR +
          "void instance i1 7 inst_obj.oct -rz 10 -t 0 .1 0 0 0\n")
    runs.append(("cut", "instance_own", ["instance_own.rad"], "both.rays", 1, DET, "exact"))

    # -ab 1 without a cache: a closed room whose window is a cut, a sky
    # outside, sensors on the floor.
    room = (MATS + "void antimatter hole 1 wallmat 0 0\n" +
            wall("wallmat", "w", 0, 1, (-2, 2), (-1, 2)) +
            wall("wallmat", "e", 4, -1, (-2, 2), (-1, 2)) +
            "wallmat polygon s 0 0 12 0 -2 -1  4 -2 -1  4 -2 2  0 -2 2\n"
            "wallmat polygon n 0 0 12 0 2 -1  0 2 2  4 2 2  4 2 -1\n"
            "wallmat polygon c 0 0 12 0 -2 2  4 -2 2  4 2 2  0 2 2\n" + HOLE +
            "void glow skyglow 0 0 4 2 2 2.5 0\nskyglow source sky 0 0 4 -1 0 0 180\n"
            "grey polygon floor 0 0 12 0 -2 -1  4 -2 -1  4 2 -1  0 2 -1\n")
    write("room.rad", room)
    write("room.rays", "1 0 -1 0 0 1\n2.5 1 -1 0 0 1\n")
    runs.append(("cutab1", "room", ["room.rad"], "room.rays", 64,
                 "-u+ -I -ab 1 -aa 0 -ad 256 -as 0", "noise"))

    # Warnings and errors.
    errors = {
        "unknown": "void antimatter hole 2 nosuch wallmat 0 0\n",
        "duplicate": "void antimatter hole 3 wallmat red wallmat 0 0\n",
        "no_strings": "void antimatter hole 0 0 0\n",
    }
    for name, text in errors.items():
        write(f"error_{name}.rad", LAMP + MATS + text + wall("wallmat", "w", 0) + HOLE + FLOOR)
        runs.append(("cuterror", name, [f"error_{name}.rad"], "view.rays", 1, DET, "exact"))

    run_and_write(runs, radiance, OUT,
                  "# Real Radiance 5.4a's answers for the antimatter cases of\n"
                  "# tests/direct/direct_matrix_test.cpp, written by\n"
                  "# tests/direct/generate_clip.py (format as in generate.py).\n")


if __name__ == "__main__":
    main()
