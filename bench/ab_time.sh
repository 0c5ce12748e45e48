#!/usr/bin/env bash
# Wall time of two rtrace builds on the issue's cornell floor job, run
# alternately so that a noisy host slows both alike; prints the minimum and
# median per build, the MD5 of each build's last output and its error against
# the converged reference (which must agree when the output is meant unchanged).
# The timing itself is bench/ab_runs.py's.
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
exec bench/ab_runs.py -n "${3:-6}" \
  --opts="-h -I -ab 2 -ad 1024 -as 512 -aa .1 -ar 256 -n 1 ${RT_OPTS:-}" \
  --scene scenes/cornell/cornell.rad --points scenes/cornell/floor.pts \
  --ref scenes/cornell/ref/floor_I_ab2.txt "$a" "$b"
