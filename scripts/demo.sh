#!/usr/bin/env bash
# The main job on the default scene, on a fresh machine: installs what is
# missing, builds (Release), then computes the irradiance at the Cornell box
# floor sensors the way a lighting engineer runs rtrace, and prints a table
# with the error against real Radiance's converged reference.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh release >/dev/null

scene=scenes/cornell/cornell_src.rad
points=scenes/cornell/floor.pts
ref=scenes/cornell/ref/floor_I_ab2.txt
opts=(-h -I -ab 2 -ad 1024 -as 512 -aa .1 -ar 256 -t 60)
echo "lazyrad: build/bin/rtrace ${opts[*]} $scene < $points"
out=$(mktemp); trap 'rm -f "$out"' EXIT
start=$(date +%s.%N)
build/bin/rtrace "${opts[@]}" "$scene" < "$points" > "$out"
end=$(date +%s.%N)
# Irradiance in W/m² per channel; illuminance = 179 lm/W × luminance weights.
paste "$points" "$out" "$ref" | awk '
  function lum(r, g, b) { return 0.265074126*r + 0.670114631*g + 0.064811243*b }
  BEGIN { printf "%7s %7s %12s %10s %10s\n", "x (m)", "y (m)", "E (W/m2)", "lux", "vs ref" }
  { e = lum($7, $8, $9); r = lum($10, $11, $12); d = (e - r) / r
    s += d*d; if ((d < 0 ? -d : d) > m) m = (d < 0 ? -d : d); n++; sum += 179*e
    if (n <= 10 || n % 10 == 0) printf "%7.3f %7.3f %12.4f %10.1f %9.2f%%\n", $1, $2, e, 179*e, 100*d }
  END { printf "%d sensors, mean %.1f lux; against real Radiance'"'"'s converged reference: %.2f%% RMS, %.2f%% max\n",
               n, sum/n, 100*sqrt(s/n), 100*m }'
awk -v s="$start" -v e="$end" 'BEGIN { printf "wall time %.2f s\n", e - s }'
