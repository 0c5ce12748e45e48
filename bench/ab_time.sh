#!/usr/bin/env bash
# Wall time of two rtrace builds on the issue's cornell floor job, run
# alternately so that a noisy host slows both alike; prints each run and the
# minimum and median per build, and the error of the last run against the
# converged reference (which must agree when the output is meant unchanged).
#
#   bench/ab_time.sh RTRACE_A RTRACE_B [PAIRS]      (default 6 pairs)
#   e.g. bench/ab_time.sh build/bin/rtrace /tmp/old/bin/rtrace
#
# The job: rtrace -h -I -ab 2 -ad 1024 -as 512 -aa .1 -ar 256 -n 1 on
# scenes/cornell/floor.pts; extra rtrace options in RT_OPTS (e.g. "-seed 2").
set -euo pipefail
cd "$(dirname "$0")/.."
a=${1:?usage: ab_time.sh RTRACE_A RTRACE_B [PAIRS]}
b=${2:?usage: ab_time.sh RTRACE_A RTRACE_B [PAIRS]}
pairs=${3:-6}
opts=(-h -I -ab 2 -ad 1024 -as 512 -aa .1 -ar 256 -n 1 ${RT_OPTS:-})
out=$(mktemp); trap 'rm -f "$out"' EXIT

# error FILE: luminance RMS and max against the reference, as scenes/README.md.
error() {
  paste "$1" scenes/cornell/ref/floor_I_ab2.txt | awk '{
      g = 0.265074126*$1 + 0.670114631*$2 + 0.064811243*$3
      r = 0.265074126*$4 + 0.670114631*$5 + 0.064811243*$6
      d = (g - r) / r; s += d*d; n++; if (d < 0) d = -d; if (d > m) m = d }
    END { printf "%.2f%% RMS, %.2f%% max", 100*sqrt(s/n), 100*m }'
}

declare -A times
for ((i = 0; i < pairs; i++)); do
  for which in A B; do
    bin=$([ "$which" = A ] && echo "$a" || echo "$b")
    start=$(date +%s.%N)
    "$bin" "${opts[@]}" scenes/cornell/cornell_src.rad < scenes/cornell/floor.pts > "$out"
    end=$(date +%s.%N)
    t=$(awk -v s="$start" -v e="$end" 'BEGIN { printf "%.2f", e - s }')
    times[$which]="${times[$which]:-} $t"
    echo "$which $t s  $(error "$out")"
  done
done
for which in A B; do
  echo "$which:${times[$which]}" | tr ' ' '\n' | tail -n +2 | sort -n | awk -v w="$which" '
    { v[NR] = $1 } END { m = (NR % 2) ? v[(NR+1)/2] : (v[NR/2] + v[NR/2+1]) / 2
                         printf "%s: min %.2f s, median %.2f s over %d runs\n", w, v[1], m, NR }'
done
