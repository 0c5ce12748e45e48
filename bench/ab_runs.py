#!/usr/bin/env python3
"""Wall time of several rtrace binaries on one job, run in turn so that a noisy
host slows them alike; millisecond resolution, for jobs too short for
bench/ab_time.sh's. Prints each binary's minimum and median and the MD5 of its
last output (equal when the output is meant unchanged).

  bench/ab_runs.py [-n RUNS] [--opts "RTRACE OPTIONS"] [--scene S] [--points P] BIN...

Defaults: 20 runs each, the fast cornell floor of issue 17
(-h -I -ab 2 -ad 256 -as 128 -aa .2 -ar 64, scenes/cornell/cornell.rad,
scenes/cornell/floor.pts). Compares builds with each other, not with Radiance:
speed-ups over Radiance come from bench/side_by_side.sh.
"""
import argparse
import hashlib
import pathlib
import statistics
import subprocess
import time

root = pathlib.Path(__file__).resolve().parent.parent
ap = argparse.ArgumentParser()
ap.add_argument("-n", type=int, default=20, help="runs per binary")
ap.add_argument("--opts", default="-h -I -ab 2 -ad 256 -as 128 -aa .2 -ar 64")
ap.add_argument("--scene", default=str(root / "scenes/cornell/cornell.rad"))
ap.add_argument("--points", default=str(root / "scenes/cornell/floor.pts"))
ap.add_argument("binaries", nargs="+")
args = ap.parse_args()

rays = pathlib.Path(args.points).read_bytes()
times = {b: [] for b in args.binaries}
digest = {}
for _ in range(args.n):
    for b in args.binaries:
        start = time.perf_counter()
        out = subprocess.run([b, *args.opts.split(), args.scene], input=rays,
                             stdout=subprocess.PIPE, check=True).stdout
        times[b].append(time.perf_counter() - start)
        digest[b] = hashlib.md5(out).hexdigest()
for b in args.binaries:
    t = times[b]
    print(f"{b}: min {1000 * min(t):.1f} ms, median {1000 * statistics.median(t):.1f} ms "
          f"over {len(t)} runs, output md5 {digest[b]}")
