#!/usr/bin/env bash
# Are two reference files (columns "r g b rel_stderr", as scenes/*/ref/) the same
# quantity within their combined standard errors?
#
#   bench/refcheck.sh A.txt B.txt
#
# Per line, on luminance Y = 0.265 R + 0.670 G + 0.065 B (scenes/README.md):
#   z = (Y_A - Y_B) / sqrt((s_A Y_A)^2 + (s_B Y_B)^2)
# where s is the file's rel_stderr (the green channel's, used for luminance;
# green carries 67 % of it and the channels are strongly correlated).
# Prints chi^2 = sum z^2 with its degrees of freedom (= lines) and upper-tail
# p-value (Wilson-Hilferty), mean z (a bias shows as |mean z| >> 1/sqrt(n)),
# max |z| and the count beyond 3. Exit status 1 when p < 0.001 or max |z| > 5.
set -euo pipefail
[ $# -eq 2 ] || { sed -n '2,13p' "$0" >&2; exit 2; }
paste "$1" "$2" | awk '
  function erfc(x,   t, y) {  # Abramowitz & Stegun 7.1.26, |error| < 1.5e-7, x >= 0
    t = 1 / (1 + 0.3275911 * x)
    y = t * (0.254829592 + t * (-0.284496736 + t * (1.421413741 + t * (-1.453152027 + t * 1.061405429))))
    return y * exp(-x * x)
  }
  {
    a = 0.265074126*$1 + 0.670114631*$2 + 0.064811243*$3
    b = 0.265074126*$5 + 0.670114631*$6 + 0.064811243*$7
    se = sqrt(($4*a)^2 + ($8*b)^2)
    z = se > 0 ? (a - b) / se : 0
    n++; chi += z*z; sz += z; d = (a - b) / b; rel += d*d
    if (z*z > mz*mz) mz = z
    if (z > 3 || z < -3) out++
  }
  END {
    k = n; w = ((chi / k)^(1/3) - (1 - 2/(9*k))) / sqrt(2/(9*k))
    p = w > 0 ? 0.5 * erfc(w / sqrt(2)) : 1 - 0.5 * erfc(-w / sqrt(2))
    printf "lines %d  chi2 %.1f / %d dof (chi2/dof %.3f, p = %.3g)  mean z %+.3f (1/sqrt(n) = %.3f)  max |z| %.2f  |z|>3: %d  RMS rel diff %.3f%%\n",
           n, chi, k, chi / k, p, sz / n, 1 / sqrt(n), (mz < 0 ? -mz : mz), out + 0, 100 * sqrt(rel / n)
    exit (p < 0.001 || mz > 5 || mz < -5) ? 1 : 0
  }'
