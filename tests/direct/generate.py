#!/usr/bin/env python3
# Generates the direct-light test matrix (tests/direct/direct_matrix_test.cpp)
# and its reference outputs from REAL Radiance 5.4a. A developer's tool: it
# needs ../shared/reference/radiance-5.4a (or RADIANCE=<its folder>); the test
# itself only reads what this writes into tests/data/direct/.
#
#   tests/direct/generate.py            # rewrites tests/data/direct/
#
# The matrix crosses
#   source surface:  quad, triangle and trapezoid polygons, sphere, ring,
#                    cylinder, the distant `source`; cone, cup, tube and bubble
#                    (which Radiance refuses as sources);
#   emitting material: light, illum with and without an alternate material,
#                    glow with zero, positive and negative radius, spotlight
#                    (plain, focused, tilted);
#   scene contents:  only opaque surfaces; a trans, glass, dielectric or mirror
#                    object away from the light; the source in a glass bulb; an
#                    opaque occluder over half the source (also with a trans
#                    object elsewhere, which sends shadow rays down the
#                    followed path instead of the any-hit query);
#   receivers:       -I sensors in front, behind, at grazing angles, inside and
#                    outside a spotlight's cone, 1e-3 of the source's size from
#                    it and 1e6 away; camera rays onto the floor and onto the
#                    source for -ov and -i;
#   settings:        -dj 0 -dt 0 with -ds 0.2 and -ds 0 (deterministic, -u-),
#                    Radiance's defaults (mean of repeated rays), -dv-, -bv-,
#                    and -ab 1 where a glow's light reaches a receiver only
#                    through the indirect calculation.
#
# Output: tests/data/direct/
#   floor.rad, contents_<c>.rad, source_<shape>_<material>.rad   scene parts
#   sensors_<shape>.pts, camera_<shape>.rays                      ray inputs
#   expected.txt   one block per run (format below), Radiance's answers
#
# expected.txt blocks:
#   case <group> <name>
#   files <scene files, relative to tests/data/direct/>
#   rays <ray file> <repeat count>
#   options <rtrace options>
#   check <exact|mean|noise>
#   status <Radiance's exit status>
#   err <one line of Radiance's standard error>       (zero or more)
#   note <where the reference is not Radiance's own printout, and why>
#   out <numbers of one output line; for mean and noise: the mean over the repeats>
#   sem <for noise: the standard error of each number of the out line in turn>
#   end
import math
import os
import subprocess
import sys
import tempfile

from matrix_data import mean_and_sem, write_expected

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
OUT = os.path.join(ROOT, "tests", "data", "direct")
RADIANCE = os.environ.get(
    "RADIANCE", os.path.normpath(os.path.join(ROOT, "..", "shared", "reference", "radiance-5.4a")))
BIN = os.path.join(RADIANCE, "bin")

# The light sits around S = (0, 0, 2) over a 6 x 6 floor at z = 0.
S = (0.0, 0.0, 2.0)
SUN = (0.3, 0.2, 1.0)  # direction toward the distant source

# shape -> (surface text, distance from S down to the surface below S, size)
LOCAL_SHAPES = {
    # Parallelogram: samples land on the source by construction.
    "quad": ("polygon src 0 0 12 -.25 -.25 2  -.25 .25 2  .25 .25 2  .25 -.25 2", 0.0, 0.5),
    # Not four vertices: a square frame of the area's size. Not quite
    # symmetric: with a mirror-symmetric triangle some -ds 0.1 sample rays
    # graze its edges, where either program may count a hit.
    "tri": ("polygon src 0 0 9 -.3 -.25 2  .0 .35 2  .31 -.25 2", 0.0, 0.6),
    # Four vertices but no parallelogram.
    "trap": ("polygon src 0 0 12 -.3 -.25 2  -.15 .25 2  .15 .25 2  .3 -.25 2", 0.0, 0.6),
    "sphere": ("sphere src 0 0 4 0 0 2 .25", 0.25, 0.5),
    "ring": ("ring src 0 0 8 0 0 2  0 0 -1  0 .3", 0.0, 0.6),
    "cylinder": ("cylinder src 0 0 7 -.5 0 2  .5 0 2  .08", 0.08, 1.0),
}
# Shapes Radiance refuses with a light material ("illegal material").
REFUSED_SHAPES = {
    "cone": "cone src 0 0 8 0 0 1.8  0 0 2.2  .2 .1",
    "cup": "cup src 0 0 8 0 0 1.8  0 0 2.2  .2 .1",
    "tube": "tube src 0 0 7 0 0 1.8  0 0 2.2  .2",
    "bubble": "bubble src 0 0 4 0 0 2 .25",
}

MATERIALS = {
    "light": "void light emit 0 0 3 5 4 3\n",
    "illumalt": "void plastic alt 0 0 5 .6 .5 .4 0 0\nvoid illum emit 1 alt 0 3 5 4 3\n",
    "illumvoid": "void illum emit 0 0 3 5 4 3\n",
    "glow0": "void glow emit 0 0 4 5 4 3 0\n",
    "glowpos": "void glow emit 0 0 4 5 4 3 1.2\n",
    "glowneg": "void glow emit 0 0 4 5 4 3 -1\n",
    "spot": "void spotlight emit 0 0 7 5 4 3 60 0 0 -1\n",
    "spotfocus": "void spotlight emit 0 0 7 5 4 3 60 0 0 -2\n",
    "spottilt": "void spotlight emit 0 0 7 5 4 3 40 .6 0 -1\n",
}

CONTENTS = {
    "opaque": "",
    # Away from the light and the receivers: they only switch lazyrad's
    # shadow rays from the any-hit query to the followed path.
    "trans": "void trans tr 0 0 7 .6 .6 .6 0 0 .5 .3\n"
             "tr polygon panel 0 0 12 -2.5 2.5 .2  -1.5 2.5 .2  -1.5 2.5 1.2  -2.5 2.5 1.2\n",
    "glass": "void glass gl 0 0 3 .9 .9 .9\n"
             "gl polygon panel 0 0 12 -2.5 2.5 .2  -1.5 2.5 .2  -1.5 2.5 1.2  -2.5 2.5 1.2\n",
    "dielectric": "void dielectric di 0 0 5 .95 .95 .95 1.5 0\n"
                  "di sphere ball 0 0 4 -2 2.5 .7 .3\n",
    # Facing away from the light (+y), so that no virtual source appears.
    "mirror": "void mirror mi 0 0 3 .9 .9 .9\n"
              "mi polygon panel 0 0 12 -2.5 2.5 .2  -2.5 2.5 1.2  -1.5 2.5 1.2  -1.5 2.5 .2\n",
    "bulb": "void glass gl 0 0 3 .9 .9 .9\ngl sphere bulb 0 0 4 0 0 2 .8\n",
    # Opaque, under the half of the light at x < 0.03, facing the light.
    "half": "void plastic blk 0 0 5 .2 .2 .2 0 0\n"
            "blk polygon occluder 0 0 12 -1 -1 1.5  .03 -1 1.5  .03 1 1.5  -1 1 1.5\n",
}
CONTENTS["halftrans"] = CONTENTS["half"] + CONTENTS["trans"]
# For the distant source: the occluder's edge under the sun's centre as seen
# from the sensor at (0, 0, 0.5).
DISTANT_HALF = ("void plastic blk 0 0 5 .2 .2 .2 0 0\n"
                "blk polygon occluder 0 0 12 -1 -1 1.5  .3 -1 1.5  .3 1 1.5  -1 1 1.5\n")

FLOOR = ("void plastic floormat 0 0 5 .5 .5 .5 0 0\n"
         "floormat polygon floor 0 0 12 -3 -3 0  3 -3 0  3 3 0  -3 3 0\n")


def unit(v):
    n = math.sqrt(sum(c * c for c in v))
    return tuple(c / n for c in v)


def fmt(v):
    return " ".join("%.17g" % c for c in v)


FAR_SENSOR = 8  # line of the sensor 1e6 away in sensors_<shape>.pts


def sensors(below, size, far=1e6):
    """-I sensors around a local source (point, normal)."""
    c20, s20 = math.cos(math.radians(20)), math.sin(math.radians(20))
    return [
        ((0.3, 0.2, 0.5), (0, 0, 1)),                    # in front, below
        ((1.5, -1.0, 0.5), (0, 0, 1)),                   # oblique, outside the spot cones
        ((1.0, 1.0, 1.0), unit((-1, -1, 1))),            # tilted toward the light
        ((0.1, 0.0, 2.6), (0, 0, -1)),                   # behind a flat light
        ((1.5, 0.0, 1.9), (0, 0, 1)),                    # light grazing the receiver
        ((3.0, 0.5, 1.999), (-1, 0, 0)),                 # a flat light seen edge-on
        ((0.02, 0.01, 2.0 - below - 1e-3 * size), (0, 0, 1)),  # 1e-3 of its size away
        ((far * c20, 0.0, 2.0 - far * s20), (-c20, 0, s20)),   # 1e6 away
        ((0.6, 0.0, 0.5), (0, 0, 1)),                    # inside the spot cones
        ((2.5, 0.0, 0.5), unit((-1, 0, 1))),             # outside the spot cones
    ]


def distant_sensors():
    sun = unit(SUN)
    graze = unit((sun[2], 0.0, -sun[0]))   # perpendicular to the sun, in xz
    graze = unit(tuple(g + 0.02 * s for g, s in zip(graze, sun)))
    return [
        ((0.3, 0.2, 0.5), (0, 0, 1)),
        ((0.0, 0.0, 0.5), (0, 0, 1)),     # under the distant occluder's edge
        ((1.0, 1.0, 0.5), sun),           # facing the sun
        ((1.0, -1.0, 0.5), tuple(-c for c in sun)),  # back to the sun
        ((-1.0, 1.0, 0.5), graze),        # the sun at 1 degree over the horizon
        ((0.5, 0.5, -0.5), (0, 0, 1)),    # under the floor: shaded
    ]


def camera(below):
    """Rays (origin, direction) that see the floor or the light."""
    a, b = (3.0, -2.0, 0.8), (1.0, 1.0, 4.0)
    c = (0.05, 0.02, 2.0 - below - 0.5)
    to = lambda o, p: unit(tuple(q - r for q, r in zip(p, o)))
    return [
        (a, to(a, (0.3, 0.2, 0.0))),     # floor under the light
        (a, to(a, (-1.5, 1.0, 0.0))),    # floor farther off
        (a, to(a, S)),                   # the light, from below
        (b, to(b, S)),                   # the light, from above (a flat one's back)
        (b, to(b, (0.5, -0.5, 0.0))),    # floor
        (c, (0.0, 0.0, 1.0)),            # straight up into the light
    ]


def distant_camera():
    sun = unit(SUN)
    return [
        ((0.0, 0.0, 0.5), sun),                       # into the sun
        ((0.0, 0.0, 0.5), (0.0, 0.0, 1.0)),           # the sky beside it
        ((3.0, -2.0, 0.8), unit((-2.7, 2.2, -0.8))),  # the floor
    ]


def scene_files(source, contents):
    return ["floor.rad", source] + ([] if contents == "opaque" else [f"contents_{contents}.rad"])


def write(path, text):
    with open(os.path.join(OUT, path), "w") as f:
        f.write(text)


def run_radiance(files, rays, repeat, options, tmp, rays_dir=OUT):
    """Radiance's exit status, stderr lines and output rows for one run."""
    octree = os.path.join(tmp, "scene.oct")
    with open(octree, "wb") as f:
        oc = subprocess.run([os.path.join(BIN, "oconv")] + [os.path.join(OUT, x) for x in files],
                            stdout=f, stderr=subprocess.PIPE, text=False)
    if oc.returncode != 0:
        return oc.returncode, oc.stderr.decode().splitlines(), [], []
    with open(os.path.join(rays_dir, rays)) as f:
        lines = [l for l in f.read().splitlines() if l.strip()]
    stdin = "".join((l + "\n") * repeat for l in lines)
    r = subprocess.run([os.path.join(BIN, "rtrace"), "-h"] + options.split() + [octree],
                       input=stdin, capture_output=True, text=True,
                       env=dict(os.environ, RAYPATH="." + os.pathsep + os.path.join(RADIANCE, "lib")))
    rows = [[float(x) for x in l.split()] for l in r.stdout.splitlines() if l.strip()]
    err = [l.replace(os.path.join(BIN, "rtrace"), "rtrace").replace(OUT + os.sep, "")
           for l in r.stderr.splitlines()]
    sems = []
    if repeat > 1 and r.returncode == 0:
        assert len(rows) == len(lines) * repeat, (files, rays, options)
        rows, sems = mean_and_sem(rows, len(lines), repeat)
    return r.returncode, err, rows, sems


DET = "-u- -dj 0 -dt 0"
REF_REPEAT_AB1 = 64


def runs_for(group, contents, local):
    """(name, rays key, repeat, options, check) of one scene."""
    sens, cam = "sensors", "camera"
    runs = [
        ("I_ds02", sens, 1, f"{DET} -ds 0.2 -I", "exact"),
        ("I_ds0", sens, 1, f"{DET} -ds 0 -I", "exact"),
        # Radiance's defaults but -u-: with -u+ each process draws the frame
        # of a non-quad flat source once, which repeated rays cannot average.
        ("I_defaults", sens, 8, "-u- -I", "mean"),
        ("ov_ds02", cam, 1, f"{DET} -ds 0.2 -ov", "exact"),
        ("i_ds02", cam, 1, f"{DET} -ds 0.2 -i", "exact"),
    ]
    if contents in ("opaque", "half"):
        runs += [
            ("ov_dv", cam, 1, f"{DET} -ds 0.2 -dv-", "exact"),
            ("ov_bv", cam, 1, f"{DET} -ds 0.2 -bv-", "exact"),
            ("I_bv", sens, 1, f"{DET} -ds 0.2 -bv- -I", "exact"),
        ]
    if contents == "opaque" and (not local or group.split("_")[0] in ("quad", "sphere")):
        # Glows reach the receivers beyond their radius only through the
        # indirect calculation; lights must not be counted twice there.
        # -u+: every repeat samples the hemisphere afresh. Radiance's mean is
        # over REF_REPEAT_AB1 repeats, so that its noise is half lazyrad's.
        # -ds 0: lazyrad subdivides the sources seen from hemisphere samples
        # for the path's real importance, Radiance for the sample's weight
        # (README, Differences); with one sample per source both agree.
        runs.append(("I_ab1", sens, 16, "-u+ -dj 0 -dt 0 -ds 0 -I -ab 1 -aa 0 -ad 4096 -as 0",
                     "mean"))
    return runs


def main():
    os.makedirs(OUT, exist_ok=True)
    for f in os.listdir(OUT):
        os.remove(os.path.join(OUT, f))
    write("floor.rad", FLOOR)
    for name, text in CONTENTS.items():
        if text:
            write(f"contents_{name}.rad", text)
    write("contents_distanthalf.rad", DISTANT_HALF)

    for shape, (surface, below, size) in LOCAL_SHAPES.items():
        write(f"sensors_{shape}.pts",
              "".join(f"{fmt(p)} {fmt(n)}\n" for p, n in sensors(below, size)))
        write(f"camera_{shape}.rays", "".join(f"{fmt(o)} {fmt(d)}\n" for o, d in camera(below)))
    write("sensors_distant.pts", "".join(f"{fmt(p)} {fmt(n)}\n" for p, n in distant_sensors()))
    write("camera_distant.rays", "".join(f"{fmt(o)} {fmt(d)}\n" for o, d in distant_camera()))

    scenes = []  # (group, contents, files, shape key for rays, local)
    all_local = ["light", "illumalt", "illumvoid", "glow0", "glowpos", "glowneg", "spot",
                 "spotfocus", "spottilt"]
    crossed = ["light", "illumalt", "glowpos", "spot"]
    for shape, (surface, _, _) in LOCAL_SHAPES.items():
        for mat in all_local:
            src = f"source_{shape}_{mat}.rad"
            write(src, MATERIALS[mat] + "emit " + surface + "\n")
            for c in CONTENTS:
                if c in ("opaque", "trans") or mat in crossed:
                    scenes.append((f"{shape}_{mat}", c, scene_files(src, c), shape, True))
    sun = fmt(unit(SUN))
    for mat, text in (("light", "void light emit 0 0 3 5 4 3\n"),
                      ("illum", "void illum emit 0 0 3 5 4 3\n"),
                      ("glow", "void glow emit 0 0 4 .5 .4 .3 0\n"),
                      ("spot", "void spotlight emit 0 0 7 5 4 3 60 0 0 -1\n")):
        src = f"source_distant_{mat}.rad"
        write(src, text + f"emit source src 0 0 4 {sun} 5\n")
        for c in ("opaque", "trans", "glass", "dielectric", "mirror", "distanthalf"):
            if c in ("opaque", "trans") or mat == "light":
                scenes.append((f"distant_{mat}", c, scene_files(src, c), "distant", False))

    blocks = []
    with tempfile.TemporaryDirectory() as tmp:
        for shape, (_, below, size) in LOCAL_SHAPES.items():
            with open(os.path.join(tmp, f"sensors_{shape}.pts"), "w") as f:
                f.write("".join(f"{fmt(p)} {fmt(n)}\n" for p, n in sensors(below, size, 1e5)))
        for group, contents, files, key, local in scenes:
            for name, rays, repeat, options, check in runs_for(group, contents, local):
                ray_file = f"{rays}_{key}.{'pts' if rays == 'sensors' else 'rays'}"
                ref_repeat = REF_REPEAT_AB1 if name == "I_ab1" else repeat
                status, err, rows, sems = run_radiance(files, ray_file, ref_repeat, options, tmp)
                notes = []
                if ref_repeat != repeat:
                    notes.append(f"Radiance's mean over {ref_repeat} repeats")
                if local and rays == "sensors" and status == 0:
                    # Radiance loses precision 1e6 away: through the glass
                    # bulb it counts the glass twice there (0.826 of the
                    # inverse-square law, exact up to 1e5). Where its answer
                    # 1e6 away breaks the inverse-square law, the reference is
                    # its answer 1e5 away times 1e-2 (README, Differences).
                    _, _, near_rows, _ = run_radiance(files, ray_file, ref_repeat, options, tmp,
                                                   rays_dir=tmp)
                    want = [v * 1e-2 for v in near_rows[FAR_SENSOR - 1]]
                    got = rows[FAR_SENSOR - 1]
                    if any(abs(a - b) > 1e-3 * max(abs(a), abs(b)) for a, b in zip(got, want)):
                        notes.append(f"line {FAR_SENSOR}: Radiance printed "
                                     + " ".join("%.7g" % v for v in got)
                                     + ", against the inverse-square law from 1e5 away")
                        rows[FAR_SENSOR - 1] = want
                if check == "mean" and name == "I_ab1":
                    check = "noise"
                blocks.append((group, f"{contents}_{name}", files, ray_file, repeat, options,
                               check, status, err, rows, notes, sems if check == "noise" else []))
        # Shapes Radiance refuses as sources: the error, for each emitting material.
        for shape, surface in REFUSED_SHAPES.items():
            for mat in ("light", "glowpos", "glow0"):
                src = f"source_{shape}_{mat}.rad"
                write(src, MATERIALS[mat] + "emit " + surface + "\n")
                files = ["floor.rad", src]
                options = f"{DET} -ds 0.2 -I"
                status, err, rows, _ = run_radiance(files, "sensors_sphere.pts", 1, options, tmp)
                blocks.append((f"refused_{shape}", mat, files, "sensors_sphere.pts", 1, options,
                               "exact", status, err, rows, [], []))
        # A cylinder too fat for Radiance's sampling: its warning.
        src = "source_fatcylinder_light.rad"
        write(src, MATERIALS["light"] + "emit cylinder src 0 0 7 -.2 0 2  .2 0 2  .15\n")
        for name, options in (("I_ds02", f"{DET} -ds 0.2 -I"), ("I_ds0", f"{DET} -ds 0 -I")):
            files = ["floor.rad", src]
            status, err, rows, _ = run_radiance(files, "sensors_cylinder.pts", 1, options, tmp)
            blocks.append(("fatcylinder_light", name, files, "sensors_cylinder.pts", 1, options,
                           "exact", status, err, rows, [], []))

    keys = "group name files rays repeat options check status err rows notes sems".split()
    write_expected(os.path.join(OUT, "expected.txt"),
                   "# Real Radiance 5.4a's answers for tests/direct/direct_matrix_test.cpp,\n"
                   "# written by tests/direct/generate.py (format described there).\n",
                   [dict(zip(keys, b)) for b in blocks])
    print(f"{len(blocks)} runs of {len(scenes)} scenes written to {OUT}", file=sys.stderr)


if __name__ == "__main__":
    main()
