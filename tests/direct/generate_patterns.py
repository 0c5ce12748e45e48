#!/usr/bin/env python3
# Generates the pattern and sky cases (tests/data/patterns/) for
# tests/direct/direct_matrix_test.cpp, with REAL Radiance 5.4a's answers. A
# developer's tool: it needs ../shared/reference/radiance-5.4a (or
# RADIANCE=<its folder>); the test only reads what this writes. Same
# expected.txt format as generate.py (see there).
#
#   tests/direct/generate_patterns.py
#
# Radiance evaluates the skies with its own skybright.cal and perezlum.cal;
# the test runs lazyrad with RAYPATH unset, so lazyrad uses its own lib/.
import math
import os
import subprocess
import sys
import tempfile

from matrix_data import mean_and_sem, write_expected

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
OUT = os.path.join(ROOT, "tests", "data", "patterns")
RADIANCE = os.environ.get(
    "RADIANCE", os.path.normpath(os.path.join(ROOT, "..", "shared", "reference", "radiance-5.4a")))
BIN = os.path.join(RADIANCE, "bin")
ENV = dict(os.environ, RAYPATH="." + os.pathsep + os.path.join(RADIANCE, "lib"))

PLANE = "polygon p 0 0 12 -10 -10 0  10 -10 0  10 10 0  -10 10 0"
DET = "-u- -dj 0 -dt 0"


def unit(v):
    n = math.sqrt(sum(c * c for c in v))
    return tuple(c / n for c in v)


def fmt(v):
    return " ".join("%.17g" % c for c in v)


def write(name, text):
    with open(os.path.join(OUT, name), "w") as f:
        f.write(text)


def radiance(files, rays, repeat, options, tmp, out=OUT):
    """Real Radiance's status, messages, rows and (repeat > 1) standard errors
    for `rays` (a file in `out`) through the scene `files` (in `out`)."""
    octree = os.path.join(tmp, "scene.oct")
    with open(octree, "wb") as f:
        oc = subprocess.run([os.path.join(BIN, "oconv")] + files, stdout=f,
                            stderr=subprocess.PIPE, env=ENV, cwd=out)
    if oc.returncode != 0:
        return oc.returncode, [l.replace(os.path.join(BIN, "oconv"), "oconv")
                               for l in oc.stderr.decode().splitlines()], [], []
    with open(os.path.join(out, rays)) as f:
        lines = [l for l in f.read().splitlines() if l.strip()]
    r = subprocess.run([os.path.join(BIN, "rtrace"), "-h"] + options.split() + [octree],
                       input="".join((l + "\n") * repeat for l in lines), capture_output=True,
                       text=True, env=ENV, cwd=out)
    rows = [[float(x) for x in l.split()] for l in r.stdout.splitlines() if l.strip()]
    err = [l.replace(os.path.join(BIN, "rtrace"), "rtrace") for l in r.stderr.splitlines()]
    sems = []
    if repeat > 1 and r.returncode == 0:
        rows, sems = mean_and_sem(rows, len(lines), repeat)
    return r.returncode, err, rows, sems


def main():
    os.makedirs(OUT, exist_ok=True)
    for f in os.listdir(OUT):
        os.remove(os.path.join(OUT, f))
    runs = []  # (group, name, files, rays, repeat, options, check)

    # Rays onto the plane z = 0 from above: straight down, and the oblique
    # ray of the specification's test values (hits P = 4.75 2 0).
    write("down.rays", "1 2 5 0.6 0 -0.8\n0 0 5 0 0 -1\n-3 4 2 0.3 -0.2 -1\n2.5 -1 7 0 0 -1\n")
    write("up.rays", "1 2 -5 0 0 1\n")  # the plane's back side

    # 1. brightfunc on a light: each ray quantity and the built-ins.
    exprs = {
        "px_half": "Px/2", "neg_px": "-Px", "divzero": "1/(Px-4.75)", "sqrtneg": "sqrt(-Px)",
        "sqrt_lib": "Sqrt(-1)+3", "dir": "Dx*10+Dy*100+Dz", "normal": "Nx+Ny+Nz*3+Rdot",
        "length": "T", "scale": "S", "args": "arg(0)+A1*A2", "uv": "Lu+Lv+1",
        "frame": "Ix+Jy*2+Kz*3+Tx+Ty+Tz", "noise": "noise3(Px,Py,Pz)+2", "rand": "rand(Px)+1",
        "trig": "sin(Px)+cos(Py)+atan2(Px,Py)", "select": "select(2,Px,Py,3)",
        "defined": "if(Px-3,Py,-Py)",
    }
    for name, e in exprs.items():
        write(f"bright_{name}.rad",
              f"void brightfunc pat\n2 {e} .\n0\n2 2.5 4\n"
              f"pat light lit 0 0 3 2 2 2\nlit {PLANE}\n")
        runs.append(("bright", name, [f"bright_{name}.rad"], "down.rays", 1, "-ab 0", "exact"))
    runs.append(("bright", "backside", ["bright_px_half.rad"], "up.rays", 1, "-ab 0", "exact"))

    # 2. colorfunc with transforms: the point, direction and normal in pattern space.
    xforms = {"none": "", "t": "-t 1 2 3", "rz": "-rz 90", "s": "-s 2", "mx": "-mx",
              "iter": "-t 1 0 0 -i 2 -rz 90", "mixed": "-rx 30 -ry 20 -s 0.5 -t 1 1 1"}
    for xname, xf in xforms.items():
        for qname, q in (("p", "Px Py Pz"), ("d", "Dx Dy Dz"), ("n", "Nx Ny Nz"),
                         ("frame", "S Tx Ty")):
            words = q.split() + ["."] + xf.split()
            write(f"color_{qname}_{xname}.rad",
                  f"void colorfunc pat\n{len(words)} {' '.join(words)}\n0\n0\n"
                  f"pat light lit 0 0 3 1 1 1\nlit {PLANE}\n")
            runs.append(("colorxf", f"{qname}_{xname}", [f"color_{qname}_{xname}.rad"],
                         "down.rays", 1, "-ab 0", "exact"))

    # 3. Chains: patterns between the surface and its material, below the
    # material, chained, an alias with its own modifier (spec 11.14 item 14).
    chains = {
        "below": "void brightfunc b3 2 3 . 0 0\nb3 light l1 0 0 3 1 2 3\nl1 " + PLANE + "\n",
        "between": "void light l1 0 0 3 1 2 3\nl1 brightfunc b5 2 5 . 0 0\nb5 " + PLANE + "\n",
        "both": "void brightfunc b3 2 3 . 0 0\nb3 light l1 0 0 3 1 2 3\n"
                "l1 colorfunc c 4 1 2 Px . 0 0\nc " + PLANE + "\n",
        "chained": "void brightfunc b3 2 3 . 0 0\nb3 brightfunc b2 2 Py . 0 0\n"
                   "b2 light l1 0 0 3 1 2 3\nl1 " + PLANE + "\n",
        "alias": "void brightfunc b3 2 3 . 0 0\nvoid light l1 0 0 3 1 2 3\n"
                 "b3 alias l1b l1\nl1b " + PLANE + "\n",
        "alias_pattern": "void brightfunc b3 2 3 . 0 0\nvoid light l1 0 0 3 1 2 3\n"
                         "l1 alias b4 b3\nb4 " + PLANE + "\n",
        "inherit": "void brightfunc b3 2 3 . 0 0\nb3 light l1 0 0 3 1 2 3\n"
                   "inherit alias l2 l1\nl2 " + PLANE + "\n",
        "plastic": "void light lamp 0 0 3 100 100 100\nlamp sphere bulb 0 0 4 0 0 6 .5\n"
                   "void colorfunc tint 4 Px/10+.5 .5 Py/10+.5 . 0 0\n"
                   "tint plastic paint 0 0 5 .6 .6 .6 0 0\npaint " + PLANE + "\n",
        "metal": "void light lamp 0 0 3 100 100 100\nlamp sphere bulb 0 0 4 0 0 6 .5\n"
                 "void brightfunc shine 2 .5+.1*Px . 0 0\n"
                 "shine metal m 0 0 5 .8 .7 .6 .05 .1\nm " + PLANE + "\n",
    }
    for name, text in chains.items():
        write(f"chain_{name}.rad", text)
        runs.append(("chain", name, [f"chain_{name}.rad"], "down.rays", 1, f"{DET} -ab 0",
                     "exact"))
    runs.append(("chain", "alias_backside", ["chain_alias.rad"], "up.rays", 1, "-ab 0", "exact"))

    # 4. Patterned light sources lighting a floor: the pattern is evaluated
    # for each shadow ray (D from the floor point toward the source).
    write("sensors.pts", "".join(f"{fmt(p)} 0 0 1\n" for p in
                                 ((0, 0, 0.01), (1, 0.5, 0.01), (-2, 1, 0.01), (3, -3, 0.01))))
    lamps = {
        "quad": "src polygon q 0 0 12 -.5 -.5 2  -.5 .5 2  .5 .5 2  .5 -.5 2",
        "sphere": "src sphere s 0 0 4 0 0 2 .3",
        "ring": "src ring r 0 0 8 0 0 2 0 0 -1 0 .4",
    }
    pats = {"dz": "void brightfunc pat 2 Dz*2 . 0 0\n",
            "dx": "void colorfunc pat 4 1+Dx 1 1-Dx . 0 0\n",
            "below": None}
    for lname, lamp in lamps.items():
        for pname, pat in pats.items():
            if pat is None:
                text = ("void light l 0 0 3 10 10 10\nl brightfunc pat 2 Dz*2 . 0 0\n"
                        + lamp.replace("src ", "pat ") + "\n")
            else:
                text = pat + "pat light src 0 0 3 10 10 10\n" + lamp + "\n"
            text += ("void plastic floor 0 0 5 .5 .5 .5 0 0\nfloor polygon fl 0 0 12 "
                     "-10 -10 -.001  10 -10 -.001  10 10 -.001  -10 10 -.001\n")
            write(f"lamp_{lname}_{pname}.rad", text)
            for rname, options in (("ds02", f"{DET} -ds 0.2 -I"), ("ds0", f"{DET} -ds 0 -I")):
                runs.append(("lamp", f"{lname}_{pname}_{rname}", [f"lamp_{lname}_{pname}.rad"],
                             "sensors.pts", 1, options, "exact"))

    # 5. Skies from real gensky and gendaylit, with the glow hemispheres a
    # daylighting tool adds. Directions all round (-ab 0), and an upward
    # sensor at -ab 1 against Radiance's mean over many repeats.
    dirs = []
    for i in range(48):
        z = (i + 0.5) / 48
        r = math.sqrt(1 - z * z)
        dirs.append((r * math.cos(2.4 * i), r * math.sin(2.4 * i), z))
    for i in range(8):
        z = -(i + 0.5) / 8
        r = math.sqrt(1 - z * z)
        dirs.append((r * math.cos(2.4 * i), r * math.sin(2.4 * i), z))
    write("sky.rays", "".join(f"0 0 0 {fmt(d)}\n" for d in dirs))
    write("up.pts", "0 0 0 0 0 1\n0 0 0 0.6 0 0.8\n")
    hemispheres = ("skyfunc glow sky_glow 0 0 4 1 1 1 0\nsky_glow source sky 0 0 4 0 0 1 180\n"
                   "skyfunc glow ground_glow 0 0 4 1 .8 .5 0\n"
                   "ground_glow source ground 0 0 4 0 0 -1 180\n")
    skies = {
        "c": ["gensky", "3", "21", "12", "-a", "40", "-o", "105", "-m", "105", "-c", "-B", "558.659"],
        "ps": ["gensky", "3", "21", "12", "-a", "40", "-o", "105", "-m", "105", "+s"],
        "ms": ["gensky", "3", "21", "12", "-a", "40", "-o", "105", "-m", "105", "-s"],
        "pi": ["gensky", "6", "21", "9", "-a", "40", "-o", "105", "-m", "105", "+i"],
        "mi": ["gensky", "6", "21", "9", "-a", "40", "-o", "105", "-m", "105", "-i"],
        "u": ["gensky", "3", "21", "12", "-u"],
        "ang": ["gensky", "-ang", "45", "0", "-c", "-B", "558.659", "-g", "0.2"],
        "perez_w": ["gendaylit", "6", "21", "14", "-a", "40", "-o", "105", "-m", "105", "-W", "500", "100"],
        "perez_g": ["gendaylit", "6", "21", "14", "-a", "40", "-o", "105", "-m", "105", "-G", "700", "150"],
    }
    for name, command in skies.items():
        sky = subprocess.run([os.path.join(BIN, command[0])] + command[1:], capture_output=True,
                             text=True, check=True).stdout
        write(f"sky_{name}.rad", sky + hemispheres)
        runs.append(("sky", f"{name}_ab0", [f"sky_{name}.rad"], "sky.rays", 1, "-ab 0", "exact"))
        runs.append(("sky", f"{name}_ab1", [f"sky_{name}.rad"], "up.pts", 64,
                     "-u+ -I -ab 1 -aa 0 -ad 8192 -as 0", "noise"))

    # 6. Errors: each a one-line fatal error from both programs.
    errors = {
        "undefined": "void brightfunc pat 2 nosuchvar . 0 0\npat light l 0 0 3 1 1 1\nl " + PLANE + "\n",
        "missing_file": "void brightfunc pat 2 x nosuch.cal 0 0\npat light l 0 0 3 1 1 1\nl " + PLANE + "\n",
        "bad_transform": "void brightfunc pat 5 Px . -t 1 0 0 0\npat light l 0 0 3 1 1 1\nl " + PLANE + "\n",
        "few_strings": "void brightfunc pat 1 Px 0 0\npat light l 0 0 3 1 1 1\nl " + PLANE + "\n",
        "conflicting": "void light l0 0 0 3 1 1 1\nl0 light l 0 0 3 1 1 1\nl " + PLANE + "\n",
        "syntax": "void brightfunc pat 2 Px+*2 . 0 0\npat light l 0 0 3 1 1 1\nl " + PLANE + "\n",
    }
    for name, text in errors.items():
        write(f"error_{name}.rad", text)
        runs.append(("error", name, [f"error_{name}.rad"], "down.rays", 1, "-ab 0", "exact"))

    blocks = []
    with tempfile.TemporaryDirectory() as tmp:
        for group, name, files, rays, repeat, options, check in runs:
            ref_repeat = repeat
            if check == "noise":
                lazy_repeat = 16  # lazyrad's repeats; Radiance's mean is over `repeat`
            else:
                lazy_repeat = repeat
            status, err, rows, sems = radiance(files, rays, ref_repeat, options, tmp)
            blocks.append((group, name, files, rays, lazy_repeat, options, check, status, err,
                           rows, sems if check == "noise" else [],
                           [f"Radiance's mean over {ref_repeat} repeats"] if check == "noise" else []))
    keys = "group name files rays repeat options check status err rows sems notes".split()
    write_expected(os.path.join(OUT, "expected.txt"),
                   "# Real Radiance 5.4a's answers for the pattern and sky cases of\n"
                   "# tests/direct/direct_matrix_test.cpp, written by\n"
                   "# tests/direct/generate_patterns.py (format as in generate.py).\n",
                   [dict(zip(keys, b)) for b in blocks])
    print(f"{len(blocks)} runs written to {OUT}", file=sys.stderr)


if __name__ == "__main__":
    main()
