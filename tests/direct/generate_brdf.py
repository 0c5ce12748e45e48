#!/usr/bin/env python3
# Generates the BRDF-function material cases (tests/data/brdf/) for
# tests/direct/direct_matrix_test.cpp, with REAL Radiance 5.4a's answers. A
# developer's tool: it needs ../shared/reference/radiance-5.4a (or
# RADIANCE=<its folder>); the test only reads what this writes. Same
# expected.txt format as generate.py (see there).
#
#   tests/direct/generate_brdf.py
#
# Covers plasfunc, metfunc, transfunc, plasdata, metdata and transdata
# (m_brdf.c's m_brdf2(); radiance-notes.md §2.6, radiance-functions.md
# §10.4): BRDFs reading the light direction and size, NxP NyP NzP, RdotP,
# CrP CgP CbP, the ray variables and the real arguments, with transforms,
# on planes and balls under three kinds of source, both sides, with
# patterns and textures, inside an instance, data looked up by functions
# of the light, -ab 1, -i, and the errors and compute errors.
import os
import subprocess
import sys
import tempfile

from generate_patterns import BIN, ENV, radiance
from matrix_data import LIT_BOX, run_and_write

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
OUT = os.path.join(ROOT, "tests", "data", "brdf")
# Without Russian roulette (-lr 8 stops at a depth, -lw at a weight), so
# that BRTDfunc's chains of specular rays end at the same place in both.
DET = "-u- -dj 0 -dt 0 -lr 8 -lw 1e-4"

LAMPS = {
    "sphere": "void light lamp 0 0 3 100 100 100\nlamp sphere bulb 0 0 4 1 1 4 .5\n",
    "polygon": "void light lamp 0 0 3 100 100 100\n"
               "lamp polygon panel 0 0 12 0 0 4  0 2 4  2 2 4  2 0 4\n",
    "distant": "void light sun 0 0 3 5e4 5e4 5e4\nsun source s 0 0 4 .3 .2 1 1\n",
}
# Lamps below the plane, for light transmitted up through it.
BELOW = "void light under 0 0 3 80 80 80\nunder sphere ubulb 0 0 4 -1 .5 -4 .5\n"
PLANE = "polygon p1 0 0 12 -10 -10 0  10 -10 0  10 10 0  -10 10 0\n"
BALL = "sphere ball 0 0 4 0 0 -1 1\n"

BRDF_CAL = """{ BRDFs of the light direction (lx, ly, lz) and size om, for the tests }
{ a lobe around the mirror direction of the view, in the perturbed frame }
mirx = Dx - 2*RdotP*NxP*-1;  miry = Dy - 2*RdotP*NyP*-1;  mirz = Dz - 2*RdotP*NzP*-1;
lobe(lx,ly,lz,om) = A5*exp(-((lx-mirx)^2+(ly-miry)^2+(lz-mirz)^2)/A6)*(1+0.1*RdotP) + 0.02*CrP + 0.01*CgP*CbP;
{ around the straight-through direction }
through(lx,ly,lz,om) = A7*exp(-((lx-Dx)^2+(ly-Dy)^2+(lz-Dz)^2)/A8) + om*10;
{ depends on the point and the normal }
spot(lx,ly,lz,om) = (1+sin(3*Px)*cos(2*Py))*abs(lz)*0.5 + 0.1*NzP*NzP;
{ a math error where Px < 0 }
bad(lx,ly,lz,om) = sqrt(Px)*0.5 + 0.1;
{ data BRDFs: the table's value v times a function of the light }
dv(v,lx,ly,lz,om) = v*(1+0.3*lz+0.2*lx-0.1*ly+om);
cx(lx,ly,lz,om) = 3*lx;
cy(lx,ly,lz,om) = 3*ly + 0.1*Py;
cz(lx,ly,lz,om) = Acos(abs(lz));
{ BRTDfunc: a glazing with a Fresnel-like specular part that differs by side }
fr = exp(-5.85*abs(Rdot)) - exp(-5.85);
brefl = A10 + fr*(1-A10) + 0.05*if(Rdot, 0, 1);
btrans = arg(11)*(1-fr)*(1+0.1*NzP*NzP);
bd(lx,ly,lz) = arg(12)*abs(lz)*(1+0.2*CrP);
bd2(lx,ly,lz,om) = arg(12)*(0.5+lx*lx) + om;
"""
# Two-dimensional table over (-5..5) x (-5..5), and one over the angle.
DATA2 = "2\n-5 5 3\n-5 5 3\n1 2 1.5\n.5 1 2\n3 1 1\n"
DATA1 = "1\n0 1.5708 4\n2 1.6 1 .4\n"

MATERIALS = {
    "plasfunc": "plasfunc m 2 lobe brdf.cal 0 6 .6 .5 .4 .3 2 .05",
    "plasfunc_xf": "plasfunc m 6 lobe brdf.cal -rz 40 -s 2 0 6 .6 .5 .4 .3 2 .05",
    "plasfunc_spot": "plasfunc m 2 spot brdf.cal 0 4 .6 .5 .4 .5",
    "metfunc": "metfunc m 2 lobe brdf.cal 0 6 .8 .7 .6 .6 1.5 .1",
    "metfunc_xf": "metfunc m 4 lobe brdf.cal -rx 20 0 6 .8 .7 .6 .6 1.5 .1",
    "transfunc": "transfunc m 2 through brdf.cal 0 8 .7 .6 .5 .05 .6 .5 3 .2",
    "transfunc_lobe": "transfunc m 2 lobe brdf.cal 0 6 .7 .6 .5 .3 .4 .3",
    "plasdata": "plasdata m 5 dv table2.dat brdf.cal cx cy 0 4 .5 .5 .5 .4",
    "metdata": "metdata m 5 dv table2.dat brdf.cal cy cx 0 4 .5 .6 .7 .6",
    "transdata": "transdata m 4 dv angle.dat brdf.cal cz 0 6 .5 .6 .7 .1 .5 .6",
    "transdata_xf": "transdata m 7 dv table2.dat brdf.cal cx cy -rz 90 0 6 .5 .6 .7 .1 .5 .6",
    "brtd": "BRTDfunc m 10 brefl brefl brefl btrans btrans*.9 btrans*.8 0 0 0 brdf.cal "
            "0 12 .2 .2 .2 .3 .3 .3 .1 .1 .1 .05 .8 .5",
    "brtd_dir": "BRTDfunc m 10 brefl brefl*.9 brefl btrans btrans btrans bd bd bd2 brdf.cal "
                "0 12 .1 .15 .2 .05 .05 .05 .2 .2 .2 .08 .5 .4",
    "brtd_xf": "BRTDfunc m 14 brefl brefl brefl btrans btrans btrans 0 bd 0 brdf.cal "
               "-rx 30 -s 2 0 12 .1 .1 .1 0 0 0 0 0 0 .1 .6 .8",
}


def write(name, text):
    with open(os.path.join(OUT, name), "w") as f:
        f.write(text)


def material(kind, modifier="void"):
    return f"{modifier} {MATERIALS[kind]}\n"


def main():
    os.makedirs(OUT, exist_ok=True)
    for f in os.listdir(OUT):
        os.remove(os.path.join(OUT, f))
    runs = []  # (group, name, files, rays, repeat, options, check)
    write("brdf.cal", BRDF_CAL)
    write("table2.dat", DATA2)
    write("angle.dat", DATA1)
    write("down.rays", "0 0 5 0 0 -1\n1 2 5 0.6 0 -0.8\n-3 4 2 0.3 -0.2 -1\n"
                       "2.5 -1 7 0 0 -1\n0 0 5 -0.8 0 -0.6\n0.5 -3 3 -0.1 0.6 -0.8\n"
                       "3 3 2 -0.6 -0.6 -0.5\n1.2 0.8 5 -0.05 0.1 -1\n")
    write("up.rays", "1 2 -5 0 0 1\n-2 1 -3 0.2 0.3 1\n0.5 0.5 -4 0.1 0.1 1\n-1 0.6 -2 0 0 1\n")
    write("ball.rays", "0 -5 -0.7 0 1 0\n0.4 -5 -1 0 1 0\n-0.6 -5 -0.5 0 1 0.1\n")
    write("both.rays", open(os.path.join(OUT, "down.rays")).read() +
          open(os.path.join(OUT, "up.rays")).read())

    # 1. Each material on a plane under each lamp (and, for the trans
    # types, a lamp below), seen from both sides.
    for kind in MATERIALS:
        for lamp, lamptext in LAMPS.items():
            if lamp != "sphere" and kind not in ("plasfunc", "metfunc", "transfunc", "plasdata",
                                                 "brtd_dir"):
                continue
            name = f"{kind}_{lamp}"
            write(f"plane_{name}.rad", lamptext + BELOW + material(kind) + "m " + PLANE)
            runs.append(("plane", name, [f"plane_{name}.rad"], "both.rays", 1, DET, "exact"))

    # 2. Balls (not flat), -bv-, patterns, textures, an instance.
    for kind in ("plasfunc", "metfunc", "transfunc", "metdata", "brtd_dir"):
        write(f"ball_{kind}.rad", LAMPS["sphere"] + material(kind) + "m " + BALL)
        runs.append(("shape", f"ball_{kind}", [f"ball_{kind}.rad"], "ball.rays", 1, DET, "exact"))
        runs.append(("shape", f"backface_{kind}", [f"plane_{kind}_sphere.rad"], "up.rays", 1,
                     DET + " -bv-", "exact"))
    chains = {
        "pattern": "void colorfunc c 4 .5+.3*sin(Px) .6 .4+.2*cos(Py) . 0 0\n",
        "texture": "void texfunc c 4 .2*sin(2*Px) .15*cos(Py) 0 . 0 0\n",
    }
    for chain, text in chains.items():
        for kind in ("plasfunc", "metfunc", "transfunc", "plasdata", "brtd_dir"):
            name = f"{chain}_{kind}"
            write(f"chain_{name}.rad", LAMPS["sphere"] + BELOW + text + material(kind, "c") +
                  "m " + PLANE)
            runs.append(("chain", name, [f"chain_{name}.rad"], "both.rays", 1, DET, "exact"))
    write("inst_obj.rad", material("metfunc_xf") + "m " + PLANE)
    with open(os.path.join(OUT, "inst_obj.oct"), "wb") as f:
        subprocess.run([os.path.join(BIN, "oconv"), "-f", "inst_obj.rad"], stdout=f,
                       check=True, env=ENV, cwd=OUT)
    write("instance.rad", LAMPS["sphere"] +
          "void instance i1 9 inst_obj.oct -rz 60 -t .5 .2 0 -s 1.5 0 0\n")
    runs.append(("chain", "instance", ["instance.rad"], "down.rays", 1, DET, "exact"))
    # Two glazings over a floor under the lamp and a sky that colours every
    # direction: transmitted, reflected and shadow rays through both.
    sky = ("void colorfunc skypat 4 1.5+Dx 1.5+Dy 1.5+Dz . 0 0\n"
           "skypat glow skyglow 0 0 4 1 1 1 0\nskyglow source sky 0 0 4 0 0 1 360\n")
    write("glazings.rad", LAMPS["sphere"] + sky + material("brtd", "void").replace(" m ", " g1 ") +
          "g1 " + PLANE + material("brtd_dir").replace(" m ", " g2 ") +
          "g2 polygon p2 0 0 12 -10 -10 -2  10 -10 -2  10 10 -2  -10 10 -2\n"
          "void plastic flr 0 0 5 .5 .5 .5 0 0\n"
          "flr polygon fl 0 0 12 -10 -10 -4  10 -10 -4  10 10 -4  -10 10 -4\n")
    write("glazings.rays", open(os.path.join(OUT, "both.rays")).read() +
          "0 0 -3 0 0 1\n2 1 -3 0.4 0.2 -1\n")
    for opts in ("", " -I"):
        runs.append(("chain", "glazings" + opts.replace(" -", "_"), ["glazings.rad"],
                     "glazings.rays", 1, DET + opts, "exact"))

    # 3. -ab 1 without a cache, and -i (transfunc is metered, not passed).
    box = LIT_BOX
    for kind in ("metfunc", "transfunc", "brtd_dir"):
        write(f"ab1_{kind}.rad", box + material(kind) +
              "m polygon top 0 0 12 -1 -1 -0.5  1 -1 -0.5  1 1 -0.5  -1 1 -0.5\n")
        runs.append(("ab1", kind, [f"ab1_{kind}.rad"], "ab1.rays", 64,
                     "-u+ -ab 1 -aa 0 -ad 256 -as 0", "noise"))
    write("ab1.rays", "0.3 0.2 1 0 0 -1\n-0.5 0.4 1 0.2 0 -1\n")
    write("irr.rays", "0.3 0.2 1 0 0 -1\n-1.5 0.4 1 0 0 -1\n")
    for kind in ("transfunc", "brtd_dir"):
        runs.append(("ab1", f"irradiance_{kind}", [f"ab1_{kind}.rad"], "irr.rays", 1,
                     DET + " -i -ab 0", "exact"))

    # 4. Errors and compute errors.
    errors = {
        "few_reals": "void plasfunc m 2 lobe brdf.cal 0 3 .5 .5 .5\n",
        "trans_reals": "void transfunc m 2 through brdf.cal 0 5 .5 .5 .5 0 .1\n",
        "few_strings": "void metfunc m 1 lobe 0 4 .5 .5 .5 .5\n",
        "data_strings": "void plasdata m 3 dv table2.dat brdf.cal 0 4 .5 .5 .5 .5\n",
        "compute": "void plasfunc m 2 bad brdf.cal 0 4 .5 .5 .5 .5\n",
        "brtd_strings": "void BRTDfunc m 9 .1 .1 .1 .5 .5 .5 0 0 0 0 9 0 0 0 0 0 0 0 0 0\n",
        "brtd_reals": "void BRTDfunc m 10 .1 .1 .1 .5 .5 .5 0 0 0 . 0 8 0 0 0 0 0 0 0 0\n",
        "brtd_compute": "void BRTDfunc m 10 brefl brefl brefl sqrt(Px)*.3 .5 .5 0 0 0 brdf.cal "
                        "0 12 .1 .1 .1 0 0 0 0 0 0 .1 .6 .8\n",
    }
    for name, text in errors.items():
        write(f"error_{name}.rad", LAMPS["sphere"] + text + "m " + PLANE)
        runs.append(("brdferror", name, [f"error_{name}.rad"], "down.rays", 1, DET, "exact"))

    run_and_write(runs, radiance, OUT,
                   "# Real Radiance 5.4a's answers for the BRDF-function material cases of\n"
                   "# tests/direct/direct_matrix_test.cpp, written by\n"
                   "# tests/direct/generate_brdf.py (format as in generate.py).\n")


if __name__ == "__main__":
    main()
