#!/usr/bin/env bash
# The cost of a function sky (issue 14): the daylit room under its constant
# glow sky, under `gensky +s` and under `gensky -c`, each timed side by side
# with real Radiance (../shared/tools/side-by-side, alternating runs).
#   bench/daylit_skies.sh LAZYRAD_RTRACE [PAIRS] [OPTIONS]
# The gensky skies are written by lazyrad's bundled gensky (byte-identical to
# Radiance's); the sun is placed where the scene's own sun is.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
lz=${1:?usage: daylit_skies.sh LAZYRAD_RTRACE [PAIRS] [OPTIONS]}
pairs=${2:-3}
opts=${3:--h -I -ab 4 -ad 1024 -as 512 -aa .1 -ar 256}
tools=$(dirname "$lz")
sbs=$root/../shared/tools/side-by-side
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
room=$root/scenes/daylit_room/daylit_room.rad
# The room without its sky and sun (the first 25 lines).
tail -n +26 "$room" > "$tmp/room_only.rad"
hemispheres='skyfunc glow sky_glow 0 0 4 1 1 1 0
sky_glow source sky 0 0 4 0 0 1 180
skyfunc glow ground_glow 0 0 4 1 1 1 0
ground_glow source ground 0 0 4 0 0 -1 180'
# Sun direction (0.2, -0.7, 0.68): altitude 42.8 degrees, azimuth -15.9 (west of south).
for sky in "+s" "-c"; do
  name=$(echo "$sky" | tr -d '+-')
  { "$tools/gensky" -ang 42.8 -15.9 "$sky" -B 100; echo "$hemispheres"; cat "$tmp/room_only.rad"; } \
    > "$tmp/room_$name.rad"
done
cp "$room" "$tmp/room_glow.rad"
for v in glow s c; do
  echo "== daylit room, sky: $v ($opts)"
  "$sbs" -n "$pairs" "$lz" "$opts" "$tmp/room_$v.rad" "$root/scenes/daylit_room/workplane.pts" | tail -1
done
