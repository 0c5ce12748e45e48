#!/usr/bin/env bash
# Generates the scale and location cases of the robustness suite (issue
# "Numerical stability"): the cornell box, the furnace and the skyplane, each
# scaled by 1e-4, 1e-2, 1, 1e2, 1e4 and moved to (1e6, -2e6, 5e5), with their
# measurement points and rays transformed the same way (positions scaled or
# moved, directions kept). Irradiance from surfaces of given radiance does not
# depend on scale or location, so every case must reproduce the untransformed
# answers.
#
#   tests/robustness/generate.sh XFORM OUTDIR
#
# XFORM is lazyrad's xform (build/bin/xform); OUTDIR/<case>/ receives
# cornell.rad floor.pts edges.pts furnace.rad furnace_points.txt
# furnace_rays.txt skyplane.rad skyplane_points.txt for the cases
# scale_1e-4 scale_1e-2 scale_1 scale_1e2 scale_1e4 translate.
set -euo pipefail
[ $# -eq 2 ] || { echo "usage: generate.sh XFORM OUTDIR" >&2; exit 2; }
xform=$1 out=$2
scenes="$(cd "$(dirname "$0")/../.." && pwd)/scenes"

# points FILE SCALE DX DY DZ: "x y z dx dy dz" lines, positions mapped to
# p*SCALE + (DX,DY,DZ), directions unchanged; full double precision.
points() {
  awk -v s="$2" -v dx="$3" -v dy="$4" -v dz="$5" \
    '{ printf "%.17g %.17g %.17g %s %s %s\n", $1*s + dx, $2*s + dy, $3*s + dz, $4, $5, $6 }' "$1"
}

# make CASE SCALE DX DY DZ
make() {
  local dir=$out/$1 s=$2 dx=$3 dy=$4 dz=$5
  mkdir -p "$dir"
  local args=(-s "$s" -t "$dx" "$dy" "$dz")
  "$xform" "${args[@]}" "$scenes/cornell/cornell.rad" > "$dir/cornell.rad"
  "$xform" "${args[@]}" "$scenes/furnace/furnace.rad" > "$dir/furnace.rad"
  "$xform" "${args[@]}" "$scenes/skyplane/skyplane.rad" > "$dir/skyplane.rad"
  points "$scenes/cornell/floor.pts" "$s" "$dx" "$dy" "$dz" > "$dir/floor.pts"
  points "$scenes/cornell/edges.pts" "$s" "$dx" "$dy" "$dz" > "$dir/edges.pts"
  points "$scenes/furnace/points.txt" "$s" "$dx" "$dy" "$dz" > "$dir/furnace_points.txt"
  points "$scenes/furnace/rays.txt" "$s" "$dx" "$dy" "$dz" > "$dir/furnace_rays.txt"
  points "$scenes/skyplane/points.txt" "$s" "$dx" "$dy" "$dz" > "$dir/skyplane_points.txt"
}

for s in 1e-4 1e-2 1 1e2 1e4; do make "scale_$s" "$s" 0 0 0; done
make translate 1 1e6 -2e6 5e5
