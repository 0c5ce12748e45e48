#!/usr/bin/env python3
"""Luminance error of an rtrace output against a reference (scenes/README.md):
  bench/score.py REF OUT  ->  "rms A% (B% less the reference's noise) max C% bias D%"
REF lines are "r g b [rel_stderr]"; the noise-corrected RMS is sqrt(rms² - s²),
s the RMS of the reference's relative standard errors (0 when absent), the
part of the measured error that is the program's own."""
import math
import sys

lum = lambda v: 0.265 * v[0] + 0.670 * v[1] + 0.065 * v[2]
ref = [[float(x) for x in l.split()] for l in open(sys.argv[1]) if l.strip()]
out = [[float(x) for x in l.split()[:3]] for l in open(sys.argv[2])
       if l.strip() and not l.startswith('#')]
if len(ref) != len(out):
    sys.exit(f"score: {len(out)} values for {len(ref)} reference lines")
pairs = [(r, o) for r, o in zip(ref, out) if lum(r[:3]) > 1e-9]
e = [(lum(o) - lum(r[:3])) / lum(r[:3]) for r, o in pairs]
s = [r[3] if len(r) > 3 else 0.0 for r, _ in pairs]
rms = math.sqrt(sum(x * x for x in e) / len(e))
noise = math.sqrt(sum(x * x for x in s) / len(s))
own = math.sqrt(max(0.0, rms * rms - noise * noise))
print(f"rms {100 * rms:.2f}% ({100 * own:.2f}% less the reference's noise) "
      f"max {100 * max(abs(x) for x in e):.2f}% bias {100 * sum(e) / len(e):+.2f}%")
