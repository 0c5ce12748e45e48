#!/usr/bin/env bash
# Makes the mesh scene test data with REAL Radiance 5.4a (obj2mesh, oconv,
# rtrace, vwrays; a developer's tool: the tests only read what it writes).
# Run from anywhere: tests/data/meshscene/make_mesh_scenes.sh [RADIANCE_DIR]
# The tests run rtrace in this folder with RAYPATH=.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
rad=${1:-$here/../../../../shared/reference/radiance-5.4a}
export PATH=$rad/bin:$PATH RAYPATH=.:$rad/lib
cd "$here"

python3 make_vase.py
obj2mesh -a vase_mats.rad vase.obj vase.rtm
rm vase.obj  # the mesh is the test input; make_vase.py remakes the OBJ
oconv shelf.rad > shelf.oct
oconv room.rad > room.oct
oconv -f room.rad > room_frozen.oct
# A view, then rays down onto the vases from a tilted grid.
vwrays -x 48 -y 36 -vp 2 -5 3 -vd 0 1 -0.55 -vh 70 -vv 55 > room.rays
awk 'BEGIN { for (i = 0; i < 40; i++) for (j = 0; j < 40; j++) {
  x = -1 + 9 * i / 39; y = -1 + 8 * j / 39
  dx = 0.5 * sin(i * 1.7 + j); dy = 0.5 * cos(j * 2.3 + i); n = sqrt(dx * dx + dy * dy + 1)
  printf "%.4f %.4f 2.5 %.6f %.6f %.6f\n", x, y, dx / n, dy / n, -1 / n } }' >> room.rays
rtrace -h -ab 0 -ovlpnNsm room.oct < room.rays > room_ab0.txt
rtrace -h -ab 0 -ovlpnNsm room_frozen.oct < room.rays > room_frozen_ab0.txt
printf '%s\n' '1 -1 0.01 0 0 1' '3 -1 0.01 0 0 1' '1 2 0.01 0 0 1' '5 1 0.01 0 0 1' \
  '3 3.2 0.01 0 0 1' '7 0 0.01 0 0 1' > floor.pts
for i in 1 2 3 4 5 6 7 8; do
  rtrace -h -I -ab 1 -aa 0 -ad 8192 -as 0 -lw 1e-5 -u+ -ov room.oct < floor.pts
  sleep 1.1  # Radiance seeds -u+ from the clock in seconds
done | awk '{ j = NR % 6; s[j] += $1; s2[j] += $1 * $1; n[j]++ }
  END { for (k = 1; k <= 6; k++) { j = k % 6; m = s[j] / n[j]; v = s2[j] / n[j] - m * m
    # mean and its relative standard error
    printf "%.5f %.5f\n", m, sqrt((v > 0 ? v : 0) / (n[j] - 1)) / m } }' > room_floor_ab1.txt

# radiance-functions.md §13.6 item 5: the worked-example mesh placed three
# ways, with (u,v) from the mesh in a pattern.
cp ../mesh/tri.rtm ../mesh/mats.rad .
oconv tri_scene.rad > tri_scene.oct
printf '%s\n' '0.25 0.25 2 0 0 -1' '0.75 0.7 2 0 0 -1' '5.25 0.25 2 0 0 -1' '10.25 0.5 2 0 0 -1' \
  '0.5 0.2 2 0 0 -1' '0.25 0.25 -2 0 0 1' > tri_scene.rays
rtrace -h -ab 0 -ovnNLpsm tri_scene.oct < tri_scene.rays > tri_scene_ab0.txt
