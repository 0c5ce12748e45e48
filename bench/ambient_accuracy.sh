#!/usr/bin/env bash
# Errors and wall times of the indirect calculation against analytic answers
# and real-Radiance references (issue "Ambient calculation"). Rerun with:
#   bench/ambient_accuracy.sh [path/to/rtrace]
#   SEEDS="0 1 2 3 4 5 6 7" bench/ambient_accuracy.sh   # the spread over seeds
# Error = relative error of luminance (0.265 R + 0.670 G + 0.065 B), as
# scenes/README.md defines it; times are wall clock of one rtrace process.
set -euo pipefail
cd "$(dirname "$0")/.."
rtrace=${1:-build/bin/rtrace}
[ -x "$rtrace" ] || { echo "ambient_accuracy: build first (scripts/build.sh release)" >&2; exit 1; }

now() { date +%s.%N; }

# compare OUTPUT REFERENCE: prints "rms% max%" over luminance.
compare() {
  paste "$1" "$2" | awk '{
      got = 0.265074126*$1 + 0.670114631*$2 + 0.064811243*$3
      ref = 0.265074126*$4 + 0.670114631*$5 + 0.064811243*$6
      e = (got - ref) / ref; s += e*e; n++; if (e < 0) e = -e; if (e > m) m = e }
    END { printf "%.2f%% RMS, %.2f%% max (%d points)", 100*sqrt(s/n), 100*m, n }'
}

# analytic OUTPUT EXPECTED: prints the largest relative deviation from a constant.
analytic() {
  awk -v want="$2" '{ for (i = 1; i <= 3; i++) { e = ($i - want) / want; if (e < 0) e = -e; if (e > m) m = e } }
    END { printf "max %.4f%% from %.6g", 100*m, want }' "$1"
}

out=$(mktemp); trap 'rm -f "$out"' EXIT

echo "== furnace (rho 0.5, -av 1 1 1 -aw 0): radiance rho^(n+1), -I pi rho^n"
for cache in "-aa .1" "-aa 0"; do
  for n in 0 1 2 3 4 5; do
    "$rtrace" -h -w -ab $n $cache -av 1 1 1 -aw 0 scenes/furnace/furnace.rad < scenes/furnace/rays.txt > "$out"
    rad=$(analytic "$out" "$(awk -v n=$n 'BEGIN { print 0.5^(n+1) }')")
    "$rtrace" -h -w -I -ab $n $cache -av 1 1 1 -aw 0 scenes/furnace/furnace.rad < scenes/furnace/points.txt > "$out"
    irr=$(analytic "$out" "$(awk -v n=$n 'BEGIN { print 3.14159265358979*0.5^n }')")
    echo "  $cache -ab $n: rays $rad; -I $irr"
  done
done

echo "== skyplane: -I above the ground is pi"
for n in 1 2 3; do
  "$rtrace" -h -w -I -ab $n scenes/skyplane/skyplane.rad < scenes/skyplane/points.txt > "$out"
  echo "  -ab $n: $(analytic "$out" 3.14159265358979)"
done

run() {  # run LABEL SCENE POINTS REF OPTIONS...
  local label=$1 scene=$2 points=$3 ref=$4; shift 4
  local t0 t1
  t0=$(now); "$rtrace" -h -w "$@" "$scene" < "$points" > "$out"; t1=$(now)
  printf "  %-28s %s, %.2f s  (rtrace %s)\n" "$label" "$(compare "$out" "$ref")" \
    "$(awk -v a="$t0" -v b="$t1" 'BEGIN { print b - a }')" "$*"
}

settings=(-I -ad 1024 -as 512 -aa .1 -ar 256)
# One seed is one draw of the Monte Carlo error: SEEDS="0 1 2 3" repeats every
# case with each -seed (default: the default seed 0 only).
for seed in ${SEEDS:-0}; do
  echo "== against converged references (scenes/*/ref), -seed $seed"
  run "cornell floor -ab 2" scenes/cornell/cornell.rad scenes/cornell/floor.pts \
      scenes/cornell/ref/floor_I_ab2.txt -ab 2 "${settings[@]}" -seed "$seed"
  run "cornell edges -ab 2" scenes/cornell/cornell.rad scenes/cornell/edges.pts \
      scenes/cornell/ref/edges_I_ab2.txt -ab 2 "${settings[@]}" -seed "$seed"
  run "daylit_room workplane -ab 4" scenes/daylit_room/daylit_room.rad scenes/daylit_room/workplane.pts \
      scenes/daylit_room/ref/workplane_I_ab4.txt -ab 4 "${settings[@]}" -seed "$seed"
done
