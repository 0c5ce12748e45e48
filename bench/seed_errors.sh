#!/usr/bin/env bash
# Mean RMS error and CPU time of one job over several seeds, for comparing two
# builds on the same seeds (one seed is one draw of the Monte Carlo error).
#
#   bench/seed_errors.sh RTRACE JOB "SEEDS" [EXTRA OPTIONS...]
#     JOB  floor edges fast daylit shelf df dense dense_tool
#
# Prints one line: the job, the mean of bench/score.py's RMS error (the raw
# figure, reference noise included), each seed's error, the mean bias over the
# seeds with its standard error, the mean user CPU seconds and the records per
# level of each run (rtrace -t summary). EXTRA OPTIONS come after the job's
# own, so they override them (-aa .2 replaces the job's -aa).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
lz=${1:?usage: seed_errors.sh RTRACE JOB "SEEDS" [OPTIONS...]}
job=${2:?job}
seeds=${3:?seeds}
shift 3
S=$root/scenes
defaults="-ad 1024 -as 512 -aa .1 -ar 256"
case $job in
  floor) o="-I -ab 2 $defaults"; scene=$S/cornell/cornell.rad; pts=$S/cornell/floor.pts; ref=$S/cornell/ref/floor_I_ab2.txt ;;
  edges) o="-I -ab 2 $defaults"; scene=$S/cornell/cornell.rad; pts=$S/cornell/edges.pts; ref=$S/cornell/ref/edges_I_ab2.txt ;;
  fast) o="-I -ab 2 -ad 256 -as 128 -aa .2 -ar 64"; scene=$S/cornell/cornell.rad; pts=$S/cornell/floor.pts; ref=$S/cornell/ref/floor_I_ab2.txt ;;
  daylit) o="-I -ab 4 $defaults"; scene=$S/daylit_room/daylit_room.rad; pts=$S/daylit_room/workplane.pts; ref=$S/daylit_room/ref/workplane_I_ab4.txt ;;
  shelf) o="-I -ab 4 $defaults"; scene=$S/shelf_room/shelf_room.rad; pts=$S/daylit_room/workplane.pts; ref=$S/shelf_room/ref/workplane_I_ab4.txt ;;
  df) o="-I -ab 2 -aa .1 -ad 2048 -ar 64"; scene=$S/df_room/df_room.oct; pts=$S/df_room/grid.pts; ref=$S/df_room/ref/grid_I_ab2.txt ;;
  dense) o="-I -ab 2 $defaults"; scene=$S/cornell/cornell.rad; pts=$S/cornell/floor_dense.pts; ref=$S/cornell/ref/floor_dense_I_ab2.txt ;;
  dense_tool) o="-I -ab 2 -aa .1 -ad 2048 -ar 64"; scene=$S/cornell/cornell.rad; pts=$S/cornell/floor_dense.pts; ref=$S/cornell/ref/floor_dense_I_ab2.txt ;;
  *) echo "seed_errors.sh: unknown job '$job'" >&2; exit 2 ;;
esac
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
errors="" cpus="" records="" biases=""
for s in $seeds; do
  # shellcheck disable=SC2086
  /usr/bin/time -f %U -o "$tmp/t" "$lz" -seed "$s" -t 1000000 -h $o "$@" "$scene" < "$pts" > "$tmp/out" 2> "$tmp/err"
  score=$(python3 "$root/bench/score.py" "$ref" "$tmp/out" | tail -1)
  e=$(sed -n 's/^rms \([0-9.]*\)%.*/\1/p' <<< "$score")
  biases="$biases $(sed -n 's/.*bias \([-+0-9.]*\)%.*/\1/p' <<< "$score")"
  errors="$errors $e"; cpus="$cpus $(tail -1 "$tmp/t")"
  records="$records $(sed -n 's/.*records per level \([0-9/]*\).*/\1/p' "$tmp/err" | tail -1)"
done
python3 - "$job" "$errors" "$cpus" "$records" "$biases" <<'PY'
import sys, statistics as st
job, errors, cpus, records = sys.argv[1], sys.argv[2].split(), sys.argv[3].split(), sys.argv[4]
e = [float(x) for x in errors]
b = [float(x) for x in sys.argv[5].split()]
sem = st.stdev(b) / len(b) ** 0.5 if len(b) > 1 else 0.0
print(f"{job}: rms mean {st.mean(e):.3f} % ({' '.join(errors)}) bias mean {st.mean(b):+.2f} % "
      f"(± {sem:.2f}) cpu mean {st.mean(float(c) for c in cpus):.2f} s, records{records}")
PY
