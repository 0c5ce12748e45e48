#!/usr/bin/env python3
# Generates the mist cases (tests/data/mist/) for
# tests/direct/direct_matrix_test.cpp, with REAL Radiance 5.4a's answers. A
# developer's tool: it needs ../shared/reference/radiance-5.4a (or
# RADIANCE=<its folder>); the test only reads what this writes. Same
# expected.txt format as generate.py (see there).
#
#   tests/direct/generate_mist.py
#
# Covers Radiance's mist material (m_mist.c; the in-scattering of srcscatter
# in source.c): a box of six outward polygons or a sphere of mist, seen by
# view rays that pass through it, stop on a surface inside it, start inside
# it (with and without a source list: the retroactive rule), with 0, 3, 4,
# 6 and 7 reals, under the global -me/-ma/-av, a pattern scaling (or, by
# its value where the ray enters and where it leaves, skewing) the
# extinction; shadow rays crossing it (-I sensors inside and outside, -i);
# exactly, at -u- -dj 0 -dt 0. Then the in-scattering of listed sources,
# the mean of many repeats ("noise"): a spotlight's beam at g = 0, .7 and
# -.5 with -ms 0, .5, .1 and .01 (capped at 16 samples), a sphere lamp, a
# distant source, one source listed of two, both, rays starting inside,
# a blocker shadowing the beam, a sphere of mist inside a box of haze, a
# mirror's virtual source named "mir>bulb" (unknown at -dr 0). Last the
# messages: 8 reals, unknown and duplicate source names, 33 names, a list
# overflowing 32 sources over two nested mists. (Radiance checks a mist
# at the first ray that hits it, lazyrad when the scene loads: a fault in
# a mist no ray hits is an error in lazyrad alone, README Differences; not
# here.) Noise cases keep -u-, under which Radiance's srcscatter() still
# draws from random() and its virtual sources' pretest is deterministic
# (under -u+ it dropped the image "mir>bulb" in most runs); the test runs
# lazyrad with -u+ for them.
#
# What Radiance 5.4a does here, seen in its answers: a ray starting inside a
# mist without sources never gets its extinction (leaving takes it off, not
# below -me), nor do its shadow rays; with sources the ray (or shadow ray)
# leaving gets it for its own segment. -i passes through mist as if it were
# not there (the hit surfaces' shadow rays start without it too). A
# negative g scatters isotropically (its phase function is taken as 1 for
# g <= 0: gneg equals g0). A ray leaving a mist so dense that its weight
# falls below -lw is dropped (0). The 33 names and the overflow are
# internal errors, exit status 3.
import os
import subprocess

from generate_patterns import BIN, ENV, radiance
import matrix_data
from matrix_data import fresh_folder, run_and_write

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
OUT = os.path.join(ROOT, "tests", "data", "mist")
DET = "-u- -dj 0 -dt 0"
# Radiance's repeats for a noise case (its mean's standard error is the
# test's yardstick), and lazyrad's.
REPEAT = 4096
LAZY_REPEAT = 512


def box(mod, name, x0, x1, y0, y1, z0, z1):
    """matrix_data.box around [x0, x1] x [y0, y1] x [z0, z1]."""
    return matrix_data.box(mod, name, (x0, y0, z0), (x1, y1, z1))


def mist(name, sources, reals, mod="void"):
    """A mist material: its source names and reals."""
    return (f"{mod} mist {name} {len(sources)} {' '.join(sources)}".rstrip() +
            f"\n0\n{len(reals)} {' '.join('%g' % r for r in reals)}".rstrip() + "\n")


# A lamp over a grey floor between two grey walls, a white ball inside the
# mist's box (x, y in [-1, 1], z in [-.5, 2.5], the floor z = 0 through it),
# the lamp above it.
ROOM = ("void plastic grey 0 0 5 .5 .5 .5 0 0\n"
        "grey polygon floor 0 0 12 -10 -10 0  10 -10 0  10 10 0  -10 10 0\n"
        "grey polygon east 0 0 12 5 -10 -1  5 -10 5  5 10 5  5 10 -1\n"
        "grey polygon west 0 0 12 -5 -10 -1  -5 10 -1  -5 10 5  -5 -10 5\n"
        "void plastic white 0 0 5 .8 .8 .8 0 0\n"
        "white sphere ball 0 0 4 .3 .3 .8 .3\n"
        "void light lamp 0 0 3 50 50 50\n"
        "lamp sphere bulb 0 0 4 0 0 4 .2\n")
ROOM_BOX = (-1, 1, -1, 1, -.5, 2.5)
# Through the box (both ways, past the ball) onto the walls; down through its
# top onto the floor inside; from inside out onto the west wall; from inside
# onto the floor inside; onto the ball; onto the floor outside (its shadow
# ray crosses the box); up through the box into the sky; through the box
# into the lamp.
ROOM_RAYS = ("-3 0.2 1.5 1 0 0\n4 0.1 1.5 -1 0 0\n0.2 -0.3 3.5 0 0 -1\n"
             "0.5 -0.5 1 -1 0.3 0.2\n0.5 -0.5 1 0 0 -1\n0.3 -2 2.5 0 2.3 -1.4\n"
             "1.6 0 1 0 0 -1\n-3 0.5 1 1 0 0.6\n-2 0 0.5 2 0 3.5\n")
# Floor inside the box, outside it with the shadow ray through it, outside
# with the shadow ray past it; in the air inside the box, up and tilted.
ROOM_SENSORS = ("0.2 -0.3 0.001 0 0 1\n1.6 0 0.001 0 0 1\n3 0 0.001 0 0 1\n"
                "0 -0.5 1.5 0 0 1\n-0.5 0.5 2 0 1 0.5\n")

# A spotlight shining down over a black floor, the mist's box (x, y in
# [-1.5, 1.5], z in [-.5, 2.5]) around its beam; a sun, not always listed.
SPOT = ("void spotlight spot 0 0 7 200 200 200 40 0 0 -1\n"
        "spot sphere spotbulb 0 0 4 0 0 3 .1\n"
        "void plastic black 0 0 5 0 0 0 0 0\n"
        "black polygon floor 0 0 12 -10 -10 0  10 -10 0  10 10 0  -10 10 0\n")
SUN = "void light sunlight 0 0 3 2e4 2e4 2e4\nsunlight source sun 0 0 4 .3 .2 1 .5\n"
SPOT_BOX = (-1.5, 1.5, -1.5, 1.5, -.5, 2.5)
# Across the beam at three heights and offsets, and back; down through it onto
# the floor inside the box; from outside above looking down (back scatter);
# from inside looking up at the lamp (forward scatter) and across.
BEAM_RAYS = ("-3 0 1 1 0 0\n-3 0.5 1.5 1 0 0\n-3 0 0.5 1 0.2 0\n3 0.2 1.2 -1 0 0\n"
             "-2 0 2 1 0 -1\n0.3 0.2 4 -0.05 0 -1\n0.5 0 0.2 -0.1 0 1\n0 0 1 1 0 0\n")

# A mirror (x = 2, facing -x) relaying the lamp into the mist's box: the
# virtual source "mir>bulb"; black floor and a black screen between the lamp
# and the box's far side.
MIRROR = ("void light lamp 0 0 3 50 50 50\nlamp sphere bulb 0 0 4 0 0 3 .2\n"
          "void mirror glass 0 0 3 .9 .9 .9\n"
          "glass polygon mir 0 0 12 2 -3 -1  2 -3 5  2 3 5  2 3 -1\n"
          "void plastic black 0 0 5 0 0 0 0 0\n"
          "black polygon floor 0 0 12 -10 -10 0  10 -10 0  10 10 0  -10 10 0\n")
MIRROR_BOX = (-1, 1.5, -1, 1, -.5, 2.5)
MIRROR_RAYS = ("-3 0 1 1 0 0\n0 -3 1.5 0 1 0\n1 -3 1 0 1 0.1\n-3 0.3 2 1 0 -0.2\n"
               "0.5 0 0.5 0 0 1\n")


def main():
    write = fresh_folder(OUT)
    runs = []  # (group, name, files, rays, repeat, options, check)
    write("room.rad", ROOM)
    write("room.rays", ROOM_RAYS)
    write("room.pts", ROOM_SENSORS)
    write("spot.rad", SPOT)
    write("spot_sun.rad", SPOT + SUN)
    write("beam.rays", BEAM_RAYS)
    write("mirror.rad", MIRROR)
    write("mirror.rays", MIRROR_RAYS)

    # 1. Extinction (and ambient in-scattering) without sources: exact.
    room_mists = {
        "ext3": mist("fog", [], [.3, .4, .5]),
        "ext0": mist("fog", [], []),
        "ext4": mist("fog", [], [.3, .4, .5, .9]),        # the 4th real unused
        "ext6": mist("fog", [], [.3, .4, .5, .9, .6, .3]),
        "ext7": mist("fog", [], [.3, .4, .5, .9, .6, .3, .5]),
        # So dense that the ray leaving it weighs less than -lw: Radiance
        # drops it (0), as it does beyond the global medium.
        "dense": mist("fog", [], [5, 8, 12]),
        # A pattern scales the extinction, taken where the ray meets the
        # surface: entering and leaving at other x, the ray may leave with
        # extinction to spare (or none).
        "const": "void brightfunc two 2 2 . 0 0\n" + mist("fog", [], [.3, .4, .5], "two"),
        "ramp": "void brightfunc ramp 2 2+Px/2 . 0 0\n" + mist("fog", [], [.3, .4, .5], "ramp"),
        "tint": "void colorfunc tint 4 1 2 3 . 0 0\n" +
        mist("fog", [], [.3, .3, .3, .5, .5, .5], "tint"),
        "sphere": "void mist fog 0 0 3 .3 .4 .5\nfog sphere fogball 0 0 4 0 0 1 1.2\n",
        # A smaller box of haze (its own albedo, no sources) inside the fog's.
        "nested": mist("fog", [], [.3, .4, .5]) + mist("haze", [], [.1, .2, .3, .5, .5, .5]) +
        box("haze", "inner", -.6, .6, -.6, .6, .6, 2),
    }
    for name, text in room_mists.items():
        if name != "sphere":
            text += box("fog", "box", *ROOM_BOX)
        write(f"room_{name}.rad", text)
    media = {
        "vacuum": "",
        "me": "-me .05 .1 .15",
        "mema": "-me .05 .1 .15 -ma .5 .6 .7 -av 1 2 3",
        "ma": "-ma .5 .5 .5 -av 1 1 1",
        "av": "-av 1 2 3",
    }
    for mname in ("ext3", "ext6", "ramp"):
        for medname, opts in media.items():
            runs.append(("mistext", f"{mname}_{medname}", ["room.rad", f"room_{mname}.rad"],
                         "room.rays", 1, f"{DET} {opts}".strip(), "exact"))
    for mname in ("ext0", "ext4", "ext7", "dense", "const", "tint", "sphere", "nested"):
        for medname in ("vacuum", "mema"):
            runs.append(("mistext", f"{mname}_{medname}", ["room.rad", f"room_{mname}.rad"],
                         "room.rays", 1, f"{DET} {media[medname]}".strip(), "exact"))

    # 2. Shadow rays through the mist, -I and -i; a source list with albedo
    # 0 (no in-scattering, so exact): the retroactive rule for rays and
    # shadow rays starting inside.
    listed = {
        "list3": mist("fog", ["bulb"], [.3, .4, .5]),
        "list6": mist("fog", ["bulb"], [.3, .4, .5, 0, 0, 0]),
        "list_unknown": mist("fog", ["nosuch"], [.3, .4, .5, .9, .6, .3]),
    }
    for name, text in listed.items():
        write(f"room_{name}.rad", text + box("fog", "box", *ROOM_BOX))
    for mname in ("ext3", "ext6", "ramp", "list3", "list6", "list_unknown", "sphere"):
        for medname in ("vacuum", "me", "mema"):
            if mname in ("ramp", "sphere", "list_unknown") and medname != "vacuum":
                continue
            files = ["room.rad", f"room_{mname}.rad"]
            opts = media[medname]
            runs.append(("mistshadow", f"sensor_{mname}_{medname}", files, "room.pts", 1,
                         f"{DET} -I {opts}".strip(), "exact"))
            runs.append(("mistshadow", f"irrad_{mname}_{medname}", files, "room.rays", 1,
                         f"{DET} -i {opts}".strip(), "exact"))
            # (list3 under -ma: the view rays scatter the bulb's light, noise.)
            if mname.startswith("list") and (mname, medname) != ("list3", "mema"):
                runs.append(("mistshadow", f"view_{mname}_{medname}", files, "room.rays", 1,
                             f"{DET} {opts}".strip(), "exact"))
    # -I with the ambient value (no medium: the sensors add it, exactly).
    runs.append(("mistshadow", "sensor_ext6_av", ["room.rad", "room_ext6.rad"], "room.pts", 1,
                 f"{DET} -I -av 1 2 3", "exact"))

    # 3. In-scattering of listed sources: noise.
    scatter = {
        "g0": mist("fog", ["spotbulb"], [.2, .2, .2, .8, .8, .8]),
        "g07": mist("fog", ["spotbulb"], [.2, .2, .2, .8, .8, .8, .7]),
        "gneg": mist("fog", ["spotbulb"], [.2, .2, .2, .8, .8, .8, -.5]),
        "colour": mist("fog", ["spotbulb"], [.1, .3, .6, .9, .6, .3, .3]),
        "global_albedo": mist("fog", ["spotbulb"], [.2, .2, .2]),
    }
    for name, text in scatter.items():
        write(f"spot_{name}.rad", text + box("fog", "box", *SPOT_BOX))
    for name in ("g0", "g07", "gneg", "colour"):
        runs.append(("mistscatter", name, ["spot.rad", f"spot_{name}.rad"], "beam.rays", REPEAT,
                     DET, "noise"))
    for ms in (".5", ".1", ".01"):
        for name in ("g0", "g07"):
            runs.append(("mistscatter", f"{name}_ms{ms.lstrip('.')}",
                         ["spot.rad", f"spot_{name}.rad"], "beam.rays", REPEAT,
                         f"{DET} -ms {ms}", "noise"))
    runs.append(("mistscatter", "global_albedo", ["spot.rad", "spot_global_albedo.rad"],
                 "beam.rays", REPEAT, f"{DET} -ma .8 .8 .8 -mg .5", "noise"))
    runs.append(("mistscatter", "g0_global", ["spot.rad", "spot_g0.rad"], "beam.rays", REPEAT,
                 f"{DET} -me .02 .03 .04 -ma .3 .3 .3 -mg .9 -av .1 .1 .1 -ms .4", "noise"))
    runs.append(("mistscatter", "g07_defaults", ["spot.rad", "spot_g07.rad"], "beam.rays",
                 REPEAT, "", "noise"))

    sources = {
        # The sphere lamp in the room.
        "bulb": ("room.rad", mist("fog", ["bulb"], [.3, .4, .5, .9, .6, .3]) +
                 box("fog", "box", *ROOM_BOX)),
        "bulb_g": ("room.rad", mist("fog", ["bulb"], [.3, .4, .5, .9, .6, .3, .6]) +
                   box("fog", "box", *ROOM_BOX)),
        # The sun listed; the spotlight and the sun, one of them listed, both.
        "sun": ("spot_sun.rad", mist("fog", ["sun"], [.2, .2, .2, .8, .8, .8, .5]) +
                box("fog", "box", *SPOT_BOX)),
        "spot_not_sun": ("spot_sun.rad", mist("fog", ["spotbulb"], [.2, .2, .2, .8, .8, .8]) +
                         box("fog", "box", *SPOT_BOX)),
        "both": ("spot_sun.rad", mist("fog", ["sun", "spotbulb"], [.2, .2, .2, .8, .8, .8, .3]) +
                 box("fog", "box", *SPOT_BOX)),
        # A black disc in the box over the middle of the beam.
        "blocker": ("spot.rad", mist("fog", ["spotbulb"], [.2, .2, .2, .8, .8, .8]) +
                    box("fog", "box", *SPOT_BOX) +
                    "black ring disc 0 0 8 0 0 2.2  0 0 1  0 .25\n"),
        # A sphere of scattering mist inside a box of absorbing haze.
        "nested": ("spot.rad", "void mist haze 0 0 3 .1 .15 .2\n" +
                   box("haze", "box", *SPOT_BOX) +
                   mist("fog", ["spotbulb"], [.3, .3, .3, .9, .9, .9, .4]) +
                   "fog sphere fogball 0 0 4 0 0 1.2 .9\n"),
        # The same sphere with the beam's source, the box with the sun.
        "overlap": ("spot_sun.rad", mist("haze", ["sun"], [.1, .1, .1, .8, .8, .8]) +
                    box("haze", "box", *SPOT_BOX) +
                    mist("fog", ["spotbulb"], [.3, .3, .3, .8, .8, .8]) +
                    "fog sphere fogball 0 0 4 0 0 1.2 .9\n"),
    }
    for name, (scene, text) in sources.items():
        write(f"src_{name}.rad", text)
        rays = "room.rays" if scene == "room.rad" else "beam.rays"
        runs.append(("mistsources", name, [scene, f"src_{name}.rad"], rays, REPEAT, DET,
                     "noise"))
    runs.append(("mistsources", "bulb_global_albedo", ["room.rad", "room_list3.rad"],
                 "room.rays", REPEAT, f"{DET} {media['mema']}", "noise"))
    runs.append(("mistsources", "bulb_ms", ["room.rad", "src_bulb.rad"], "room.rays", REPEAT,
                 f"{DET} -ms .2 -me .01 .01 .01 -av .2 .2 .2", "noise"))

    # 4. A mirror's virtual source: "mir>bulb" (default -dr); not found at -dr 0.
    mirror_mists = {
        "virtual": ["mir>bulb"],
        "both": ["bulb", "mir>bulb"],
        "real": ["bulb"],
    }
    for name, srcs in mirror_mists.items():
        write(f"mirror_{name}.rad", mist("fog", srcs, [.2, .2, .2, .8, .8, .8, .2]) +
              box("fog", "box", *MIRROR_BOX))
        runs.append(("mistmirror", name, ["mirror.rad", f"mirror_{name}.rad"], "mirror.rays",
                     REPEAT, DET, "noise"))
    runs.append(("mistmirror", "virtual_dr0", ["mirror.rad", "mirror_virtual.rad"],
                 "mirror.rays", 1, f"{DET} -dr 0", "exact"))
    runs.append(("mistmirror", "both_dr0", ["mirror.rad", "mirror_both.rad"], "mirror.rays",
                 REPEAT, f"{DET} -dr 0", "noise"))
    write("mirror_bad_relay.rad", mist("fog", ["bulb>mir", "nosuch>bulb", "mir>"],
                                       [.2, .2, .2, .8, .8, .8]) +
          box("fog", "box", *MIRROR_BOX))
    runs.append(("mistmirror", "bad_relay", ["mirror.rad", "mirror_bad_relay.rad"],
                 "mirror.rays", 1, DET, "exact"))

    # 5. Mist crossed with other features (noise): hemisphere rays of -ab 1
    # through the fog (each scattering the bulb's light and dimmed by it),
    # at view rays and -I sensors; the fog box as an octree instance,
    # moved, turned and scaled (extinction stays per unit of world length,
    # its source named in the scene), lit by the spotlight.
    write("cross_fog.rad", mist("fog", ["bulb"], [.3, .3, .3, .7, .7, .7, .3]) +
          box("fog", "box", *ROOM_BOX))
    for rays in ("room.rays", "room.pts"):
        runs.append(("mistcross", f"ab1_{rays.split('.')[1]}", ["room.rad", "cross_fog.rad"],
                     rays, REPEAT // 8, "-u+ -dj 0 -dt 0 -ab 1 -aa 0 -ad 64 -as 0" +
                     (" -I" if rays == "room.pts" else ""), "noise"))
    write("inst_fog.rad", mist("fog", ["spotbulb"], [.2, .2, .2, .8, .8, .8]) +
          box("fog", "box", -1, 1, -1, 1, -.5, 1.5))
    with open(os.path.join(OUT, "inst_fog.oct"), "wb") as f:
        subprocess.run([os.path.join(BIN, "oconv"), "-f", "inst_fog.rad"], stdout=f,
                       check=True, env=ENV, cwd=OUT)
    write("cross_instance.rad", "void instance fogi 9 inst_fog.oct -rz 30 -s 1.5 -t .1 0 0 0 0\n")
    runs.append(("mistcross", "instance", ["spot.rad", "cross_instance.rad"], "beam.rays",
                 REPEAT, DET, "noise"))

    # 6. Messages.
    lamps = "".join(f"lamp sphere l{i} 0 0 4 {i % 6 - 2.5} {i // 6 - 2.5} 4 .05\n"
                    for i in range(34))
    write("lamps.rad", "void light lamp 0 0 3 50 50 50\n" + lamps +
          "void plastic grey 0 0 5 .5 .5 .5 0 0\n"
          "grey polygon floor 0 0 12 -10 -10 0  10 -10 0  10 10 0  -10 10 0\n")
    errors = {
        "reals8": ("room.rad", mist("fog", [], [.3, .4, .5, .9, .6, .3, .5, 1]) +
                   box("fog", "box", *ROOM_BOX)),
        "unknown": ("room.rad", mist("fog", ["nosuch", "bulb", "other"], [.3, .4, .5]) +
                    box("fog", "box", *ROOM_BOX)),
        "duplicate": ("room.rad", mist("fog", ["bulb", "bulb"], [.3, .4, .5]) +
                      box("fog", "box", *ROOM_BOX)),
        "sources32": ("lamps.rad", mist("fog", [f"l{i}" for i in range(32)], [.3, .4, .5]) +
                      box("fog", "box", -3, 3, -3, 3, -.5, 3)),
        "sources33": ("lamps.rad", mist("fog", [f"l{i}" for i in range(33)], [.3, .4, .5]) +
                      box("fog", "box", -3, 3, -3, 3, -.5, 3)),
        # 17 sources and 17 others: a ray in both mists has 34 in its list.
        "overflow": ("lamps.rad", mist("fog", [f"l{i}" for i in range(17)], [.3, .4, .5]) +
                     box("fog", "box", -3, 3, -3, 3, -.5, 3) +
                     mist("haze", [f"l{i}" for i in range(17, 34)], [.1, .1, .1]) +
                     box("haze", "inner", -1, 1, -1, 1, .5, 2)),
    }
    for name, (scene, text) in errors.items():
        write(f"error_{name}.rad", text)
        rays = "room.rays" if scene == "room.rad" else "lamps.rays"
        runs.append(("misterror", name, [scene, f"error_{name}.rad"], rays, 1, DET, "exact"))
    write("lamps.rays", "-4 0 1 1 0 0\n0 0.5 2.8 0 0 -1\n0.2 0.1 1.5 0 0 -1\n")

    run_and_write(runs, radiance, OUT,
                  "# Real Radiance 5.4a's answers for the mist cases of\n"
                  "# tests/direct/direct_matrix_test.cpp, written by\n"
                  "# tests/direct/generate_mist.py (format as in generate.py).\n",
                  lazy_noise_repeat=LAZY_REPEAT)


if __name__ == "__main__":
    main()
