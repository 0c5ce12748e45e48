#!/usr/bin/env bash
# Makes the references of Golden.ObstructorCacheMatchesRadiance with real
# Radiance 5.4a: the 120 work-plane sensors of the mixed room (a polygon, a
# sphere and a cylinder light, a ring spotlight, and the sun, which the south
# wall hides), one process, -ab 0 -u- -dj 0 -ss 0, where adaptive shadow
# testing (-dt above 0) decides from the obstructor cache which samples it
# tests: the shadow rays Radiance traces (-oTvmp at -dt .3 -dc .5, every
# shadow ray its cache does not skip) and the values at -dt 1 -dc 0 and at
# -dt .5 -dc .25. The panel is divided into partitions near it (-ds .2), and
# the cache checks only the samples of undivided sources. And sensors in and
# around a lampshade (obstructor_shade.rad), one lit inside it although the
# cache holds the shade's far side for its direction. The test only reads
# the committed files.
#
#   tests/data/golden/make_obstructor_refs.sh [radiance-dir]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
# shellcheck source=radiance_setup.sh
source "$here/radiance_setup.sh"
scenes="$here/../../../scenes"
"$rad/bin/oconv" "$scenes/mixed/mixed.rad" > "$tmp/mixed.oct"
run() { "$rad/bin/rtrace" -h -I -ab 0 -u- -dj 0 -ss 0 "$@" "$tmp/mixed.oct" < "$scenes/mixed/workplane.pts"; }
run -dt .3 -dc .5 -oTvmp > "$here/mixed_obstructed_oTvmp.txt"
run -dt 1 -dc 0 -ov > "$here/mixed_obstructed_dt1.txt"
run -dt .5 -dc .25 -ov > "$here/mixed_obstructed_dt5.txt"
"$rad/bin/oconv" "$here/obstructor_shade.rad" > "$tmp/shade.oct"
"$rad/bin/rtrace" -h -I -ab 0 -dt 0 -oTvmp "$tmp/shade.oct" < "$here/obstructor_shade.pts" \
  > "$here/obstructor_shade_oTvmp.txt"
"$rad/bin/rtrace" -h -I -ab 0 -dt 0 -ov "$tmp/shade.oct" < "$here/obstructor_shade.pts" \
  > "$here/obstructor_shade_ov.txt"
