#!/usr/bin/env python3
# Generates the BSDF and aBSDF cases (tests/data/bsdf/) for
# tests/direct/direct_matrix_test.cpp, with REAL Radiance 5.4a's answers. A
# developer's tool: it needs ../shared/reference/radiance-5.4a (or
# RADIANCE=<its folder>); the test only reads what this writes. Same
# expected.txt format as generate.py (see there).
#
#   tests/direct/generate_bsdf.py
#
# The BSDF files are written here too, as LBNL WINDOW writes Klems matrices:
# a glazing-like one (a straight-through peak, sampled front reflection),
# a redirecting "louvre" (light sent toward +y, so the up vector matters;
# incident directions in rows), one on a basis the file defines itself, one
# on the full Klems basis with transmission given for one side only
# (reciprocity), one with nothing but transmission (aBSDF's peak), one
# whose transmission is all Lambertian, and one whose matrices are
# asymmetric (which of the direct light's two directions is the incident).
# Covers: each file on a plane under three kinds of source, seen from both
# sides; up vectors (constant, from the position, transformed, along the
# normal: a warning); aBSDF's through peak for view and shadow rays; BSDF
# proxies of either sign with detail behind them; the added diffuse reals;
# a pattern; -bv-; -i; the sampled rays at -ss 0.5, 1 and 4 (means of
# repeats under a sky that colours every direction); -ab 1; argument errors.
import math
import os
import subprocess

from generate_aniso import LAMPS, PLANE, SKY
from generate_patterns import BIN, ENV, radiance
from matrix_data import LIT_BOX, fresh_folder, run_and_write

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
OUT = os.path.join(ROOT, "tests", "data", "bsdf")
# -ss 0: no jitter of the view direction, and a sampled ray's direction
# fixed (up to libBSDF's finest cell): deterministic.
DET = "-u- -dj 0 -dt 0 -ss 0"

HALF = [(0, 1), (6.5, 8), (19.5, 12), (32.5, 16), (46.5, 20), (61.5, 12), (76.5, 4)]
FULL = [(0, 1), (5, 8), (15, 16), (25, 20), (35, 24), (45, 24), (55, 24), (65, 16), (75, 12)]
QUARTER = [(0, 1), (9, 8), (27, 12), (46, 12), (66, 8)]
PATTERN = "void colorfunc c 4 .5+.3*sin(Px) .6 .4+.2*cos(Py) . 0 0\n"


def patches(rings):
    """(centre polar angle °, centre azimuth °, projected solid angle) per patch."""
    out = []
    bounds = [t for t, _ in rings] + [90]
    for k, (t0, n) in enumerate(rings):
        t1 = bounds[k + 1]
        ohm = math.pi * (math.cos(math.radians(t0)) ** 2 - math.cos(math.radians(t1)) ** 2) / n
        tc = 0.0 if k == 0 else 0.5 * (t0 + t1)
        out += [(tc, 360.0 * j / n, ohm) for j in range(n)]
    return out


def klems_xml(blocks, basis, rows=False, define=None, wavelengths=("Solar", "Visible"),
              digits=5):
    """blocks: {WINDOW direction: matrix[outgoing][incident]} in 1/sr."""
    s = ['<?xml version="1.0" encoding="UTF-8"?>',
         '<WindowElement xmlns="http://windows.lbl.gov" version="1.1">',
         '<WindowElementType>System</WindowElementType>', '<Optical>', '<Layer>',
         '<Material><Name>test</Name><Thickness unit="Millimeter">6</Thickness></Material>',
         '<DataDefinition>',
         f'<IncidentDataStructure>{"Rows" if rows else "Columns"}</IncidentDataStructure>']
    if define:
        bounds = [t for t, _ in define] + [90]
        s += ['<AngleBasis>', f'<AngleBasisName>{basis}</AngleBasisName>']
        for k, (t0, n) in enumerate(define):
            s += ['<AngleBasisBlock>', f'<Theta>{0.5 * (t0 + bounds[k + 1]) if k else 0}</Theta>',
                  f'<nPhis>{n}</nPhis>', '<ThetaBounds>',
                  f'<LowerTheta>{t0}</LowerTheta>', f'<UpperTheta>{bounds[k + 1]}</UpperTheta>',
                  '</ThetaBounds>', '</AngleBasisBlock>']
        s.append('</AngleBasis>')
    s.append('</DataDefinition>')
    for wavelength in wavelengths:
        for direction, m in blocks.items():
            data = [list(r) for r in zip(*m)] if rows else m  # rows: one per incident
            scale = 0.8 if wavelength == "Solar" else 1.0  # Radiance reads Visible only
            s += ['<WavelengthData>', '<LayerNumber>System</LayerNumber>',
                  f'<Wavelength unit="Integral">{wavelength}</Wavelength>',
                  '<WavelengthDataBlock>',
                  f'<WavelengthDataDirection>{direction}</WavelengthDataDirection>',
                  f'<ColumnAngleBasis>{basis}</ColumnAngleBasis>',
                  f'<RowAngleBasis>{basis}</RowAngleBasis>',
                  '<ScatteringDataType>BTDF</ScatteringDataType>', '<ScatteringData>']
            s += [", ".join("%.*g" % (digits, v * scale) for v in row) + "," for row in data]
            s += ['</ScatteringData>', '</WavelengthDataBlock>', '</WavelengthData>']
    s += ['</Layer>', '</Optical>', '</WindowElement>']
    return "\n".join(s) + "\n"


def diagonal(rings, base, peak):
    """base everywhere, plus peak(θ)/Ω on the diagonal (straight through or mirror)."""
    p = patches(rings)
    m = [[base] * len(p) for _ in p]
    for i, (t, _, ohm) in enumerate(p):
        m[i][i] += peak(t) / ohm
    return m


def louvre(rings):
    """Transmission sent toward local +y: each incident patch's light spread
    over the outgoing patches in proportion to max(0, sinθ sinφ)."""
    p = patches(rings)
    w = [max(0.0, math.sin(math.radians(t)) * math.sin(math.radians(f))) for t, f, _ in p]
    norm = sum(wk * ohm for wk, (_, _, ohm) in zip(w, p))
    m = [[0.004] * len(p) for _ in p]
    for i, (t, _, _) in enumerate(p):
        share = 0.5 * math.cos(math.radians(t)) ** 0.5
        for o in range(len(p)):
            m[o][i] += share * w[o] / norm
    return m


def material(kind, body, up="0 1 0 .", thick="0", modifier="void", reals="0"):
    strings = ([thick] if kind == "BSDF" else []) + [body] + up.split()
    return f"{modifier} {kind} m {len(strings)} {' '.join(strings)} 0 {reals}\n"


def main():
    write = fresh_folder(OUT)
    runs = []  # (group, name, files, rays, repeat, options, check)
    glass = lambda t: 0.55 * (1 - (t / 90) ** 4)  # noqa: E731
    write("glaze.xml", klems_xml({
        "Transmission Front": diagonal(HALF, 0.01, glass),
        "Transmission Back": diagonal(HALF, 0.01, glass),
        "Reflection Front": diagonal(HALF, 0.06, lambda t: 0.05),
        "Reflection Back": diagonal(HALF, 0.08, lambda t: 0.2)}, "LBNL/Klems Half"))
    write("louvre.xml", klems_xml({
        "Transmission Back": louvre(HALF),
        "Reflection Back": diagonal(HALF, 0.05, lambda t: 0.0)}, "LBNL/Klems Half", rows=True))
    write("custom.xml", klems_xml({
        "Transmission Front": diagonal(QUARTER, 0.02, lambda t: 0.4),
        "Reflection Front": diagonal(QUARTER, 0.03, lambda t: 0.1)}, "Test Quarter",
        define=QUARTER))
    write("full.xml", klems_xml({"Transmission Back": diagonal(FULL, 0.005, glass)},
                                "LBNL/Klems Full"))
    write("clear.xml", klems_xml({
        "Transmission Front": diagonal(HALF, 0.0, lambda t: 0.8),
        "Transmission Back": diagonal(HALF, 0.0, lambda t: 0.8)}, "LBNL/Klems Half"))
    write("diffuse.xml", klems_xml({
        "Transmission Front": diagonal(HALF, 0.25, lambda t: 0.0),
        "Transmission Back": diagonal(HALF, 0.25, lambda t: 0.0),
        "Reflection Back": diagonal(HALF, 0.05, lambda t: 0.0)}, "LBNL/Klems Half"))
    # Asymmetric matrices (no reciprocity between their incident and
    # outgoing patches): the direct light's view direction is libBSDF's
    # incident one and the source's the outgoing one, as in Radiance 5.4a.
    nh = len(patches(HALF))
    write("asym.xml", klems_xml({
        "Reflection Back": [[0.03 + 0.002 * o + 0.02 * (i % 7) for i in range(nh)]
                            for o in range(nh)],
        "Transmission Back": [[0.02 + 0.004 * (o % 5) + 0.03 * (i % 3) for i in range(nh)]
                              for o in range(nh)]}, "LBNL/Klems Half"))
    write("down.rays", "1 2 5 0.6 0 -0.8\n0 0 5 0 0 -1\n-3 4 2 0.3 -0.2 -1\n"
                       "2.5 -1 7 0 0 -1\n0.2 0.3 5 -0.1 -0.15 -1\n3 3 2 -0.6 -0.6 -0.5\n")
    write("up.rays", "1 2 -5 0 0 1\n-1 0.5 -3 0.2 0.1 1\n0.6 0.6 -2 0.2 0.2 1\n"
                     "-0.8 -0.6 -4 0.3 0.28 1\n")
    below = "void light under 0 0 3 80 80 80\nunder sphere ubulb 0 0 4 -1 .5 -4 .5\n"
    big = "void light lamp 0 0 3 10 10 10\nlamp sphere bulb 0 0 4 1 1 4 1.5\n"
    lamps = dict(LAMPS, below=below, big=big)

    # 1. Each file on a plane under each kind of source, seen from both sides.
    for body in ("glaze", "louvre", "custom", "full", "asym"):
        for lamp in lamps:
            if body in ("custom", "full", "asym") and lamp in ("polygon", "distant"):
                continue
            name = f"{body}_{lamp}"
            write(f"plane_{name}.rad", lamps[lamp] + material("BSDF", f"{body}.xml") +
                  "m " + PLANE)
            for side in ("down", "up"):
                runs.append(("bsdfplane", f"{name}_{side}", [f"plane_{name}.rad"],
                             f"{side}.rays", 1, DET, "exact"))
    # 2. Up vectors: constant, from the position, transformed; along the
    # normal (warned, black).
    ups = {"x": "1 0 0 .", "position": "Py 1+Px 0 .", "xf": "1 .2 0 . -rz 30 -s 2",
           "normal": "0 0 1 ."}
    for key, up in ups.items():
        for lamp in ("sphere", "below"):
            name = f"{key}_{lamp}"
            write(f"up_{name}.rad", lamps[lamp] + material("BSDF", "louvre.xml", up) +
                  "m " + PLANE)
            runs.append(("bsdfup", name, [f"up_{name}.rad"], "up.rays" if lamp == "sphere"
                         else "down.rays", 1, DET, "exact"))
    # An instance turning and scaling the louvre (its up vector and a
    # proxy's thickness follow the instance's transform).
    write("inst_obj.rad", material("BSDF", "louvre.xml", "1 .2 0 . -rz 30") + "m " + PLANE)
    with open(os.path.join(OUT, "inst_obj.oct"), "wb") as f:
        subprocess.run([os.path.join(BIN, "oconv"), "-f", "inst_obj.rad"], stdout=f,
                       check=True, env=ENV, cwd=OUT)
    for lamp in ("sphere", "below"):
        write(f"instance_{lamp}.rad", lamps[lamp] +
              "void instance i1 9 inst_obj.oct -rz 60 -t .5 .2 0 -s 1.5 0 0\n")
        runs.append(("bsdfup", f"instance_{lamp}", [f"instance_{lamp}.rad"],
                     "up.rays" if lamp == "sphere" else "down.rays", 1, DET, "exact"))
    # 3. aBSDF's through peak (view rays and shadow rays pass it), proxies of
    # either sign with detail behind them, added diffuse reals, a pattern,
    # -bv-, -i.
    floor = "void plastic grey 0 0 5 .6 .6 .6 0 0\ngrey polygon floor 0 0 12 " \
            "-10 -10 -2  10 -10 -2  10 10 -2  -10 10 -2\n"
    detail = "void plastic red 0 0 5 .7 .2 .1 0 0\nred polygon slat 0 0 12 " \
             "-10 -10 -.03  10 -10 -.03  10 10 -.03  -10 10 -.03\n"
    cases = {
        "absclear": (LAMPS["sphere"] + material("aBSDF", "clear.xml") + "m " + PLANE + floor,
                    "down.rays"),
        "absglaze": (big + material("aBSDF", "glaze.xml") + "m " + PLANE + floor, "down.rays"),
        "absglaze_up": (big + material("aBSDF", "glaze.xml") + "m " + PLANE, "up.rays"),
        "proxy": (LAMPS["sphere"] + material("BSDF", "glaze.xml", thick=".05") + "m " + PLANE +
                  detail + floor, "down.rays"),
        "proxy_neg": (below + material("BSDF", "glaze.xml", thick="-.05") + "m " + PLANE +
                      detail.replace("-.03", ".03") + floor, "up.rays"),
        "reals3": (LAMPS["sphere"] + material("BSDF", "louvre.xml", reals="3 .1 .2 .3") +
                   "m " + PLANE, "down.rays"),
        "reals9": (below + material("BSDF", "glaze.xml", reals="9 .1 .2 .3 .05 .1 .15 .2 .1 0") +
                   "m " + PLANE, "up.rays"),
        "pattern": (LAMPS["sphere"] + PATTERN + material("BSDF", "glaze.xml", modifier="c") +
                    "m " + PLANE, "down.rays"),
        "pattern_up": (LAMPS["sphere"] + PATTERN + material("BSDF", "glaze.xml", modifier="c") +
                       "m " + PLANE, "up.rays"),
    }
    for name, (text, rays) in cases.items():
        write(f"kind_{name}.rad", text)
        runs.append(("bsdfkinds", name, [f"kind_{name}.rad"], rays, 1, DET, "exact"))
    runs.append(("bsdfkinds", "backface_off", ["plane_glaze_sphere.rad"], "up.rays", 1,
                 DET + " -bv-", "exact"))
    runs.append(("bsdfkinds", "irradiance_proxy", ["kind_proxy.rad"], "down.rays", 1,
                 DET + " -i", "exact"))
    runs.append(("bsdfkinds", "irradiance_abs", ["kind_absglaze.rad"], "down.rays", 1,
                 DET + " -i", "exact"))

    # 4. The sampled rays: means of repeats under a sky whose colour encodes
    # the direction, a BSDF above an aBSDF.
    write("sky_rays.rays", "0 0 2 0.5 0 -1\n1 1 2 -0.2 0.3 -1\n0 0 -1 0 0.3 1\n"
                           "0 0 -5 0.2 0 1\n0 0 1 0.98 0 -0.17\n")
    for body in ("glaze", "louvre", "asym"):
        write(f"sky_{body}.rad", SKY + material("BSDF", f"{body}.xml") + "m " + PLANE +
              material("aBSDF", "glaze.xml") +
              "m polygon p2 0 0 12 -10 -10 -3  10 -10 -3  10 10 -3  -10 10 -3\n")
        for ss in ("0.5", "1", "4"):
            runs.append(("bsdfsampled", f"{body}_ss{ss}", [f"sky_{body}.rad"], "sky_rays.rays",
                         300, f"-u+ -dj 0 -dt 0 -ss {ss}", "noise"))
    # 5. -ab 1 without a cache: the box's top a BSDF window, its lamp above.
    window = LIT_BOX.replace("wall polygon ceiling", "win polygon ceiling").replace(
        "void light l 0 0 3 20 20 20\nl sphere bulb 0 0 4 0 0 1.5 .2\n",
        "void light l 0 0 3 200 200 200\nl sphere bulb 0 0 4 .5 .3 4 .4\n")
    write("ab1.rad", window.replace("void plastic wall", material("BSDF", "glaze.xml")
                                    .replace(" m ", " win ") + "void plastic wall"))
    write("ab1.rays", "0.3 0.2 1 0 0 -1\n-0.5 0.4 1 0.2 0 -1\n0 0 0 0 0 1\n")
    runs.append(("bsdfab1", "window", ["ab1.rad"], "ab1.rays", 48,
                 "-u+ -ab 1 -aa 0 -ad 512 -as 0", "noise"))
    # 5b. A proxy window (positive thickness) over slats, a lamp and the sky
    # beyond: ambient rays meet it, its direct light, sampled rays and
    # ambient term start beyond the slats.
    slats = "void plastic red 0 0 5 .7 .2 .1 0 0\n" + "".join(
        f"red polygon slat{k} 0 0 12 {x} -2 2.03  {x + .25} -2 2.03  {x + .25} 2 2.03  {x} 2 2.03\n"
        for k, x in enumerate((-2, -1.5, -1, -.5, 0, .5, 1, 1.5)))
    proxy = LIT_BOX.replace("wall polygon ceiling", "win polygon ceiling").replace(
        "void light l 0 0 3 20 20 20\nl sphere bulb 0 0 4 0 0 1.5 .2\n",
        "void light l 0 0 3 200 200 200\nl sphere bulb 0 0 4 .5 .3 4 .4\n")
    write("proxy_ab.rad", SKY + slats + proxy.replace(
        "void plastic wall", material("BSDF", "glaze.xml", thick=".05").replace(" m ", " win ") +
        "void plastic wall"))
    runs.append(("bsdfproxy", "ab1", ["proxy_ab.rad"], "ab1.rays", 48,
                 "-u+ -ab 1 -aa 0 -ad 512 -as 0", "noise"))
    runs.append(("bsdfproxy", "ab2", ["proxy_ab.rad"], "ab1.rays", 24,
                 "-u+ -ab 2 -aa 0 -ad 128 -as 0", "noise"))
    # 5c. Sampled rays meeting a proxy: a glaze plane's sampled reflection
    # rises to a proxy (facing down, slats just above it, a lamp and the sky
    # beyond), whose direct light, sampled rays and ambient term start above
    # the slats.
    stack = (SKY + "void light lamp 0 0 3 100 100 100\nlamp sphere bulb 0 0 4 .5 .4 8 .5\n" +
             material("BSDF", "glaze.xml") + "m " + PLANE +
             material("BSDF", "glaze.xml", thick=".05").replace(" m ", " px ") +
             "px polygon p2 0 0 12 -10 -10 3  -10 10 3  10 10 3  10 -10 3\n" +
             "void plastic red 0 0 5 .7 .2 .1 0 0\n" + "".join(
                 f"red polygon s{k} 0 0 12 {x} -9 3.03  {x + .25} -9 3.03  {x + .25} 9 3.03  "
                 f"{x} 9 3.03\n" for k, x in enumerate([-3 + .5 * i for i in range(13)])))
    write("stack.rad", stack)
    write("stack.rays", "-1 0 1.5 0.3 0.1 -1\n0.4 -0.7 1 0 0.2 -1\n1.1 0.9 2 -0.25 -0.3 -1\n"
                        "-0.3 0.2 2.5 0.1 0 -1\n")
    # -lr 8: Radiance's Russian roulette (-lr -10) draws even at -u-.
    runs.append(("bsdfproxy", "stack", ["stack.rad"], "stack.rays", 1, DET + " -lr 8", "exact"))
    runs.append(("bsdfproxy", "stack_ab1", ["stack.rad"], "stack.rays", 48,
                 "-u+ -dj 0 -ss 0 -ab 1 -aa 0 -ad 256 -as 0", "noise"))
    # The same with a proxy that only transmits diffusely: its ambient term
    # (gathered above the slats) is most of what it sends down.
    write("stack_diffuse.rad", stack.replace('px 6 .05 glaze.xml', 'px 6 .05 diffuse.xml'))
    runs.append(("bsdfproxy", "stack_diffuse", ["stack_diffuse.rad"], "stack.rays", 48,
                 "-u+ -dj 0 -ss 0 -ab 1 -aa 0 -ad 256 -as 0", "noise"))
    # 5d. The direct light's view jitter at -ss 1 and 2: views from below
    # tilted across the edge of the central patch, the lamp straight above.
    tilts = []
    for deg in (3, 5, 6, 6.5, 7, 8, 10):
        t = math.radians(deg)
        d = (math.sin(t), 0.0, math.cos(t))
        tilts.append("%.6f 0.3 %.6f %.6f 0 %.6f" % (1 - 3 * d[0], -3 * d[2], d[0], d[2]))
    write("tilt.rays", "\n".join(tilts) + "\n")
    write("tilt.rad", "void light lamp 0 0 3 100 100 100\nlamp sphere bulb 0 0 4 1 .3 6 .1\n" +
          material("BSDF", "glaze.xml") + "m " + PLANE)
    write("tilt_asym.rad", "void light lamp 0 0 3 100 100 100\nlamp sphere bulb 0 0 4 1 .3 6 .1\n" +
          material("BSDF", "asym.xml") + "m " + PLANE)
    for ss in ("1", "2"):
        runs.append(("bsdfjitter", f"ss{ss}", ["tilt.rad"], "tilt.rays", 200,
                     f"-u+ -dj 0 -dt 0 -ss {ss}", "noise"))
        runs.append(("bsdfjitter", f"asym_ss{ss}", ["tilt_asym.rad"], "tilt.rays", 200,
                     f"-u+ -dj 0 -dt 0 -ss {ss}", "noise"))
    # 6. Errors.
    errors = {
        "reals": "void BSDF m 6 0 glaze.xml 0 1 0 . 0 4 .1 .1 .1 .1\n",
        "strings": "void BSDF m 5 0 glaze.xml 0 1 0 0 0\n",
        "absstrings": "void aBSDF m 4 glaze.xml 0 1 0 0 0\n",
    }
    for name, text in errors.items():
        write(f"error_{name}.rad", LAMPS["sphere"] + text + "m " + PLANE)
        runs.append(("bsdferror", name, [f"error_{name}.rad"], "down.rays", 1, DET, "exact"))

    run_and_write(runs, radiance, OUT,
                  "# Real Radiance 5.4a's answers for the BSDF and aBSDF cases of\n"
                  "# tests/direct/direct_matrix_test.cpp, written by\n"
                  "# tests/direct/generate_bsdf.py (format as in generate.py).\n")


if __name__ == "__main__":
    main()
