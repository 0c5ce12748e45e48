#!/usr/bin/env bash
# The training jobs of the profile-guided build (scripts/build.sh release):
# runs an instrumented rtrace on a mix of the repository's scenes so that its
# branch and call counts land in the profile folder. Usage:
#   scripts/pgo-train.sh INSTRUMENTED_RTRACE
#
# The mix covers what users run - sensor points with -I at a daylight tool's
# kind of settings, a picture's rays, a frozen octree with a gensky sky and
# its .cal functions, curved surfaces, metal, trans and glass, several kinds of
# source - but none of the timed jobs of bench/side_by_side.sh: the cornell
# floor points and the daylit room's 96 work-plane points are not in it (its
# dense grid is), the cornell edges and the mixed room only at other settings,
# so the table's speed-ups are not a replay of the training (README,
# "Profile-guided build").
set -euo pipefail
cd "$(dirname "$0")/.."
rt=$1
[ -x "$rt" ] || { echo "pgo-train: no program '$rt'" >&2; exit 1; }
fast=(-h -I -ab 2 -ad 256 -as 128 -aa .2 -ar 64)
run() {  # run POINTS ARGS...: one job, output discarded
    local points=$1; shift
    "$rt" "$@" < "$points" > /dev/null
}
run scenes/cornell/edges.pts "${fast[@]}" scenes/cornell/cornell.rad
run scenes/cornell/cam32.rays -h -ab 1 -ad 128 -as 64 -aa .2 -ar 32 scenes/cornell/cornell.rad
run scenes/daylit_room/workplane_dense.pts -h -I -ab 2 -ad 128 -as 64 -aa .2 -ar 32 \
    scenes/daylit_room/daylit_room.rad
run scenes/mixed/workplane.pts "${fast[@]}" scenes/mixed/mixed.rad
run scenes/df_room/grid.pts -h -I -ab 2 -aa .1 -ad 512 -ar 64 scenes/df_room/df_room.oct
