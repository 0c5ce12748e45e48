#!/usr/bin/env bash
# Converged -ab 2 irradiance at grid.pts with REAL Radiance 5.4a, as the other
# scenes' references are made (scenes/README.md): the mean of N independent
# path-traced estimates per point (-aa 0 -ad 1 -as 0 -lw 1e-9 -u+), in chunks
# (../path_traced_ref.py).
# Writes ref/grid_I_ab2.txt: r g b rel_stderr (green channel). A developer's
# tool; nothing in the build or tests runs it.
#   scenes/df_room/make_ref.sh [PATHS_PER_POINT] [RADIANCE_DIR]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
n=${1:-200000}
rad=${2:-$here/../../../shared/reference/radiance-5.4a}
export PATH=$rad/bin:$PATH RAYPATH=.:$rad/lib
cd "$here"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
oconv -f sky.rad room.rad > "$tmp/room.oct"
python3 ../path_traced_ref.py "$tmp/room.oct" grid.pts "$n" ref/grid_I_ab2.txt
# The frozen octree the demo runs on (scripts/demo.sh), as a daylighting tool
# makes it.
oconv -f sky.rad room.rad > df_room.oct
