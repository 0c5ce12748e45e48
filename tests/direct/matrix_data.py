# Shared by tests/direct/generate.py and generate_patterns.py: the mean and
# standard error of repeated rows, and the expected.txt format that
# tests/direct/direct_matrix_test.cpp reads (described in generate.py).
import math
import os
import sys
import tempfile


def fresh_folder(out):
    """Creates `out` (emptied if it exists) and returns write(name, text),
    which writes a file into it."""
    os.makedirs(out, exist_ok=True)
    for f in os.listdir(out):
        os.remove(os.path.join(out, f))

    def write(name, text):
        with open(os.path.join(out, name), "w") as f:
            f.write(text)
    return write


def mean_and_sem(rows, rays, repeat):
    """Per input ray: the mean of its `repeat` output rows, and the standard
    error of each mean."""
    groups = [rows[i * repeat:(i + 1) * repeat] for i in range(rays)]
    means = [[sum(g[k][j] for k in range(repeat)) / repeat for j in range(len(g[0]))]
             for g in groups]
    sems = [[math.sqrt(sum((g[k][j] - m[j]) ** 2 for k in range(repeat)) / (repeat - 1) / repeat)
             for j in range(len(m))] for g, m in zip(groups, means)]
    return means, sems


def write_expected(path, header, blocks):
    """blocks: dicts with group name files rays repeat options check status
    err rows notes sems."""
    with open(path, "w") as f:
        f.write(header)
        for b in blocks:
            f.write(f"case {b['group']} {b['name']}\nfiles {' '.join(b['files'])}\n"
                    f"rays {b['rays']} {b['repeat']}\noptions {b['options']}\n"
                    f"check {b['check']}\nstatus {b['status']}\n")
            for line in b["err"]:
                f.write(f"err {line}\n")
            for line in b["notes"]:
                f.write(f"note {line}\n")
            for row in b["rows"]:
                f.write("out " + " ".join("%.7g" % v for v in row) + "\n")
            for row in b["sems"]:
                f.write("sem " + " ".join("%.4g" % v for v in row) + "\n")
            f.write("end\n")


def run_and_write(runs, radiance, out, header, lazy_noise_repeat=16):
    """Runs each (group, name, files, rays, repeat, options, check) of `runs`
    through real Radiance (`radiance`, generate_patterns.radiance) and writes
    out/expected.txt after `header`. "noise" runs: Radiance's mean over
    `repeat` repeats against lazyrad's over `lazy_noise_repeat`."""
    blocks = []
    with tempfile.TemporaryDirectory() as tmp:
        for group, name, files, rays, repeat, options, check in runs:
            lazy_repeat = lazy_noise_repeat if check == "noise" else repeat
            status, err, rows, sems = radiance(files, rays, repeat, options, tmp, out=out)
            blocks.append(dict(group=group, name=name, files=files, rays=rays,
                               repeat=lazy_repeat, options=options, check=check,
                               status=status, err=err, rows=rows,
                               sems=sems if check == "noise" else [],
                               notes=[f"Radiance's mean over {repeat} repeats"]
                               if check == "noise" else []))
    write_expected(os.path.join(out, "expected.txt"), header, blocks)
    print(f"{len(blocks)} runs written to {out}", file=sys.stderr)


# The room x, y in [-2, 2], z in [-1, 2], faces turned inwards, with a lamp:
# where the -ab 1 cases put the surface they test.
LIT_BOX = ("void plastic wall 0 0 5 .5 .5 .5 0 0\n" + "".join(
    f"wall polygon {n} 0 0 12 {v}\n" for n, v in (
        ("floor", "-2 -2 -1  2 -2 -1  2 2 -1  -2 2 -1"),
        ("ceiling", "-2 -2 2  -2 2 2  2 2 2  2 -2 2"),
        ("south", "-2 -2 -1  -2 -2 2  2 -2 2  2 -2 -1"),
        ("north", "-2 2 -1  2 2 -1  2 2 2  -2 2 2"),
        ("west", "-2 -2 -1  -2 2 -1  -2 2 2  -2 -2 2"),
        ("east", "2 -2 -1  2 -2 2  2 2 2  2 2 -1"))) +
    "void light l 0 0 3 20 20 20\nl sphere bulb 0 0 4 0 0 1.5 .2\n")


def box(mod, name, lo, hi):
    """A closed box of six polygons of `mod` from corner `lo` to corner `hi`,
    normals outward (genbox's order; checked)."""
    (x0, y0, z0), (x1, y1, z1) = lo, hi
    faces = {
        "xlo": [(x0, y0, z0), (x0, y0, z1), (x0, y1, z1), (x0, y1, z0)],
        "xhi": [(x1, y0, z0), (x1, y1, z0), (x1, y1, z1), (x1, y0, z1)],
        "ylo": [(x0, y0, z0), (x1, y0, z0), (x1, y0, z1), (x0, y0, z1)],
        "yhi": [(x0, y1, z0), (x0, y1, z1), (x1, y1, z1), (x1, y1, z0)],
        "zlo": [(x0, y0, z0), (x0, y1, z0), (x1, y1, z0), (x1, y0, z0)],
        "zhi": [(x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)],
    }
    centre = ((x0 + x1) / 2, (y0 + y1) / 2, (z0 + z1) / 2)
    for f, v in faces.items():
        e1 = [v[1][k] - v[0][k] for k in range(3)]
        e2 = [v[2][k] - v[0][k] for k in range(3)]
        n = (e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
             e1[0] * e2[1] - e1[1] * e2[0])
        mid = [sum(p[k] for p in v) / 4 - centre[k] for k in range(3)]
        assert sum(n[k] * mid[k] for k in range(3)) > 0, f
    return "".join(f"{mod} polygon {name}.{k} 0 0 12 " +
                   "  ".join(" ".join(f"{c:g}" for c in v) for v in vs) + "\n"
                   for k, vs in faces.items())
