#!/usr/bin/env bash
# A large model, side by side with real Radiance 5.4a (../shared/tools/side-by-side):
# the open-plan office of bench/make_office.py (about 110 000 polygons, every
# chair, plant and blind slat a plain polygon) under gensky's sunny sky, in a
# frozen octree (oconv -f, as honeybee-radiance makes them). Three jobs:
#   start-up  no rays at all: reading the octree and building the ray core
#   direct    -ab 0 on 40 work-plane points: mostly start-up
#   chunk     honeybee's daylight-factor settings (-ab 2 -aa .1 -ad 2048
#             -ar 64) on 40 points, the size of the chunks honeybee splits a
#             grid into for parallel processes
#
#   bench/big_scene.sh LAZYRAD_RTRACE [PAIRS]
#
# The sky and the octree are made with real Radiance's gensky and oconv (a
# benchmark may use them; the build and the tests never do). No reference
# exists for this scene: the errors are not compared.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
lz=$(realpath "${1:?usage: big_scene.sh LAZYRAD_RTRACE [PAIRS]}")
pairs=${2:-3}
rad=$root/../shared/reference/radiance-5.4a
sbs=$root/../shared/tools/side-by-side
[ -x "$sbs" ] || { echo "big_scene.sh: $sbs not found (needs ../shared)" >&2; exit 2; }
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
cd "$tmp"
python3 "$root/bench/make_office.py" > office.rad
{
  "$rad/bin/gensky" 3 21 12 -a 52 -o 0 -m 0 +s
  printf 'skyfunc glow skyglow 0 0 4 1 1 1 0\nskyglow source sky 0 0 4 0 0 1 180\n'
  printf 'skyfunc glow groundglow 0 0 4 1 1 1 0\ngroundglow source ground 0 0 4 0 0 -1 180\n'
} > sky.rad
RAYPATH=.:$rad/lib "$rad/bin/oconv" -f sky.rad office.rad > office.oct 2> /dev/null
# The first 40 points (sed reads to the end: head would close the pipe early and
# stop the script under pipefail when awk is still writing).
awk 'BEGIN { for (i = 0; i < 26; i++) for (j = 0; j < 15; j++)
  printf "%.2f %.2f 0.8 0 0 1\n", 0.8 + 1.5 * i, 1.0 + 1.5 * j }' | sed -n 1,40p > chunk.pts
: > none.pts
echo "office: $(grep -c ' polygon ' office.rad) polygons, frozen octree $(stat -c %s office.oct) bytes"
run() {  # description options points
  echo "== $1 ($2)"
  RAYPATH=.:$rad/lib "$sbs" -n "$pairs" "$lz" "$2 -w" office.oct "$3" | tail -1
}
run "start-up: no rays" "-h -I -ab 0" none.pts
run "direct: 40 points" "-h -I -ab 0" chunk.pts
run "chunk: 40 points, honeybee daylight factor" "-h -I -ab 2 -aa .1 -ad 2048 -ar 64" chunk.pts
