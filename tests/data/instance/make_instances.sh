#!/usr/bin/env bash
# Makes the instance test data with REAL Radiance 5.4a (a developer's tool; the
# tests only read what it writes). Run from anywhere:
#   tests/data/instance/make_instances.sh [RADIANCE_DIR]
# The tests run rtrace in this folder with RAYPATH=. (octrees, .cal files and
# the scene files of non-frozen octrees are found relative to it).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
rad=${1:-$here/../../../../shared/reference/radiance-5.4a}
export PATH=$rad/bin:$PATH RAYPATH=.:$rad/lib
cd "$here"

# radiance-functions.md §13.6: a unit-square light whose colour is its point,
# placed twice: with a void modifier (its own material, pattern in instance
# coordinates) and with an overriding modifier.
oconv square.rad > square.oct
oconv -f square.rad > square_frozen.oct
oconv two_squares.rad > two_squares.oct
printf '%s\n' '11 1 5 0 0 -1' '0.5 10.5 5 0 0 -1' '11 1 -5 0 0 1' '13 3 5 0 0 -1' \
  '10.2 0.3 1 0 0 -1' '21 1 5 0 0 -1' '31 1 5 0 0 -1' '30.5 1.5 2 0.6 0 -0.8' > two_squares.rays
rtrace -h -ab 0 -ovnNLpsmM two_squares.oct < two_squares.rays > two_squares_ab0.txt
oconv two_squares_frozen.rad > two_squares_frozen.oct
rtrace -h -ab 0 -ovnNLpsmM two_squares_frozen.oct < two_squares.rays > two_squares_frozen_ab0.txt

# Nested instances: chairs in a row, rows in a room, with rotation, uniform
# scale, a mirror, an overriding modifier at each level, patterns and every
# surface kind. Frozen and named octrees both.
oconv chair.rad > chair.oct
oconv row.rad > row.oct
oconv -f room.rad > room_frozen.oct
oconv room.rad > room.oct
# A view of the room, then rays down onto the chairs from a tilted grid.
vwrays -x 48 -y 36 -vp 3 -8 3.5 -vd 0 1 -0.6 -vh 65 -vv 50 > room.rays
awk 'BEGIN { for (i = 0; i < 50; i++) for (j = 0; j < 50; j++) {
  x = -4 + 14 * i / 49; y = -6 + 14 * j / 49
  dx = 0.35 * sin(i * 1.7 + j); dy = 0.35 * cos(j * 2.3 + i); n = sqrt(dx * dx + dy * dy + 1)
  printf "%.4f %.4f 2.2 %.6f %.6f %.6f\n", x, y, dx / n, dy / n, -1 / n } }' >> room.rays
rtrace -h -ab 0 -ovlpnNsm room.oct < room.rays > room_ab0.txt
rtrace -h -ab 0 -ovlpnNsm room_frozen.oct < room.rays > room_frozen_ab0.txt
# -ab 1 irradiance on the floor between the chairs, converged: many
# hemisphere rays, no interpolation, averaged over repeats.
printf '%s\n' '1 -2 0.01 0 0 1' '3 -1 0.01 0 0 1' '5 -3 0.01 0 0 1' '2 2 0.01 0 0 1' \
  '6 1 0.01 0 0 1' '-1 3 0.01 0 0 1' > floor.pts
for i in 1 2 3 4 5 6 7 8; do
  rtrace -h -I -ab 1 -aa 0 -ad 8192 -as 0 -lw 1e-5 -u+ -ov room.oct < floor.pts
  sleep 1.1  # Radiance seeds -u+ from the clock in seconds
done | awk '{ j = NR % 6; s[j] += $1; s2[j] += $1 * $1; n[j]++ }
  END { for (k = 1; k <= 6; k++) { j = k % 6; m = s[j] / n[j]; v = s2[j] / n[j] - m * m
    # mean and its relative standard error
    printf "%.5f %.5f\n", m, sqrt((v > 0 ? v : 0) / (n[j] - 1)) / m } }' > room_floor_ab1.txt

# radiance-functions.md §13.6 item 4: a lamp inside an instance lights nothing.
oconv lamp.rad > lamp.oct
printf '1 1 1 0 0 -1\n0 0 5 0 0 -1\n' > lamp_scene.rays
oconv lamp_scene.rad > lamp_scene.oct
rtrace -h -ab 0 -ov lamp_scene.oct < lamp_scene.rays > lamp_scene_ab0.txt 2> lamp_scene_ab0.err
echo '1 1 0 0 0 1' | rtrace -h -I -ab 1 -ov lamp_scene.oct > lamp_scene_ab1.txt 2>/dev/null

# The cube of two instances of the unit square (radiance-functions.md §13.1).
oconv two_placed.rad > two_placed.oct

# An octree whose scene instances that octree itself.
cp square.oct self.oct
oconv self.rad > self.oct.new
mv self.oct.new self.oct
