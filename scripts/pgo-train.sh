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
# A large model's start-up, no rays: 60 000 polygons (small boxes, as
# furniture comes out of a modeller) read, built and put in the ray core.
# Written by awk, so the build machine needs no generator.
big=$(mktemp); trap 'rm -f "$big"' EXIT
awk 'BEGIN {
  print "void plastic grey 0 0 5 .5 .5 .5 0 0"
  print "void light lamp 0 0 3 10 10 10"
  print "lamp polygon panel 0 0 12 9 9 2.99 9 11 2.99 11 11 2.99 11 9 2.99"
  for (b = 0; b < 10000; b++) {
    x = (b % 100) * 0.2; y = int(b / 100) * 0.2; z = (b % 7) * 0.3; s = 0.1
    split("0 0 0 0 1 0 1 1 0 1 0 0|0 0 1 1 0 1 1 1 1 0 1 1|0 0 0 1 0 0 1 0 1 0 0 1|0 1 0 0 1 1 1 1 1 1 1 0|0 0 0 0 0 1 0 1 1 0 1 0|1 0 0 1 1 0 1 1 1 1 0 1", faces, "|")
    for (f = 1; f <= 6; f++) {
      n = split(faces[f], c, " ")
      printf "grey polygon b%d.%d 0 0 12", b, f
      for (k = 1; k <= n; k += 3) printf " %g %g %g", x + s * c[k], y + s * c[k + 1], z + s * c[k + 2]
      printf "\n"
    }
  } }' > "$big"
run /dev/null -h -I -ab 0 "$big"
