#!/usr/bin/env python3
# Generates the texture and mixture cases (tests/data/textures/) for
# tests/direct/direct_matrix_test.cpp, with REAL Radiance 5.4a's answers. A
# developer's tool: it needs ../shared/reference/radiance-5.4a (or
# RADIANCE=<its folder>); the test only reads what this writes. Same
# expected.txt format as generate.py (see there).
#
#   tests/direct/generate_textures.py
#
# Covers texfunc (radiance-functions.md §11.8) on every material that uses the
# perturbed normal (radiance-notes.md §2.7-2.8), with transforms, chains and
# the illegal-perturbation warning, and mixfunc (§11.9) of materials, void,
# patterns, textures and other mixtures, as seen by primary rays, shadow rays
# and light sources, at -ab 0 and (as a mean of repeats) at -ab 1.
import os
import subprocess
import sys
import tempfile

from generate_patterns import radiance
from matrix_data import LIT_BOX, run_and_write

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
OUT = os.path.join(ROOT, "tests", "data", "textures")
# -ss 0 puts a rough surface's one specular sample on the (perturbed) mirror
# direction, so that the sampled highlights compare exactly.
DET = "-u- -dj 0 -dt 0 -ss 0"

PLANE = "polygon p1 0 0 12 -10 -10 0  10 -10 0  10 10 0  -10 10 0"
# A lamp above and an all-round sky whose colour encodes the direction, so
# that every reflected or transmitted direction shows in the value.
LIGHTS = ("void light lamp 0 0 3 100 100 100\nlamp sphere bulb 0 0 4 1 1 4 .5\n"
          "void colorfunc skypat 4 1.5+Dx 1.5+Dy 1.5+Dz . 0 0\n"
          "skypat glow skyglow 0 0 4 1 1 1 0\nskyglow source sky 0 0 4 0 0 1 360\n")
BEHIND = ("void light bk 0 0 3 8 8 8\n"
          "bk polygon back 0 0 12 -10 -10 -1  10 -10 -1  10 10 -1  -10 10 -1\n")
FLOOR = ("void plastic floor 0 0 5 .5 .5 .5 0 0\nfloor polygon fl 0 0 12 "
         "-10 -10 -2  10 -10 -2  10 10 -2  -10 10 -2\n")

MATERIALS = {
    "plastic": "plastic m 0 0 5 .6 .5 .4 .05 .08",
    "plastic_pure": "plastic m 0 0 5 .6 .5 .4 .05 0",
    "metal": "metal m 0 0 5 .8 .7 .6 .9 .1",
    "metal_pure": "metal m 0 0 5 .8 .7 .6 .9 0",
    "mirror": "mirror m 0 0 3 .9 .8 .7",
    "glass": "glass m 0 0 3 .8 .7 .6",
    "glass_n": "glass m 0 0 4 .8 .7 .6 1.7",
    "trans": "trans m 0 0 7 .6 .5 .4 .05 0 .5 .8",
    "trans_rough": "trans m 0 0 7 .6 .5 .4 .05 .1 .5 .5",
    # Clear media: rays refracted into them escape to the sky, and Radiance
    # attenuates a coloured medium over an infinite path to black.
    "dielectric": "dielectric m 0 0 5 1 1 1 1.5 0",
    "interface": "interface m 0 0 8 1 1 1 1.5 1 1 1 1.2",
}

TEXTURES = {
    "const": "4 0.5 0 0 .",
    "wave": "4 .3*sin(Px) .2*cos(Py) 0 .",
    "xf": "8 .3*sin(Px) .2*cos(Py) 0 . -rz 90 -s 2",
    "xf2": "10 .2*Px .1 Py*.05 . -rx 30 -t 1 2 3",
}


def write(name, text):
    with open(os.path.join(OUT, name), "w") as f:
        f.write(text)


def main():
    os.makedirs(OUT, exist_ok=True)
    for f in os.listdir(OUT):
        os.remove(os.path.join(OUT, f))
    runs = []  # (group, name, files, rays, repeat, options, check)

    write("down.rays", "0 0 5 0 0 -1\n1 2 5 0.6 0 -0.8\n-3 4 2 0.3 -0.2 -1\n"
                       "2.5 -1 7 0 0 -1\n0 0 5 -0.8 0 -0.6\n")
    write("up.rays", "1 2 -5 0 0 1\n-2 1 -3 0.2 0.3 1\n")
    write("sphere.rays", "0 -5 0.3 0 1 0\n0.4 -5 0 0 1 0\n")
    write("sensors.pts", "0 0 -1.99 0 0 1\n1 0.5 -1.99 0 0 1\n-2 1 -1.99 0 0 1\n")

    # 1. texfunc on each material: values and shading normals (-on) from
    # above, and from below for those that shade both sides.
    for mname, mat in MATERIALS.items():
        for tname, tex in TEXTURES.items():
            name = f"tex_{mname}_{tname}"
            write(f"{name}.rad", LIGHTS + f"void texfunc t\n{tex}\n0\n0\nt {mat}\nm {PLANE}\n")
            runs.append(("texture", f"{mname}_{tname}", [f"{name}.rad"], "down.rays", 1,
                         f"{DET} -ab 0 -ovn", "exact"))
            if mname.startswith(("trans", "glass", "dielectric", "interface")):
                runs.append(("texture", f"{mname}_{tname}_back", [f"{name}.rad"], "up.rays", 1,
                             f"{DET} -ab 0 -ovn", "exact"))
    # On a sphere (not flat), and the spec's test values (§11.14 item 9).
    write("tex_sphere.rad", LIGHTS + "void texfunc t 4 .2*sin(5*Pz) 0 .1 . 0 0\n"
          "t plastic m 0 0 5 .6 .5 .4 .05 .05\nm sphere ball 0 0 4 0 0 0 1\n")
    runs.append(("texture", "sphere", ["tex_sphere.rad"], "sphere.rays", 1,
                 f"{DET} -ab 0 -ovnN", "exact"))
    spec = {"half": "4 0.5 0 0 .", "minus2": "4 -2 0 0 .", "illegal": "4 0 0 -1 .",
            "rz_s": "8 0.5 0 0 . -rz 90 -s 2", "s": "6 0.5 0 0 . -s 2"}
    for tname, tex in spec.items():
        write(f"spec_{tname}.rad", LIGHTS + f"void texfunc t\n{tex}\n0\n0\n"
              f"t plastic m 0 0 5 .6 .6 .6 0 0\nm {PLANE}\n")
        runs.append(("texspec", tname, [f"spec_{tname}.rad"], "down.rays", 1,
                     f"{DET} -ab 0 -onNv", "exact"))

    # 2. Chains: pattern and texture in either order and place, two textures
    # adding up, a texture behind the material, an alias.
    chains = {
        "pattern_texture": "void colorfunc c 4 1 .5+.1*Px 1 . 0 0\n"
                           "c texfunc t 4 .3*sin(Px) 0 0 . 0 0\n"
                           "t plastic m 0 0 5 .6 .5 .4 .05 .08\nm " + PLANE + "\n",
        "texture_pattern": "void texfunc t 4 .3*sin(Px) 0 0 . 0 0\n"
                           "t colorfunc c 4 1 .5+.1*Px 1 . 0 0\n"
                           "c metal m 0 0 5 .6 .5 .4 .9 .1\nm " + PLANE + "\n",
        "two_textures": "void texfunc t1 4 .3 0 0 . 0 0\nt1 texfunc t2 4 0 .2*Py 0 . 0 0\n"
                        "t2 plastic m 0 0 5 .6 .5 .4 .05 0\nm " + PLANE + "\n",
        "between": "void mirror m 0 0 3 .9 .8 .7\nm texfunc t 4 .3*sin(Px) .1 0 . 0 0\n"
                   "t " + PLANE + "\n",
        "alias": "void texfunc t 4 .3*sin(Px) .1 0 . 0 0\nvoid plastic m0 0 0 5 .6 .5 .4 .05 0\n"
                 "t alias m m0\nm " + PLANE + "\n",
        "args": "void texfunc t 4 A1*sin(Px) A2 0 . 0 2 .3 .1\n"
                "t plastic m 0 0 5 .6 .5 .4 .05 .08\nm " + PLANE + "\n",
    }
    for name, text in chains.items():
        write(f"chain_{name}.rad", LIGHTS + text)
        runs.append(("texchain", name, [f"chain_{name}.rad"], "down.rays", 1,
                     f"{DET} -ab 0 -ovn", "exact"))

    # 3. mixfunc: the specification's values (§11.14 items 10-12) ...
    mixes = {
        "lights": "l1 l2 0.25", "over": "l1 l2 2", "under": "l1 l2 -1",
        "fore_void": "l1 void 0.25", "void_back": "void l1 0.25", "px": "l1 l2 Px+0.5",
        "divzero": "l1 l2 1/(Px-0)",
    }
    base = BEHIND + "void light l1 0 0 3 4 4 4\nvoid light l2 0 0 3 1 2 3\n"
    for name, args in mixes.items():
        write(f"mix_{name}.rad", base + f"void mixfunc mx 4 {args} . 0 0\nmx {PLANE}\n")
        runs.append(("mixspec", name, [f"mix_{name}.rad"], "down.rays", 1, "-ab 0", "exact"))
    brights = base + "void brightfunc b2 2 2 . 0 0\nvoid brightfunc b4 2 4 . 0 0\n"
    write("mix_patterns_l1.rad", brights + f"l1 mixfunc mx 4 b2 b4 0.25 . 0 0\nmx {PLANE}\n")
    write("mix_patterns_void.rad", brights + f"void mixfunc mx 4 b2 b4 0.25 . 0 0\nmx {PLANE}\n")
    write("mix_pattern_l2.rad", base + "void colorfunc c 4 1 2 3 . 0 0\n"
          f"void mixfunc mx 4 c l2 0.5 . 0 0\nmx {PLANE}\n")
    for name in ("patterns_l1", "patterns_void", "pattern_l2"):
        runs.append(("mixspec", name, [f"mix_{name}.rad"], "down.rays", 1, "-ab 0", "exact"))

    # ... and of shading materials: two materials, a material and void (a
    # hole), nested, with patterns and textures on each branch, mixing two
    # textures under a material.
    shaded = {
        "two": "void plastic a 0 0 5 .6 .5 .4 .05 .08\nvoid metal b 0 0 5 .8 .7 .6 .9 0\n"
               "void mixfunc mx 4 a b .5+.4*sin(Px) . 0 0\nmx " + PLANE + "\n",
        "hole": "void plastic a 0 0 5 .6 .5 .4 .05 .08\n"
                "void mixfunc mx 4 a void .3 . 0 0\nmx " + PLANE + "\n",
        "hole_back": "void mirror a 0 0 3 .9 .8 .7\n"
                     "void mixfunc mx 4 void a .7 . 0 0\nmx " + PLANE + "\n",
        "nested": "void plastic a 0 0 5 .6 .5 .4 .05 .08\nvoid metal b 0 0 5 .8 .7 .6 .9 0\n"
                  "void glass c 0 0 3 .8 .7 .6\n"
                  "void mixfunc ab 4 a b .5+.4*sin(Px) . 0 0\n"
                  "void mixfunc mx 4 ab c .2+.1*Py . 0 0\nmx " + PLANE + "\n",
        "branch_patterns": "void colorfunc ca 4 1 .5+.1*Px 1 . 0 0\n"
                           "ca plastic a 0 0 5 .6 .5 .4 .05 .08\n"
                           "void texfunc tb 4 .3*sin(Px) .1 0 . 0 0\n"
                           "void metal b0 0 0 5 .8 .7 .6 .9 0\ntb alias b b0\n"
                           "void mixfunc mx 4 a b .6 . 0 0\n"
                           "mx brightfunc bb 2 .5+.1*Py . 0 0\nbb " + PLANE + "\n",
        "modifier_on_mixture": "void plastic a 0 0 5 .6 .5 .4 .05 .08\n"
                               "void brightfunc bb 2 .5 . 0 0\nbb mixfunc mx 4 a void .6 . 0 0\n"
                               "mx " + PLANE + "\n",
        "pattern_on_branch": "void plastic a 0 0 5 .6 .5 .4 .05 .08\n"
                             "a brightfunc pa 2 .5+.1*Px . 0 0\n"
                             "void mirror b 0 0 3 .9 .8 .7\n"
                             "b texfunc tb 4 .2 .1*Py 0 . 0 0\n"
                             "void mixfunc mx 4 pa tb .4 . 0 0\nmx " + PLANE + "\n",
        "textures_under": "void texfunc t1 4 .4 0 0 . 0 0\nvoid texfunc t2 4 0 -.4 0 . 0 0\n"
                          "void plastic m 0 0 5 .6 .5 .4 .05 0\n"
                          "m mixfunc mx 4 t1 t2 .3+.1*Px . 0 0\nmx " + PLANE + "\n",
        "xf": "void plastic a 0 0 5 .6 .5 .4 .05 .08\nvoid metal b 0 0 5 .8 .7 .6 .9 0\n"
              "void mixfunc mx 6 a b .5+.4*sin(Px) . -s 2 0 0\nmx " + PLANE + "\n",
    }
    for name, text in shaded.items():
        write(f"mixmat_{name}.rad", LIGHTS + BEHIND + text)
        runs.append(("mixmat", name, [f"mixmat_{name}.rad"], "down.rays", 1,
                     f"{DET} -ab 0 -ovn", "exact"))
    runs.append(("mixmat", "hole_from_below", ["mixmat_hole.rad"], "up.rays", 1,
                 f"{DET} -ab 0 -ovn", "exact"))

    # 4. Mixtures seen by shadow rays and light sources: a half-hole
    # occluder, a mixture of a glass and a plastic as occluder, a patterned
    # lamp by mixture (a source), a mixture of a light and void (no source).
    lamp = "sphere bulb 0 0 4 0 0 2 .3\n"
    shadows = {
        "hole": "void light l 0 0 3 10 10 10\nl " + lamp +
                "void plastic a 0 0 5 .3 .3 .3 0 0\nvoid mixfunc mx 4 a void .25 . 0 0\n"
                "mx polygon occ 0 0 12 -5 -5 1  5 -5 1  5 5 1  -5 5 1\n",
        "glass": "void light l 0 0 3 10 10 10\nl " + lamp +
                 "void plastic a 0 0 5 .3 .3 .3 0 0\nvoid glass g 0 0 3 .8 .7 .6\n"
                 "void mixfunc mx 4 g a .5+.2*Px . 0 0\n"
                 "mx polygon occ 0 0 12 -5 -5 1  5 -5 1  5 5 1  -5 5 1\n",
        "pattern_lamp": "void light l 0 0 3 10 10 10\nvoid brightfunc b2 2 2 . 0 0\n"
                        "void colorfunc c 4 1 Dz*-1 .5 . 0 0\n"
                        "l mixfunc mx 4 b2 c .3 . 0 0\nmx " + lamp,
        "light_void": "void light l 0 0 3 10 10 10\nvoid mixfunc mx 4 l void .5 . 0 0\nmx " + lamp,
    }
    for name, text in shadows.items():
        write(f"mixshadow_{name}.rad", text + FLOOR)
        runs.append(("mixshadow", name, [f"mixshadow_{name}.rad"], "sensors.pts", 1,
                     f"{DET} -ds 0 -I -ab 0", "exact"))

    # 5. -ab 1 (no cache): a textured floor and a mixed floor in a closed box
    # under a lamp; the mean of repeats against Radiance's.
    box = LIT_BOX
    write("ab1_texture.rad", box + "void texfunc t 4 .3*sin(3*Px) .3*cos(3*Py) 0 . 0 0\n"
          "t plastic m 0 0 5 .6 .5 .4 .05 .08\n"
          "m polygon top 0 0 12 -1 -1 -0.5  1 -1 -0.5  1 1 -0.5  -1 1 -0.5\n")
    write("ab1_mixture.rad", box + "void plastic a 0 0 5 .6 .5 .4 0 0\n"
          "void metal b 0 0 5 .8 .7 .6 .9 .1\nvoid mixfunc mx 4 a b .5+.4*sin(3*Px) . 0 0\n"
          "mx polygon top 0 0 12 -1 -1 -0.5  1 -1 -0.5  1 1 -0.5  -1 1 -0.5\n")
    write("ab1.rays", "0.3 0.2 1 0 0 -1\n-0.5 0.4 1 0.2 0 -1\n")
    for name in ("texture", "mixture"):
        runs.append(("ab1", name, [f"ab1_{name}.rad"], "ab1.rays", 64,
                     "-u+ -ab 1 -aa 0 -ad 256 -as 0", "noise"))

    # 6. Errors, each a one-line fatal error from both programs.
    errors = {  # name: (objects, the test surface's modifier)
        "tex_few_strings": ("void texfunc t 3 1 0 0 0 0\nt plastic m 0 0 5 .5 .5 .5 0 0\n", "m"),
        "mix_few_strings": ("void plastic a 0 0 5 .5 .5 .5 0 0\n"
                            "void mixfunc mx 3 a void .5 0 0\n", "mx"),
        "mix_undefined": ("void mixfunc mx 4 nosuch void .5 . 0 0\n", "mx"),
        "mix_inappropriate": ("void light l1 0 0 3 1 1 1\nvoid light l2 0 0 3 1 2 3\n"
                              "l1 mixfunc mx 4 l1 l2 .5 . 0 0\n", "mx"),
    }
    for name, (text, surface) in errors.items():
        # A lamp, so that neither program warns of missing light sources.
        write(f"error_{name}.rad", "void light lamp 0 0 3 1 1 1\nlamp sphere s 0 0 4 0 0 10 1\n" +
              text + f"{surface} {PLANE}\n")
        runs.append(("texerror", name, [f"error_{name}.rad"], "down.rays", 1, "-ab 0", "exact"))

    run_and_write(runs, radiance, OUT,
                   "# Real Radiance 5.4a's answers for the texture and mixture cases of\n"
                   "# tests/direct/direct_matrix_test.cpp, written by\n"
                   "# tests/direct/generate_textures.py (format as in generate.py).\n")


if __name__ == "__main__":
    main()
