#!/usr/bin/env python3
"""Per-point bias and spread of several runs of one job (e.g. one per seed).

    bench/point_bias.py [--top N] REFERENCE POINTS OUTPUT...

REFERENCE: the converged reference (bench/reference.sh; first three columns
RGB). POINTS: the job's input rays (for printing positions). OUTPUT: each
run's rtrace output, one RGB triple per line, in the points' order.

Prints, over the runs: the mean of each run's RMS error (as bench/score.py
computes it, luminance against the reference), the RMS over points of each
point's mean relative error (its bias) and of its standard deviation (its
noise), then the N points with the largest |bias|. A bias is told from noise
by its standard error, spread / sqrt(runs).
"""
import argparse
import math
import sys

from values import luminance, read_rows


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--top", type=int, default=6)
    ap.add_argument("reference")
    ap.add_argument("points")
    ap.add_argument("outputs", nargs="+")
    args = ap.parse_args()
    ref = [luminance(r[:3]) for r in read_rows(args.reference)]
    points = read_rows(args.points)
    # Points the reference gives no light are left out, as bench/score.py does.
    lit = [i for i, r in enumerate(ref) if r > 1e-9]
    runs = []
    for path in args.outputs:
        out = [luminance(r[:3]) for r in read_rows(path)]
        if len(out) != len(ref):
            sys.exit(f"point_bias.py: {path}: {len(out)} values, the reference has {len(ref)}")
        runs.append([out[i] / ref[i] - 1 for i in lit])
    points = [points[i] for i in lit]
    n = len(lit)
    k = len(runs)
    bias = [sum(r[i] for r in runs) / k for i in range(n)]
    spread = [math.sqrt(sum((r[i] - bias[i]) ** 2 for r in runs) / max(1, k - 1)) for i in range(n)]
    rms = sum(math.sqrt(sum(x * x for x in r) / n) for r in runs) / k
    print(f"{k} runs, {n} points: mean RMS {100 * rms:.3f} %, "
          f"RMS of point biases {100 * math.sqrt(sum(b * b for b in bias) / n):.3f} %, "
          f"RMS of point spreads {100 * math.sqrt(sum(s * s for s in spread) / n):.3f} %")
    for i in sorted(range(n), key=lambda i: -abs(bias[i]))[: args.top]:
        where = " ".join(f"{x:g}" for x in points[i][:3])
        print(f"  point {lit[i]} ({where}): bias {100 * bias[i]:+.2f} % "
              f"± {100 * spread[i] / math.sqrt(k):.2f}, spread {100 * spread[i]:.2f} %")


if __name__ == "__main__":
    main()
