#!/usr/bin/env bash
# A mesh-heavy job (issue 15): a 12 x 8 m room with 200 chairs, each a
# ~1200-triangle mesh placed by a `mesh` primitive, lit by ceiling panels;
# -I -ab 2 at Radiance's default ambient settings on a work-plane grid, side by
# side with real Radiance (../shared/tools/side-by-side), followed by the
# cornell floor job in the same run for comparison of the two speed-ups.
#   bench/mesh_room.sh LAZYRAD_RTRACE [PAIRS]
# The chair mesh is made with real Radiance's obj2mesh (a benchmark may use
# it; the build and the tests never do).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
lz=$(realpath "${1:?usage: mesh_room.sh LAZYRAD_RTRACE [PAIRS]}")
pairs=${2:-3}
rad=$root/../shared/reference/radiance-5.4a
sbs=$root/../shared/tools/side-by-side
opts="-h -I -ab 2 -ad 1024 -as 512 -aa .1 -ar 256"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
cd "$tmp"
python3 "$root/bench/make_chair.py" > chair.obj
printf 'void plastic seat 0 0 5 .5 .3 .2 0 0\nvoid metal frame 0 0 5 .6 .6 .6 .8 .05\n' > chair_mats.rad
"$rad/bin/obj2mesh" -a chair_mats.rad chair.obj chair.rtm
{
  echo 'void plastic wall 0 0 5 .6 .6 .6 0 0'
  echo 'void light panel 0 0 3 50 50 50'
  "$rad/bin/genbox" wall room 12 8 3 -i
  for x in 2 6 10; do for y in 2 6; do
    echo "panel polygon p$x.$y 0 0 12 $((x - 1)) $((y - 1)) 2.99  $((x - 1)) $((y + 1)) 2.99  $((x + 1)) $((y + 1)) 2.99  $((x + 1)) $((y - 1)) 2.99"
  done; done
  awk 'BEGIN { for (i = 0; i < 200; i++) {
    x = 0.6 + (i % 20) * 0.55; y = 0.5 + int(i / 20) * 0.72; a = (i * 37) % 360
    printf "void mesh chair%d 7 chair.rtm -rz %d -t %.2f %.2f 0 0 0\n", i, a, x, y } }'
} > room.rad
awk 'BEGIN { for (i = 0; i < 12; i++) for (j = 0; j < 8; j++) printf "%.2f %.2f 0.8 0 0 1\n", 0.5 + i, 0.5 + j }' > grid.pts
echo "== mesh room: 200 chair meshes, 96 points ($opts)"
RAYPATH=.:$rad/lib "$sbs" -n "$pairs" "$lz" "$opts" room.rad grid.pts | tail -1
echo "== cornell floor ($opts)"
"$sbs" -n "$pairs" "$lz" "$opts" "$root/scenes/cornell/cornell.rad" "$root/scenes/cornell/floor.pts" | tail -1
