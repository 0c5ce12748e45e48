#!/usr/bin/env python3
# Generates the anisotropic material cases (tests/data/aniso/) for
# tests/direct/direct_matrix_test.cpp, with REAL Radiance 5.4a's answers. A
# developer's tool: it needs ../shared/reference/radiance-5.4a (or
# RADIANCE=<its folder>); the test only reads what this writes. Same
# expected.txt format as generate.py (see there).
#
#   tests/direct/generate_aniso.py
#
# Covers plastic2, metal2 and trans2 (m_aniso.c; radiance-notes.md §2.6):
# direct highlights and transmitted highlights from sources of several
# shapes on flat and curved receivers, both sides, u from constants, from
# ray quantities and through transforms, u along the normal (the isotropic
# fallback and its warning), with patterns and textures on the material,
# inside instances, the sampled specular rays (-ss 0 on the mirror
# direction, exactly; -ss 1 and 4 as means of repeats), -ab 1, -I through
# trans2, and the errors.
import os
import subprocess
import sys
import tempfile

from generate_patterns import BIN, ENV, radiance
from matrix_data import LIT_BOX, run_and_write

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
OUT = os.path.join(ROOT, "tests", "data", "aniso")
# -ss 0 puts each specular sample on the (perturbed) mirror or transmitted
# direction, so that the sampled highlights compare exactly.
DET = "-u- -dj 0 -dt 0 -ss 0"

# Lamps of three shapes above the test surfaces, and a sky whose colour
# encodes the direction, so that every sampled direction shows in the value.
LAMPS = {
    "sphere": "void light lamp 0 0 3 100 100 100\nlamp sphere bulb 0 0 4 1 1 4 .5\n",
    "polygon": "void light lamp 0 0 3 100 100 100\n"
               "lamp polygon panel 0 0 12 0 0 4  0 2 4  2 2 4  2 0 4\n",
    "distant": "void light sun 0 0 3 5e4 5e4 5e4\nsun source s 0 0 4 .3 .2 1 1\n",
}
SKY = ("void colorfunc skypat 4 1.5+Dx 1.5+Dy 1.5+Dz . 0 0\n"
       "skypat glow skyglow 0 0 4 1 1 1 0\nskyglow source sky 0 0 4 0 0 1 360\n")
PLANE = "polygon p1 0 0 12 -10 -10 0  10 -10 0  10 10 0  -10 10 0\n"
BALL = "sphere ball 0 0 4 0 0 -1 1\n"
RING = "ring disc 0 0 8 0 0 0  0.2 0.1 1  0 6\n"

MATERIALS = {
    "plastic2": "plastic2 m {u} 0 6 .6 .5 .4 .06 .05 .2",
    "metal2": "metal2 m {u} 0 6 .8 .7 .6 .9 .2 .04",
    "metal2_low": "metal2 m {u} 0 6 .8 .7 .6 .3 .1 .1",
    "trans2": "trans2 m {u} 0 8 .7 .6 .5 .04 .08 .25 .6 .7",
    "trans2_diffuse": "trans2 m {u} 0 8 .7 .6 .5 .04 .3 .1 .8 .2",
}
ORIENTATIONS = {
    "x": "4 1 0 0 .",
    "position": "4 Py 1+Px 0 .",
    "xf": "8 1 Px*.2 0 . -rz 30 -s 2",
    "xf_mirror": "5 1 .3 0 . -mx",
    "args": "4 arg(1) A2 0 .",
    "normal": "4 0 0 1 .",  # along the plane's normal: no u in the surface
    "matherr": "4 sqrt(-1-Px*Px) 0 0 .",  # Radiance takes u = 0 after EDOM
}


def write(name, text):
    with open(os.path.join(OUT, name), "w") as f:
        f.write(text)


def material(kind, orient, extra=""):
    """The material line, `void` modified unless `extra` names a modifier."""
    text = MATERIALS[kind].format(u=ORIENTATIONS[orient])
    return (extra or "void") + " " + text + "\n"


def main():
    os.makedirs(OUT, exist_ok=True)
    for f in os.listdir(OUT):
        os.remove(os.path.join(OUT, f))
    runs = []  # (group, name, files, rays, repeat, options, check)

    write("down.rays", "0 0 5 0 0 -1\n1 2 5 0.6 0 -0.8\n-3 4 2 0.3 -0.2 -1\n"
                       "2.5 -1 7 0 0 -1\n0 0 5 -0.8 0 -0.6\n0.5 -3 3 -0.1 0.6 -0.8\n"
                       "3 3 2 -0.6 -0.6 -0.5\n")
    write("up.rays", "1 2 -5 0 0 1\n-2 1 -3 0.2 0.3 1\n0.5 0.5 -4 0.1 0.1 1\n")
    write("ball.rays", "0 -5 -0.7 0 1 0\n0.4 -5 -1 0 1 0\n-0.6 -5 -0.5 0 1 0.1\n")
    write("sensors.pts", "0 0 -1.99 0 0 1\n1 0.5 -1.99 0 0 1\n-2 1 -1.99 0 0 1\n")

    # 1. Each material and orientation on a plane under each lamp and the
    # sky, seen from above (and for trans2 from below, through it).
    for kind in MATERIALS:
        for orient in ORIENTATIONS:
            for lamp, lamptext in LAMPS.items():
                if orient not in ("x", "position") and lamp != "sphere":
                    continue
                name = f"{kind}_{orient}_{lamp}"
                write(f"plane_{name}.rad", lamptext + SKY + material(kind, orient) + "m " + PLANE)
                rays = "down.rays" if not kind.startswith("trans2") else "both.rays"
                runs.append(("plane", name, [f"plane_{name}.rad"], rays, 1, DET, "exact"))
    write("both.rays", open(os.path.join(OUT, "down.rays")).read() +
          open(os.path.join(OUT, "up.rays")).read())

    # 2. Curved and ring receivers (not flat: no source widening on the
    # sphere), -bv- on the back, and -st above the specularity (the
    # highlight then joins the ambient coefficient; -av shows it).
    for kind in ("plastic2", "metal2", "trans2"):
        write(f"ball_{kind}.rad", LAMPS["sphere"] + SKY + material(kind, "position") + "m " + BALL)
        runs.append(("shape", f"ball_{kind}", [f"ball_{kind}.rad"], "ball.rays", 1, DET, "exact"))
        write(f"ring_{kind}.rad", LAMPS["polygon"] + SKY + material(kind, "x") + "m " + RING)
        runs.append(("shape", f"ring_{kind}", [f"ring_{kind}.rad"], "down.rays", 1, DET, "exact"))
        write(f"plane_bv_{kind}.rad", LAMPS["sphere"] + SKY + material(kind, "x") + "m " + PLANE)
        runs.append(("shape", f"backface_{kind}", [f"plane_bv_{kind}.rad"], "up.rays", 1,
                     DET + " -bv-", "exact"))
        runs.append(("shape", f"threshold_{kind}", [f"plane_bv_{kind}.rad"], "down.rays", 1,
                     DET + " -st 1 -av .3 .2 .1", "exact"))

    # 3. Patterns and textures on the material, and instances of it.
    chains = {
        "pattern": "void colorfunc c 4 .5+.3*sin(Px) .6 .4+.2*cos(Py) . 0 0\n",
        "texture": "void texfunc c 4 .2*sin(2*Px) .15*cos(Py) 0 . 0 0\n",
        "texture_xf": "void texfunc c 10 .2*sin(2*Px) .15 0 . -rz 45 -t 1 0 0 0 0\n",
    }
    for chain, text in chains.items():
        for kind in ("plastic2", "metal2", "trans2"):
            name = f"{chain}_{kind}"
            write(f"chain_{name}.rad", LAMPS["sphere"] + SKY + text +
                  material(kind, "position", "c") + "m " + PLANE)
            runs.append(("chain", name, [f"chain_{name}.rad"], "both.rays", 1, DET, "exact"))
    write("inst_obj.rad", material("metal2", "position") + "m " + PLANE)
    with open(os.path.join(OUT, "inst_obj.oct"), "wb") as f:
        subprocess.run([os.path.join(BIN, "oconv"), "-f", "inst_obj.rad"], stdout=f,
                       check=True, env=ENV, cwd=OUT)
    write("instance.rad", LAMPS["sphere"] + SKY +
          "void instance i1 9 inst_obj.oct -rz 60 -t .5 .2 0 -s 1.5 0 0\n")
    runs.append(("chain", "instance", ["instance.rad"], "down.rays", 1, DET, "exact"))

    # 4. Sampled specular rays: the mean of repeats against Radiance's.
    for kind in ("plastic2", "metal2", "trans2"):
        for ss in ("1", "4", ".5"):
            name = f"{kind}_ss{ss.replace('.', '')}"
            runs.append(("sampled", name, [f"plane_{kind}_x_sphere.rad"],
                         "down.rays" if kind != "trans2" else "both.rays", 64,
                         f"-u+ -dj 0 -dt 0 -ss {ss}", "noise"))

    # 5. -ab 1 without a cache, and -I through trans2 (passed straight, as
    # Radiance's irradiance calculation passes transparent materials).
    box = LIT_BOX
    write("ab1_metal2.rad", box + material("metal2", "position") +
          "m polygon top 0 0 12 -1 -1 -0.5  1 -1 -0.5  1 1 -0.5  -1 1 -0.5\n")
    write("ab1.rays", "0.3 0.2 1 0 0 -1\n-0.5 0.4 1 0.2 0 -1\n")
    runs.append(("ab1", "metal2", ["ab1_metal2.rad"], "ab1.rays", 64,
                 "-u+ -ab 1 -aa 0 -ad 256 -as 0", "noise"))
    write("irr_trans2.rad", box + material("trans2", "x") +
          "m polygon pane 0 0 12 -1 -1 -0.5  1 -1 -0.5  1 1 -0.5  -1 1 -0.5\n")
    write("irr.rays", "0.3 0.2 1 0 0 -1\n-1.5 0.4 1 0 0 -1\n")
    runs.append(("ab1", "irradiance_through_trans2", ["irr_trans2.rad"], "irr.rays", 1,
                 DET + " -i -ab 0", "exact"))

    # 6. Errors, each a one-line fatal error from both programs.
    errors = {
        "few_reals": "void plastic2 m 4 1 0 0 . 0 5 .5 .5 .5 0 .1\n",
        "trans2_reals": "void trans2 m 4 1 0 0 . 0 6 .5 .5 .5 0 .1 .1\n",
        "few_strings": "void metal2 m 3 1 0 0 0 6 .5 .5 .5 .5 .1 .1\n",
        "zero_roughness": "void plastic2 m 4 1 0 0 . 0 6 .5 .5 .5 .05 0 .1\n",
        "undefined": "void plastic2 m 4 nosuch 0 0 . 0 6 .5 .5 .5 .05 .1 .1\n",
    }
    for name, text in errors.items():
        write(f"error_{name}.rad", LAMPS["sphere"] + text + "m " + PLANE)
        runs.append(("anisoerror", name, [f"error_{name}.rad"], "down.rays", 1, "-ab 0", "exact"))

    run_and_write(runs, radiance, OUT,
                   "# Real Radiance 5.4a's answers for the anisotropic material cases of\n"
                   "# tests/direct/direct_matrix_test.cpp, written by\n"
                   "# tests/direct/generate_aniso.py (format as in generate.py).\n")


if __name__ == "__main__":
    main()
