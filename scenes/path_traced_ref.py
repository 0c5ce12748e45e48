#!/usr/bin/env python3
# Converged irradiance with REAL Radiance 5.4a's rtrace (on PATH): the mean
# of N independent path-traced estimates per point (-I -ab B -aa 0 -ad 1 -as
# 0 -lw 1e-9 -u+), in chunks, as the scenes' references are made
# (scenes/README.md). Writes "r g b rel_stderr" per point (the standard error
# of the green mean over the mean). A developer's tool, called by the
# scenes' make_ref.sh; nothing in the build or tests runs it.
#   path_traced_ref.py OCTREE POINTS PATHS_PER_POINT OUT [BOUNCES]
import math
import subprocess
import sys
import time


def main():
    octree, points, n, out = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4]
    bounces = sys.argv[5] if len(sys.argv) > 5 else "2"
    # Radiance seeds -u+ from the clock in seconds: chunks must start in
    # different seconds, or they repeat each other's random numbers.
    chunk = 20000
    pts = [l for l in open(points).read().splitlines() if l.strip()]
    s = [[0.0] * 3 for _ in pts]
    s2 = [0.0] * len(pts)
    done = 0
    while done < n:
        k = min(chunk, n - done)
        start = time.time()
        inp = "".join((p + "\n") * k for p in pts)
        rows = subprocess.run(["rtrace", "-h", "-I", "-ab", bounces, "-aa", "0", "-ad", "1",
                               "-as", "0", "-lw", "1e-9", "-u+", octree], input=inp, text=True,
                              capture_output=True, check=True).stdout.split("\n")
        for i in range(len(pts)):
            for j in range(k):
                v = [float(x) for x in rows[i * k + j].split()]
                for c in range(3):
                    s[i][c] += v[c]
                s2[i] += v[1] * v[1]
        done += k
        time.sleep(max(0.0, 1.1 - (time.time() - start)))
    with open(out, "w") as f:
        for i in range(len(pts)):
            m = [x / n for x in s[i]]
            var = max(0.0, s2[i] / n - m[1] * m[1])
            f.write("%.6e %.6e %.6e %.4e\n" % (m[0], m[1], m[2], math.sqrt(var / n) / m[1]))


if __name__ == "__main__":
    main()
