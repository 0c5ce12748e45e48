#!/usr/bin/env bash
# The main job on the default scene, on a fresh machine: installs what is
# missing, builds (Release), then computes the irradiance at the Cornell box
# floor sensors the way a lighting engineer runs rtrace, and prints a table.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh release >/dev/null

scene=scenes/cornell/cornell_src.rad
points=scenes/cornell/floor.pts
opts=(-h -I -ab 0)
echo "lazyrad: build/bin/rtrace ${opts[*]} $scene < $points"
start=$(date +%s.%N)
build/bin/rtrace "${opts[@]}" "$scene" < "$points" > /tmp/lazyrad-demo.$$
end=$(date +%s.%N)
# Irradiance in W/m² per channel; illuminance = 179 lm/W × luminance weights.
paste "$points" /tmp/lazyrad-demo.$$ | awk '
  BEGIN { printf "%8s %8s %12s %12s\n", "x (m)", "y (m)", "E (W/m2)", "lux" }
  { e = 0.265074126*$7 + 0.670114631*$8 + 0.064811243*$9
    sum += 179*e; n++
    if (n <= 12 || n % 12 == 0) printf "%8.3f %8.3f %12.4f %12.1f\n", $1, $2, e, 179*e }
  END { printf "%d sensors, mean illuminance %.1f lux (direct light only: -ab 0)\n", n, sum/n }'
rm -f /tmp/lazyrad-demo.$$
awk -v s="$start" -v e="$end" 'BEGIN { printf "wall time %.3f s\n", e - s }'
