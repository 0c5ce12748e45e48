#!/usr/bin/env bash
# Converged -ab 2 irradiance at grid.pts with REAL Radiance 5.4a under each
# sky, as ../df_room's reference is made (scenes/README.md): the mean of N
# independent path-traced estimates per point (-aa 0 -ad 1 -as 0 -lw 1e-9
# -u+), in chunks (../path_traced_ref.py). Writes ref/grid_I_ab2_SKY.txt:
# r g b rel_stderr (green).
# A developer's tool; nothing in the build or tests runs it.
#   scenes/bsdf_room/make_ref.sh SKY [PATHS_PER_POINT] [RADIANCE_DIR]
#   (SKY: sky for the overcast sky.rad, sun_sky for sun_sky.rad, tree_sky
#   for the overcast sky over room_tree.rad, the tensor-tree glazing)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
sky=${1:?usage: make_ref.sh sky|sun_sky|tree_sky [PATHS] [RADIANCE_DIR]}
n=${2:-1000000}
rad=${3:-$here/../../../shared/reference/radiance-5.4a}
export PATH=$rad/bin:$PATH RAYPATH=.:$rad/lib
cd "$here"
mkdir -p ref
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
case $sky in
  tree_sky) oconv sky.rad room_tree.rad > "$tmp/room.oct" ;;
  *) oconv "$sky.rad" room.rad > "$tmp/room.oct" ;;
esac
python3 ../path_traced_ref.py "$tmp/room.oct" grid.pts "$n" "ref/grid_I_ab2_$sky.txt"
# The frozen octrees bench/side_by_side.sh runs both programs on, as a
# daylighting tool makes them.
case $sky in
  sky) oconv -f sky.rad room.rad > bsdf_room_overcast.oct ;;
  sun_sky) oconv -f sun_sky.rad room.rad > bsdf_room_sun.oct ;;
  tree_sky) oconv -f sky.rad room_tree.rad > bsdf_room_tree.oct ;;
esac
