#!/usr/bin/env bash
# The main job on the default scene, on a fresh machine: installs what is
# missing, builds (Release, profile-guided: scripts/build.sh), then runs a
# daylight-factor calculation the way honeybee runs it - rtrace on a frozen
# octree (made by Radiance's oconv from a gensky CIE overcast sky and a room
# with a window), 96 work-plane sensors - and prints each sensor's daylight
# factor with its error against real Radiance's converged reference.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh release >/dev/null

octree=scenes/df_room/df_room.oct
points=scenes/df_room/grid.pts
ref=scenes/df_room/ref/grid_I_ab2.txt
opts=(-h -I -aa .1 -ab 2 -ad 2048 -ar 64)
echo "lazyrad: build/bin/rtrace ${opts[*]} $octree < $points"
out=$(mktemp); trap 'rm -f "$out"' EXIT
start=$(date +%s.%N)
build/bin/rtrace "${opts[@]}" "$octree" < "$points" > "$out"
end=$(date +%s.%N)
# Irradiance in W/m² per channel; illuminance = 179 lm/W × luminance. The sky
# gives 100 000 lux on an unobstructed horizontal plane (gensky -B 558.659), so
# the daylight factor is illuminance / 1000 per cent.
paste "$points" "$out" "$ref" | awk '
  function lum(r, g, b) { return 0.265074126*r + 0.670114631*g + 0.064811243*b }
  BEGIN { printf "%7s %7s %10s %8s %10s\n", "x (m)", "y (m)", "lux", "DF (%)", "vs ref" }
  { e = lum($7, $8, $9); r = lum($10, $11, $12); d = (e - r) / r
    s += d*d; if ((d < 0 ? -d : d) > m) m = (d < 0 ? -d : d); n++; sum += 179*e
    if (n <= 8 || n % 12 == 0) printf "%7.2f %7.2f %10.1f %8.2f %9.2f%%\n", $1, $2, 179*e, 179*e/1000, 100*d }
  END { printf "%d sensors, mean %.1f lux (daylight factor %.2f %%); against real Radiance'"'"'s converged reference: %.2f%% RMS, %.2f%% max\n",
               n, sum/n, sum/n/1000, 100*sqrt(s/n), 100*m }'
awk -v s="$start" -v e="$end" 'BEGIN { printf "wall time %.2f s\n", e - s }'
