#!/usr/bin/env python3
"""How far an ambient file's records are from the truth at their own points.

    bench/record_errors.py [--bin DIR] [--ad N] [--near X Y Z D] AMBFILE BOUNCES LEVEL SCENE...

A record of LEVEL made in a run with -ab BOUNCES holds BOUNCES - LEVEL bounces
of indirect light: its value is the cosine-weighted mean radiance its
hemisphere saw, light sources counting 0 (radiance-notes §4.8). The truth at
its point and normal is that run's irradiance without the cache (`-aa 0 -ab
BOUNCES-LEVEL -ad N -as 0`) less the direct part (`-ab 0`), over pi. Each
record's relative error is value / truth - 1; the mean over many records is
their bias (the truth's own noise averages out), their RMS includes the
truth's noise. Records whose truth is below 1e-3 (in the scene's units) are
left out. --near keeps the records within D of (X, Y, Z).

Uses DIR/lookamb and DIR/rtrace (default build/bin): lazyrad's lookamb reads
Radiance's files too, so records made by real Radiance can be checked the
same way.
"""
import argparse
import math
import os
import subprocess
import sys

from values import luminance, rows


def run(cmd, text_in=None):
    return subprocess.run(cmd, input=text_in, capture_output=True, text=True, check=True).stdout


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--bin", default=os.path.join(root, "build", "bin"))
    ap.add_argument("--ad", type=int, default=4096)
    ap.add_argument("--near", type=float, nargs=4, metavar=("X", "Y", "Z", "D"))
    ap.add_argument("ambfile")
    ap.add_argument("bounces", type=int)
    ap.add_argument("level", type=int)
    ap.add_argument("scene", nargs="+")
    a = ap.parse_args()
    if not 0 <= a.level < a.bounces:
        sys.exit("record_errors.py: LEVEL must lie in [0, BOUNCES)")
    # lookamb -d: position, normal, u axis, level, weight, two radii, value
    # (RGB), two positional and two directional gradients, corral bits.
    records = [r for r in rows(run([os.path.join(a.bin, "lookamb"), "-h", "-d", a.ambfile]))
               if int(r[9]) == a.level]
    if a.near:
        x, y, z, d = a.near
        records = [r for r in records
                   if (r[0] - x) ** 2 + (r[1] - y) ** 2 + (r[2] - z) ** 2 <= d * d]
    if not records:
        sys.exit("record_errors.py: no records of that level")
    rays = "".join(" ".join(f"{v:.9g}" for v in r[:6]) + "\n" for r in records)
    rtrace = os.path.join(a.bin, "rtrace")
    common = ["-h", "-I", "-lw", "1e-6"]
    indirect = rows(run([rtrace, *common, "-ab", str(a.bounces - a.level), "-aa", "0",
                         "-ad", str(a.ad), "-as", "0", *a.scene], rays))
    direct = rows(run([rtrace, *common, "-ab", "0", *a.scene], rays))
    groups = {"all": [], "at the largest radius": [], "below it": []}
    largest = max(r[12] for r in records)
    for r, full, dir_ in zip(records, indirect, direct):
        truth = (luminance(full[:3]) - luminance(dir_[:3])) / math.pi
        if truth <= 1e-3:
            continue
        e = luminance(r[13:16]) / truth - 1
        groups["all"].append(e)
        groups["at the largest radius" if r[11] >= largest * (1 - 1e-6) else "below it"].append(e)
    for name, errors in groups.items():
        n = len(errors)
        if n < 2:
            continue
        mean = sum(errors) / n
        sd = math.sqrt(sum((e - mean) ** 2 for e in errors) / (n - 1))
        rms = math.sqrt(sum(e * e for e in errors) / n)
        print(f"{name}: {n} records, mean error {100 * mean:+.2f} % ± {100 * sd / math.sqrt(n):.2f}, "
              f"RMS {100 * rms:.2f} %")


if __name__ == "__main__":
    main()
