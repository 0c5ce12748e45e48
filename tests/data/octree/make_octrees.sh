#!/usr/bin/env bash
# Makes the octree test data with REAL Radiance 5.4a (a developer's tool; the
# tests only read what it writes). Run from anywhere:
#   tests/data/octree/make_octrees.sh [RADIANCE_DIR]
# Octrees that name their scene files store the names as given, relative to
# this folder, so the tests run rtrace from here.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
rad=${1:-$here/../../../../shared/reference/radiance-5.4a}
export PATH=$rad/bin:$PATH RAYPATH=.:$rad/lib
cd "$here"
scenes=../../../scenes

oconv $scenes/cornell/cornell.rad > cornell.oct
oconv -f $scenes/cornell/cornell.rad > cornell_frozen.oct
oconv $scenes/daylit_room/daylit_room.rad > daylit_room.oct
oconv -f $scenes/daylit_room/daylit_room.rad > daylit_room_frozen.oct
# Curved surfaces, metal, glass, a trans screen and five kinds of source.
oconv -f $scenes/mixed/mixed.rad > mixed_frozen.oct
# oconv -i: the cornell box plus a lamp, added to an existing octree.
oconv -i cornell.oct lamp.rad > cornell_plus_lamp.oct
# A forced cube (oconv -b), larger than the scene: -ar must follow it. Frozen,
# so that it loads from any directory.
oconv -f -b -10 -10 -10 40 $scenes/cornell/cornell.rad > cornell_cube40.oct

rtrace -h -ab 0 -ovlpnNm cornell_frozen.oct < $scenes/cornell/cam32.rays > cornell_frozen_ab0.txt
rtrace -h -ab 0 -ovlpnNm daylit_room_frozen.oct < $scenes/daylit_room/cam32x24.rays \
  > daylit_room_frozen_ab0.txt
# mixed_room.rays: 400 rays from random points inside the mixed room, half in
# random directions and half aimed at its spheres, cylinders, rings and cone
# (kept as data; made once with Python's random.Random(7)). -dt 0 as below,
# and -ss 0: rough metal samples its specular lobe at random.
rtrace -h -ab 0 -dt 0 -ss 0 -ovlpnNm mixed_frozen.oct < mixed_room.rays > mixed_frozen_ab0.txt
# -dt 0: with two sources, -dt's estimates depend on the shadow statistics of
# earlier rays, which Radiance's obstructor cache changes (README, Differences).
rtrace -h -ab 0 -dt 0 -ovlpnNm cornell_plus_lamp.oct < $scenes/cornell/cam32.rays \
  > cornell_plus_lamp_ab0.txt

# A stale octree: made from a two-object stale.rad, which then gains a third.
printf 'void plastic grey 0 0 5 .5 .5 .5 0 0\ngrey sphere ball 0 0 4 0 0 0 1\n' > stale.rad
oconv stale.rad > stale.oct
printf 'grey sphere ball2 0 0 4 3 0 0 1\n' >> stale.rad
{ echo "0 0 5 0 0 -1" | rtrace -h stale.oct || true; } > stale_radiance.txt 2>&1
# Stale, and the new object names an undefined modifier: Radiance reports the
# scene file's error, met while reading it, before it counts the objects.
printf 'void plastic grey 0 0 5 .5 .5 .5 0 0\ngrey sphere ball 0 0 4 0 0 0 1\n' > stale_undefined.rad
oconv stale_undefined.rad > stale_undefined.oct
printf 'nosuch sphere ball2 0 0 4 3 0 0 1\n' >> stale_undefined.rad
{ echo "0 0 5 0 0 -1" | rtrace -h stale_undefined.oct || true; } > stale_undefined_radiance.txt 2>&1
