#!/usr/bin/env python3
"""Wall time of several rtrace binaries on one job, run in turn so that a noisy
host slows them alike; millisecond resolution, for jobs too short for
the shell's clock. Prints each binary's minimum and median, the MD5 of its last
output (equal when the output is meant unchanged) and, given a reference, that
output's error (bench/score.py). bench/ab_time.sh is this script on the cornell
floor job at Radiance's defaults.

  bench/ab_runs.py [-n RUNS] [--opts="RTRACE OPTIONS"] [--scene S] [--points P]
                   [--ref REF] BIN...

(--opts with "=", as its value begins with a dash.)

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
import sys
import tempfile
import time

root = pathlib.Path(__file__).resolve().parent.parent
ap = argparse.ArgumentParser()
ap.add_argument("-n", type=int, default=20, help="runs per binary")
ap.add_argument("--opts", default="-h -I -ab 2 -ad 256 -as 128 -aa .2 -ar 64")
ap.add_argument("--scene", default=str(root / "scenes/cornell/cornell.rad"))
ap.add_argument("--points", default=str(root / "scenes/cornell/floor.pts"))
ap.add_argument("--ref", help="reference for bench/score.py")
ap.add_argument("binaries", nargs="+")
args = ap.parse_args()

rays = pathlib.Path(args.points).read_bytes()
# Per position, so that one binary given twice is timed twice.
times = [[] for _ in args.binaries]
last = [b""] * len(args.binaries)
for _ in range(args.n):
    for k, b in enumerate(args.binaries):
        start = time.perf_counter()
        run = subprocess.run([b, *args.opts.split(), args.scene], input=rays,
                             stdout=subprocess.PIPE)
        if run.returncode != 0:
            sys.exit(f"ab_runs.py: {b} exited with status {run.returncode}")
        last[k] = run.stdout
        times[k].append(time.perf_counter() - start)
for k, b in enumerate(args.binaries):
    t = times[k]
    error = ""
    if args.ref:
        with tempfile.NamedTemporaryFile() as f:
            f.write(last[k])
            f.flush()
            error = ", " + subprocess.run([sys.executable, str(root / "bench/score.py"), args.ref,
                                           f.name], stdout=subprocess.PIPE, text=True,
                                          check=True).stdout.strip()
    print(f"{b}: min {1000 * min(t):.1f} ms, median {1000 * statistics.median(t):.1f} ms "
          f"over {len(t)} runs, output md5 {hashlib.md5(last[k]).hexdigest()}{error}")
