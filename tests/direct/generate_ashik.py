#!/usr/bin/env python3
# Generates the ashik2 cases (tests/data/ashik/) for
# tests/direct/direct_matrix_test.cpp, with REAL Radiance 5.4a's answers. A
# developer's tool: it needs ../shared/reference/radiance-5.4a (or
# RADIANCE=<its folder>); the test only reads what this writes. Same
# expected.txt format as generate.py (see there).
#
#   tests/direct/generate_ashik.py
#
# Covers ashik2 (Radiance's ashikhmin.c: Ashikhmin and Shirley's anisotropic
# Phong model): direct highlights for several forms of u (constant, from the
# position, arguments, transforms, along the normal, a math error) on a
# plane, a ball and a ring under three kinds of source, the back side with
# and without -bv, a pattern and a texture, an instance, the sampled
# reflection at -ss 1 and 4 (means of repeats against a sky that colours
# every direction), -ab 1, -i, and the argument errors.
import os
import subprocess

from generate_aniso import BALL, LAMPS, PLANE, RING, SKY
from generate_patterns import BIN, ENV, radiance
from matrix_data import LIT_BOX, fresh_folder, run_and_write

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
OUT = os.path.join(ROOT, "tests", "data", "ashik")
# -st 1 puts every highlight below the sampling threshold: ashik2 samples
# its reflection at random even at -ss 0, so deterministic runs leave it out
# (its colour then joins the ambient term, zero at -ab 0).
DET = "-u- -dj 0 -dt 0 -st 1"

MATERIALS = {
    "sharp": "ashik2 m {u} 0 8 .3 .25 .2 .2 .3 .4 200 20",
    "broad": "ashik2 m {u} 0 8 .1 .1 .1 .5 .5 .5 8 60",
    "iso": "ashik2 m {u} 0 8 .5 .4 .3 .1 .1 .1 30 30",
    "dark": "ashik2 m {u} 0 8 0 0 0 .6 .5 .4 100 10",
}
ORIENTATIONS = {
    "x": "4 1 .3 0 .",
    "position": "4 Py 1+Px 0 .",
    "xf": "8 1 Px*.2 0 . -rz 30 -s 2",
    "args": "4 arg(1) A2 0 .",  # the material's own reals: A1, A2
    "normal": "4 0 0 1 .",  # along the normal: isotropic, harmonic mean
    "matherr": "4 sqrt(-1-Px*Px) 0 0 .",  # u = 0 after EDOM: the same
}


def material(kind, orient, modifier="void"):
    return modifier + " " + MATERIALS[kind].format(u=ORIENTATIONS[orient]) + "\n"


def main():
    write = fresh_folder(OUT)
    runs = []  # (group, name, files, rays, repeat, options, check)
    write("down.rays", "1 2 5 0.6 0 -0.8\n0 0 5 0 0 -1\n-3 4 2 0.3 -0.2 -1\n"
                       "2.5 -1 7 0 0 -1\n0 0 5 -0.8 0 -0.6\n0.5 -3 3 -0.1 0.6 -0.8\n"
                       "3 3 2 -0.6 -0.6 -0.5\n1.2 0.8 5 -0.05 0.1 -1\n")
    write("up.rays", "1 2 -5 0 0 1\n-1 0.5 -3 0.2 0.1 1\n")
    write("ball.rays", "0 -5 -0.7 0 1 0\n0.4 -5 -1 0 1 0\n-0.6 -5 -0.5 0 1 0.1\n")
    write("ring.rays", "0 0 5 0 0 -1\n1 2 5 0.6 0 -0.8\n-2 1 6 0.2 -0.1 -1\n")

    # 1. Each material and form of u on a plane under each lamp.
    for kind in MATERIALS:
        for orient in ORIENTATIONS:
            for lamp, lamptext in LAMPS.items():
                if lamp != "sphere" and (kind not in ("sharp", "broad") or orient != "x"):
                    continue
                name = f"{kind}_{orient}_{lamp}"
                text = lamptext + material(kind, orient) + "m " + PLANE
                write(f"plane_{name}.rad", text)
                runs.append(("ashikplane", name, [f"plane_{name}.rad"], "down.rays", 1, DET,
                             "exact"))
    # 2. Not flat: a ball; a ring; the back side, visible and not.
    for kind in ("sharp", "broad"):
        write(f"ball_{kind}.rad", LAMPS["sphere"] + material(kind, "x") + "m " + BALL)
        runs.append(("ashikshape", f"ball_{kind}", [f"ball_{kind}.rad"], "ball.rays", 1, DET,
                     "exact"))
        write(f"ring_{kind}.rad", LAMPS["sphere"] + material(kind, "position") + "m " + RING)
        runs.append(("ashikshape", f"ring_{kind}", [f"ring_{kind}.rad"], "ring.rays", 1, DET,
                     "exact"))
        below = "void light under 0 0 3 80 80 80\nunder sphere ubulb 0 0 4 -1 .5 -4 .5\n"
        write(f"back_{kind}.rad", below + material(kind, "x") + "m " + PLANE)
        for bv in ("", " -bv-"):
            runs.append(("ashikshape", f"back_{kind}{bv.replace(' -', '_')}", [f"back_{kind}.rad"],
                         "up.rays", 1, DET + bv, "exact"))
    # 3. A colour pattern and a texture before it; an instance.
    chains = {
        "pattern": "void colorfunc c 4 .5+.3*sin(Px) .6 .4+.2*cos(Py) . 0 0\n",
        "texture": "void texfunc c 4 .2*sin(2*Px) .15*cos(Py) 0 . 0 0\n",
    }
    for chain, text in chains.items():
        for kind in ("sharp", "broad"):
            name = f"{chain}_{kind}"
            write(f"chain_{name}.rad", LAMPS["sphere"] + text + material(kind, "position", "c") +
                  "m " + PLANE)
            runs.append(("ashikchain", name, [f"chain_{name}.rad"], "down.rays", 1, DET, "exact"))
    write("inst_obj.rad", material("sharp", "xf") + "m " + PLANE)
    with open(os.path.join(OUT, "inst_obj.oct"), "wb") as f:
        subprocess.run([os.path.join(BIN, "oconv"), "-f", "inst_obj.rad"], stdout=f,
                       check=True, env=ENV, cwd=OUT)
    write("instance.rad", LAMPS["sphere"] +
          "void instance i1 9 inst_obj.oct -rz 60 -t .5 .2 0 -s 1.5 0 0\n")
    runs.append(("ashikchain", "instance", ["instance.rad"], "down.rays", 1, DET, "exact"))

    # 4. The sampled reflection: means of repeats under a sky whose colour
    # encodes the direction, at -ss 1 and 4.
    write("sky_rays.rays", "0 0 2 0.5 0 -1\n1 1 2 -0.2 0.3 -1\n")
    for kind in ("sharp", "broad", "iso"):
        write(f"sky_{kind}.rad", SKY + material(kind, "x") + "m " + PLANE)
        for ss in ("1", "4"):
            runs.append(("ashiksampled", f"{kind}_ss{ss}", [f"sky_{kind}.rad"], "sky_rays.rays",
                         400, f"-u+ -dj 0 -dt 0 -st 0 -ss {ss}", "noise"))
    # 5. -ab 1 without a cache, and -i.
    write("ab1.rad", LIT_BOX + material("broad", "x") +
          "m polygon top 0 0 12 -1 -1 -0.5  1 -1 -0.5  1 1 -0.5  -1 1 -0.5\n")
    write("ab1.rays", "0.3 0.2 1 0 0 -1\n-0.5 0.4 1 0.2 0 -1\n")
    runs.append(("ashikab1", "broad", ["ab1.rad"], "ab1.rays", 64,
                 "-u+ -ab 1 -aa 0 -ad 256 -as 0 -st 1", "noise"))
    runs.append(("ashikab1", "irradiance", ["ab1.rad"], "ab1.rays", 1, DET + " -i", "exact"))
    # 6. Errors.
    errors = {
        "reals": "void ashik2 m 4 1 0 0 . 0 7 .3 .3 .3 .2 .2 .2 10\n",
        "strings": "void ashik2 m 3 1 0 0 0 8 .3 .3 .3 .2 .2 .2 10 10\n",
    }
    for name, text in errors.items():
        write(f"error_{name}.rad", LAMPS["sphere"] + text + "m " + PLANE)
        runs.append(("ashikerror", name, [f"error_{name}.rad"], "down.rays", 1, DET, "exact"))

    run_and_write(runs, radiance, OUT,
                  "# Real Radiance 5.4a's answers for the ashik2 cases of\n"
                  "# tests/direct/direct_matrix_test.cpp, written by\n"
                  "# tests/direct/generate_ashik.py (format as in generate.py).\n")


if __name__ == "__main__":
    main()
