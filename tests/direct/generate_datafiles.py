#!/usr/bin/env python3
# Generates the data-file pattern cases (tests/data/datafiles/) for
# tests/direct/direct_matrix_test.cpp, with REAL Radiance 5.4a's answers:
# brightdata, colordata and colorpict at -ab 0 (1-D to 5-D data, regular,
# irregular and descending axes, extrapolation beyond both ends, transforms,
# chains with brightfunc, an ies2rad-style luminaire over source.cal lighting a
# floor, pictures on lights and on plastic) and the bad-input errors. A
# developer's tool: it needs ../shared/reference/radiance-5.4a (or
# RADIANCE=<its folder>); the test only reads what this writes. Same
# expected.txt format as generate.py.
#
#   tests/direct/generate_datafiles.py
#
# Radiance runs with RAYPATH=.:<its lib> (its own source.cal); the test runs
# lazyrad with RAYPATH=<this folder>, so lazyrad's own lib/source.cal is used.
# Radiance names data files as found ("./d6.dat"); lazyrad as written
# ("d6.dat"), so "./" is dropped from Radiance's messages here.
import os
import subprocess
import sys
import tempfile

from matrix_data import write_expected

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
OUT = os.path.join(ROOT, "tests", "data", "datafiles")
RADIANCE = os.environ.get(
    "RADIANCE", os.path.normpath(os.path.join(ROOT, "..", "shared", "reference", "radiance-5.4a")))
BIN = os.path.join(RADIANCE, "bin")
ENV = dict(os.environ, RAYPATH="." + os.pathsep + os.path.join(RADIANCE, "lib"))

PLANE = "polygon p 0 0 12 -10 -10 0  10 -10 0  10 10 0  -10 10 0"
DET = "-u- -dj 0 -dt 0"


def write(name, text, mode="w"):
    with open(os.path.join(OUT, name), mode) as f:
        f.write(text)


def rays_at(name, points):
    """Rays straight down onto the plane z = 0 at (x, y)."""
    write(name, "".join(f"{x} {y} 5 0 0 -1\n" for x, y in points))


def radiance(files, rays, options, tmp):
    octree = os.path.join(tmp, "scene.oct")
    with open(octree, "wb") as f:
        oc = subprocess.run([os.path.join(BIN, "oconv")] + files, stdout=f,
                            stderr=subprocess.PIPE, env=ENV, cwd=OUT)
    if oc.returncode != 0:
        return oc.returncode, [l.replace(os.path.join(BIN, "oconv"), "oconv")
                               for l in oc.stderr.decode().splitlines()], []
    with open(os.path.join(OUT, rays)) as f:
        lines = [l for l in f.read().splitlines() if l.strip()]
    r = subprocess.run([os.path.join(BIN, "rtrace"), "-h"] + options.split() + [octree],
                       input="".join(l + "\n" for l in lines), capture_output=True,
                       text=True, env=ENV, cwd=OUT)
    rows = [[float(x) for x in l.split()] for l in r.stdout.splitlines() if l.strip()]
    err = [l.replace(os.path.join(BIN, "rtrace"), "rtrace").replace('"./', '"')
           for l in r.stderr.splitlines()]
    return r.returncode, err, rows


def picture(name, width, height, pixels, header=""):
    """A Radiance picture made by real pvalue from (r, g, b) rows, top row first."""
    text = "".join(f"{r} {g} {b}\n" for row in pixels for r, g, b in row)
    pic = subprocess.run([os.path.join(BIN, "pvalue"), "-r", "-h", "-d", "-y", str(height),
                          "+x", str(width)], input=text.encode(), capture_output=True,
                         check=True).stdout
    if header:
        pic = pic.replace(b"FORMAT=", header.encode() + b"\nFORMAT=", 1)
    write(name, pic, "wb")


def counted(text):
    """Replaces each "N# words" string-argument line by "<number of words> words"."""
    return "\n".join(f"{len(l.split()) - 1} {' '.join(l.split()[1:])}" if l.startswith("N# ") else l
                     for l in text.split("\n"))


def main():
    os.makedirs(OUT, exist_ok=True)
    for f in os.listdir(OUT):
        os.remove(os.path.join(OUT, f))
    runs = []  # (group, name, files, rays, options)

    def light_case(group, name, pattern, rays, color="1 1 1", extra=""):
        pattern = counted(pattern)
        write(f"{group}_{name}.rad", extra + pattern + f"\npat light lit 0 0 3 {color}\nlit {PLANE}\n")
        runs.append((group, name, [f"{group}_{name}.rad"], rays, "-ab 0"))

    # 1. One dimension: regular (spec 11.14 item 2), irregular, descending,
    # number formats and comments; points inside, on the ends, one division
    # beyond (the upper discontinuity) and far beyond both ends.
    write("d1.dat", "1\n0 4 5\n10 20 30 40 80\n")
    write("irr.dat", "1\n0 0 4 0 1 3 10\n# irregular coordinates\n0 10 20 30\n")
    write("low.dat", "1\n0 4 5\n50 40 30 20 10\n")
    write("desc.dat", "1\n10 0 5\n0 10 20 30 40\n")
    write("descirr.dat", "1\n0 0 4 3 1 0 -2\n30 10 0 -20\n")
    write("formats.dat", "1 # dims\n+0 4.e0 05#points\n\t10 2.0e1 +30.\r\n.4e2 8E1 # tail\n")
    write("eqdesc.dat", "1\n0 0 3 3 3 2\n3 7 8\n")
    xs = [0, 0.5, 2.5, 4, 4.5, 5, 5.0001, 6, -0.5, -1, -1.0001, -3, 9.99, -9.99]
    rays_at("x.rays", [(x, 0) for x in xs])
    rays_at("xi.rays", [(x, 0) for x in (2, 6.5, -1, 10, 0, 0.5, 9.99, -2, -9.99, 3, 1)])
    # (Not 3 for eqdesc: between its equal coordinates both programs give NaN.)
    rays_at("xq.rays", [(x, 0) for x in (2.5, 2, 1, 5, -1, 0.5, 4.5)])
    rays_at("xd.rays", [(x, 0) for x in (0, 2.5, 10, -2.5, -5, 9.99, -9.99, 2, 0.5, -1, 3, 4, 5)])
    for name, data, rays in (("regular", "d1.dat", "x.rays"), ("irregular", "irr.dat", "xi.rays"),
                             ("lower", "low.dat", "x.rays"), ("descending", "desc.dat", "xd.rays"),
                             ("descirr", "descirr.dat", "xd.rays"),
                             ("formats", "formats.dat", "x.rays"),
                             ("eqdesc", "eqdesc.dat", "xq.rays")):
        light_case("data1d", name, f"void brightdata pat\nN# noop {data} . Px\n0\n0", rays)
    # Far beyond the ends through a scale transform (P = 0.001 * hit).
    light_case("data1d", "far", "void brightdata pat\nN# noop d1.dat . Px -s 0.001\n0\n0", "x.rays")

    # 2. Two to five dimensions, mixed regular and irregular axes.
    write("d2.dat", "2\n0 1 2\n0 2 3\n1 2 3\n4 5 6\n")
    write("d3.dat", "3\n0 1 2\n0 0 3 0 1 4\n1 -1 3\n" +
          " ".join(str(v * v % 17 + v) for v in range(18)) + "\n")
    write("d5.dat", "5\n0 1 2\n0 1 2\n0 0 3 -1 0 2\n1 0 2\n0 2 2\n" +
          " ".join(str((v * 7) % 11 - 3) for v in range(48)) + "\n")
    pts = [(0, 0), (0.5, 1), (1, 2), (0.25, 0.5), (2, 1), (-1, 1), (3, 5), (-2, -3), (0.7, 3.3),
           (5, -1), (-4, 6), (1.5, 1.5)]
    rays_at("xy.rays", pts)
    light_case("datand", "two", "void brightdata pat\nN# noop d2.dat . Px Py\n0\n0", "xy.rays")
    light_case("datand", "three", "void brightdata pat\nN# noop d3.dat . Px Py Px*Py\n0\n0", "xy.rays")
    light_case("datand", "five",
               "void brightdata pat\nN# noop d5.dat . Px Py Px-Py Py/3 Px*Py/4\n0\n0", "xy.rays")

    # 3. Functions, function files, real arguments, transforms, chains.
    write("data.cal", "sq1(v) = v*v + A1;\nnear = Px/2;\n")
    light_case("datafunc", "file_function",
               "void brightdata pat\nN# sq1 d1.dat data.cal near\n0\n1 0.5", "x.rays")
    light_case("datafunc", "library_function",
               "void brightdata pat\nN# sqrt d1.dat . Px\n0\n0", "x.rays")
    light_case("datafunc", "xf_rz_s",
               "void brightdata pat\nN# noop d2.dat . Px Py -rz 90 -s 2\n0\n0", "xy.rays")
    light_case("datafunc", "xf_t_mx",
               "void brightdata pat\nN# noop d2.dat . Px Py -t 1 0 0 -mx\n0\n0", "xy.rays")
    light_case("datafunc", "chain_brightfunc",
               "void brightfunc b2\n2 Py+2 .\n0\n0\nb2 brightdata pat\nN# noop d2.dat . Px Py\n0\n0",
               "xy.rays", color="1 2 3")
    light_case("datafunc", "chain_below",
               "void brightdata pat\nN# noop d2.dat . Px Py\n0\n0\n"
               "pat light l2 0 0 3 2 2 2\nvoid colorfunc pat2\n4 1 Px 2 .\n0\n0\n"
               "pat2 alias pat l2", "xy.rays")
    light_case("datafunc", "compute_error",
               "void brightdata pat\nN# noop d1.dat . 1/(Px-4)\n0\n0", "x.rays", color="2 2 2")

    # 4. colordata (spec item 7): each function its own channel, or all three.
    write("r.dat", "1\n0 4 5\n1 2 3 4 5\n")
    write("g.dat", "1\n0 4 5\n10 20 30 40 50\n")
    write("b.dat", "1\n0 0 3 0 1 4\n100 200 500\n")
    write("rgb3.cal", "mix3(r, g, b) = r + g/10 + b/100;\n")
    light_case("colordata", "noop", "void colordata pat\nN# noop noop noop r.dat g.dat b.dat . Px\n0\n0",
               "x.rays")
    light_case("colordata", "grey_noop_red",
               "void colordata pat\nN# grey noop red r.dat g.dat b.dat . Px\n0\n0", "x.rays")
    light_case("colordata", "user3",
               "void colordata pat\nN# mix3 noop mix3 r.dat g.dat b.dat rgb3.cal Px -s 0.5 -t 1 0 0\n0\n0",
               "x.rays")

    # 5. colorpict: a 4x2 landscape picture (spec item 8), a portrait one, one
    # with a pixel aspect ratio; on a light and on plastic under a lamp.
    picture("p.hdr", 4, 2, [[(c + 1, 2, 1) for c in range(4)], [(c + 1, 1, 1) for c in range(4)]])
    picture("tall.hdr", 3, 5, [[(c + 1, 5 - r, (c * r) % 3 + 0.5) for c in range(3)]
                               for r in range(5)])
    picture("aspect.hdr", 4, 2, [[(c + 1, 2, 1) for c in range(4)],
                                 [(c + 1, 1, 1) for c in range(4)]], header="PIXASPECT=0.5")
    rays_at("uv.rays", [(0, 0), (2, 1), (1, 0.5), (0.6666667, 0), (2, 0), (3, 0), (-1, -1),
                        (1.3, 0.7), (0.2, 1.6), (0.5, 2.5), (-0.3, 0.4)])
    # Pictures one pixel high, one pixel wide and a single pixel: Radiance's
    # datavalue() gives the value of the one row (column) all along that axis.
    picture("row.hdr", 4, 1, [[(c + 1, 2, 0.5 * c + 1) for c in range(4)]])
    picture("column.hdr", 1, 3, [[(3 - r, r + 1, 2)] for r in range(3)])
    picture("pixel.hdr", 1, 1, [[(3, 2, 1)]])
    for name, pic in (("landscape", "p.hdr"), ("portrait", "tall.hdr"), ("aspect", "aspect.hdr"),
                      ("row", "row.hdr"), ("column", "column.hdr"), ("pixel", "pixel.hdr")):
        light_case("colorpict", name,
                   f"void colorpict pat\nN# red green blue {pic} . Px Py\n0\n0", "uv.rays")
    light_case("colorpict", "grey_xf",
               "void colorpict pat\nN# grey noop blue p.hdr . Px Py -rz 30 -s 0.5\n0\n0", "uv.rays")
    write("colorpict_plastic.rad", counted(
          "void light lamp 0 0 3 100 100 100\nlamp sphere bulb 0 0 4 1 0.5 4 .5\n"
          "void colorpict pat\nN# red green blue p.hdr . Px/4 Py/4\n0\n0\n"
          "pat plastic paint 0 0 5 .6 .6 .6 0 0\npaint " + PLANE + "\n"))
    write("eye.rays", "".join(f"{x} {y} 5 0 0 -1\n" for x, y in
                              ((0, 0), (2, 1), (4, 2), (6, 3), (-2, 1), (9, 9))))
    runs.append(("colorpict", "plastic", ["colorpict_plastic.rad"], "eye.rays", f"{DET} -ab 0"))

    # 6. ies2rad-style luminaires over real Radiance's source.cal, lighting a
    # floor at -ab 0: a flat square emitter with a 1-D (symmetric) and with a
    # 2-D (quadrilateral symmetry) candela table, a box emitter with boxcorr.
    write("lum1.dat", "1\n0 0 7 0 15 30 45 60 75 90\n# candela\n"
          "1200 1150 980 700 380 120 10\n")
    write("lum2.dat", "2\n0 90 3\n0 0 7 0 15 30 45 60 75 90\n"
          "1200 1150 980 700 380 120 10\n1200 1100 900 600 300 100 8\n"
          "1200 1000 800 500 200 60 5\n")
    flat = "lamp_light polygon lamp.d 0 0 12 -.25 -.25 2.5  -.25 .25 2.5  .25 .25 2.5  .25 -.25 2.5\n"
    box = subprocess.run(os.path.join(BIN, "genbox") + " lamp_light lamp .4 .3 .2 | " +
                         os.path.join(BIN, "xform") + " -t -.2 -.15 2.4", shell=True,
                         capture_output=True, text=True, check=True).stdout
    box = "".join(l + "\n" for l in box.splitlines() if not l.startswith("#"))
    lums = {
        "flat_1d": ("void brightdata lamp_dist\nN# flatcorr lum1.dat source.cal src_theta\n0\n1 0.01\n", flat),
        "flat_2d": ("void brightdata lamp_dist\nN# flatcorr lum2.dat source.cal src_phi4 src_theta\n0\n1 0.01\n",
                    flat),
        "flat_2d_rz": ("void brightdata lamp_dist\nN# flatcorr lum2.dat source.cal src_phi4 src_theta -rz 30\n"
                       "0\n1 0.01\n", flat),
        "box_2d": ("void brightdata lamp_dist\nN# boxcorr lum2.dat source.cal src_phi4 src_theta\n0\n"
                   "4 0.01 .4 .3 .2\n", box),
    }
    write("floor.pts", "".join(f"{x} {y} 0.001 0 0 1\n" for x, y in
                               ((0, 0), (1, 0.5), (-2, 1), (3, -3), (0.5, 2), (-1, -1))))
    for name, (dist, geometry) in lums.items():
        write(f"ies_{name}.rad", counted(dist) + "lamp_dist light lamp_light\n0\n0\n3 1 1 1\n" + geometry +
              "void plastic floor 0 0 5 .5 .5 .5 0 0\nfloor polygon fl 0 0 12 "
              "-10 -10 0  10 -10 0  10 10 0  -10 10 0\n")
        for rname, options in (("ds0", f"{DET} -ds 0 -I -ab 0"), ("ds02", f"{DET} -ds 0.2 -I -ab 0")):
            runs.append(("ies", f"{name}_{rname}", [f"ies_{name}.rad"], "floor.pts", options))

    # 6b. texdata (three functions, always of the three values), mixdata and
    # mixpict (one function; mixpict's of the three picture values), on their
    # own and under materials, with a transform.
    write("tex.cal", "tx(a, b, c) = a;\nty(a, b, c) = b;\ntz(a, b, c) = c + 0 * a * b;\n")
    write("tdx.dat", "1\n0 4 5\n0 .2 .4 -.3 .1\n")
    write("tdy.dat", "1\n0 4 5\n.1 0 -.2 .3 0\n")
    write("tdz.dat", "1\n0 4 5\n0 0 .1 .2 .3\n")
    write("mix.dat", "1\n0 4 5\n0 .25 .5 1 1.5\n")
    picture("m.hdr", 4, 2, [[(c / 4, 0.5, 0.2) for c in range(4)], [(0.9, c / 5, 0.1) for c in range(4)]])
    lamp = "void light lamp 0 0 3 100 100 100\nlamp sphere bulb 0 0 4 1 0.5 4 .5\n"
    for name, xf in (("plain", ""), ("xf", " -rz 90 -s 2")):
        write(f"texdata_{name}.rad", counted(
              lamp + f"void texdata tex\nN# tx ty tz tdx.dat tdy.dat tdz.dat tex.cal Px{xf}\n0\n0\n"
              "tex plastic shiny 0 0 5 .6 .5 .4 .05 .02\nshiny " + PLANE + "\n"))
        runs.append(("texdata", name, [f"texdata_{name}.rad"], "eye.rays", f"{DET} -ab 0 -ovn"))
    for name, pattern in (
            ("mixdata", "void mixdata mx\nN# red blue noop mix.dat . Px\n0\n0\n"),
            ("mixdata_xf", "void mixdata mx\nN# red blue noop mix.dat . Px -t 1 0 0\n0\n0\n"),
            ("mixpict", "void mixpict mx\nN# red blue grey m.hdr . Px Py\n0\n0\n"),
            ("mixpict_void", "void mixpict mx\nN# red void grey m.hdr . Px Py\n0\n0\n")):
        write(f"mix_{name}.rad", counted(
              "void light red 0 0 3 1 0 0\nvoid light blue 0 0 3 0 0 1\n"
              "void light behind 0 0 3 0 2 0\nbehind polygon under 0 0 12 "
              "-10 -10 -1  10 -10 -1  10 10 -1  -10 10 -1\n" + pattern + "mx " + PLANE + "\n"))
        runs.append(("mixdata", name, [f"mix_{name}.rad"], "x.rays" if "data" in name else "uv.rays",
                     "-ab 0"))
    # Two patterns mixed by data under a light: the mixture acts as a pattern.
    write("mix_patterns.rad", counted(
          "void brightfunc b2 2 2 . 0 0\nvoid brightfunc b4 2 4 . 0 0\n"
          "void mixdata mx\nN# b2 b4 noop mix.dat . Px\n0\n0\n"
          "mx light lit 0 0 3 1 1 1\nlit " + PLANE + "\n"))
    runs.append(("mixdata", "patterns", ["mix_patterns.rad"], "x.rays", "-ab 0"))

    # 7. Bad input: each a fatal error from both programs.
    bad = {
        "nonmonotonic": "1\n0 0 4 0 2 1 3\n1 2 3 4\n",
        "count1": "1\n0 4 1\n5\n",
        "dims6": "6\n",
        "dims0": "0\n",
        "few_values": "1\n0 4 5\n1 2 3\n",
        "few_values_noeol": "1\n0 4 5\n1 2 3 4 5x",
        "bad_word": "1\n0 4 5\n1 2 x 4 5\n",
        "float_count": "1\n0 4 5.0\n1 2 3 4 5\n",
        "long_word": "1\n0 4 2\n1 " + "7" * 64 + "\n",
        "empty": "",
        "comment_only": "# nothing\n",
        "hash_in_word": "1\n0 4 2\n3#x 7\n",
    }
    for name, text in bad.items():
        write(f"bad_{name}.dat", text)
        light_case("error", name, f"void brightdata pat\nN# noop bad_{name}.dat . Px\n0\n0", "x.rays")
    light_case("error", "missing_data", "void brightdata pat\nN# noop nonexist.dat . Px\n0\n0", "x.rays")
    light_case("error", "missing_picture",
               "void colorpict pat\nN# red green blue nonexist.hdr . Px Py\n0\n0", "x.rays")
    write("bad_picture.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 4\nshort")
    light_case("error", "bad_picture",
               "void colorpict pat\nN# red green blue bad_picture.hdr . Px Py\n0\n0", "x.rays")
    # 57 bytes declaring 2^40 pixels: both programs refuse it (lazyrad before
    # reading any pixel, tests/image/hdr_test.cpp), exit status 1.
    write("huge_picture.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1048576 +X 1048576\n")
    light_case("error", "huge_picture",
               "void colorpict pat\nN# red green blue huge_picture.hdr . Px Py\n0\n0", "x.rays")
    light_case("error", "few_strings", "void brightdata pat\nN# noop d2.dat .\n0\n0", "x.rays")
    light_case("error", "few_coordinates", "void brightdata pat\nN# noop d2.dat . Px\n0\n0", "x.rays")
    light_case("error", "dimension_mismatch",
               "void colordata pat\nN# noop noop noop r.dat d2.dat b.dat . Px\n0\n0", "x.rays")
    light_case("error", "undefined_function",
               "void brightdata pat\nN# nosuchf d1.dat . Px\n0\n0", "x.rays")
    light_case("error", "bad_transform",
               "void brightdata pat\nN# noop d1.dat . Px -t 1\n0\n0", "x.rays")

    blocks = []
    with tempfile.TemporaryDirectory() as tmp:
        for group, name, files, rays, options in runs:
            status, err, rows = radiance(files, rays, options, tmp)
            blocks.append(dict(group=group, name=name, files=files, rays=rays, repeat=1,
                               options=options, check="exact", status=status, err=err,
                               rows=rows, sems=[], notes=[]))
    write_expected(os.path.join(OUT, "expected.txt"),
                   "# Real Radiance 5.4a's answers for the data-file cases of\n"
                   "# tests/direct/direct_matrix_test.cpp, written by\n"
                   "# tests/direct/generate_datafiles.py (format as in generate.py).\n", blocks)
    print(f"{len(blocks)} runs written to {OUT}", file=sys.stderr)


if __name__ == "__main__":
    main()
