#!/usr/bin/env bash
# Makes the reference outputs of tests/golden/virtual_source_test.cpp with
# real Radiance 5.4a (a developer's tool; the tests only read its output).
# -ab 0 -dj 0 -dt 0: deterministic direct light, so that the two programs'
# outputs agree to the printed digits.
#
#   tests/data/virtual/make_references.sh [RADIANCE_FOLDER]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
rad=${1:-$here/../../../../shared/reference/radiance-5.4a}
export RAYPATH=$here:$rad/lib  # mirror_instance.rad finds mirror_ceiling.oct here
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
cd "$here"
"$rad/bin/oconv" mirror_ceiling.rad > mirror_ceiling.oct
run() {  # output scene options... < input
  local out=$1 scene=$2; shift 2
  "$rad/bin/oconv" "$scene.rad" > "$tmp/$scene.oct"
  "$rad/bin/rtrace" -h -ab 0 -dj 0 -dt 0 "$@" "$tmp/$scene.oct" > "$out" 2> "$tmp/err"
  [ ! -s "$tmp/err" ] || { cat "$tmp/err" >&2; exit 1; }
}
run lamp_ceiling_dr0.txt lamp_ceiling -I -dr 0 < room.pts
run lamp_ceiling_dr2.txt lamp_ceiling -I -dr 2 < room.pts
run shelf_dr2.txt shelf -I -dr 2 < room.pts
run shelf_camera_dr2.txt shelf -ovlpnNm -dr 2 < shelf_camera.rays
run relays_dr1.txt relays -I -dr 1 < room.pts
run relays_dr3.txt relays -I -dr 3 < room.pts
run penumbra_ds02.txt penumbra -I -ds .02 < line.pts
run uplight_ds02.txt uplight -I -ds .02 < grid.pts
run glow_illum_dr2.txt glow_illum -I -dr 2 < room.pts
run mirror_box_dr4.txt mirror_box -I -dr 4 < room.pts
run textured_dr2.txt textured -I -dr 2 < room.pts
run mirror_instance_dr2.txt mirror_instance -I -dr 2 < room.pts
run shelf_bv.txt shelf -I -dr 2 -bv- < room.pts
run relays_bv.txt relays -I -dr 2 -bv- < room.pts
run tube_ds02.txt tube -I -dr 2 -ds .02 < room.pts
run illum_mirror_dr2.txt illum_mirror -I -dr 2 < room.pts
run illum_mirror_dr0.txt illum_mirror -I -dr 0 < room.pts
