#!/usr/bin/env bash
# The daylit room's work plane under gensky skies (issue 14) at a daylighting
# tool's settings, lazyrad against real Radiance, each scored against the
# converged references of scenes/daylit_room/make_sky_refs.sh. lazyrad runs
# with RAYPATH holding no .cal files, so it evaluates the skies with its own
# lib/skybright.cal; Radiance with its own library. Both run RUNS times, each
# run another draw of the Monte Carlo error: lazyrad with -seed 1..RUNS,
# Radiance with -u+ in different seconds (it seeds -u+ from the clock in
# seconds), so the spread of each one's error shows.
#   bench/daylit_sky_refcheck.sh LAZYRAD_RTRACE [RUNS] [OPTIONS] [RADIANCE_DIR]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
lz=$(cd "$(dirname "${1:?usage: daylit_sky_refcheck.sh LAZYRAD_RTRACE [RUNS] [OPTIONS]}")" && pwd)/$(basename "$1")
runs=${2:-3}
opts=${3:--h -I -aa .1 -ab 2 -ad 2048 -ar 64}
rad=${4:-$root/../shared/reference/radiance-5.4a}
room=$root/scenes/daylit_room
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
mkdir "$tmp/no_cal"
# The room without its own sky and sun (the first 25 lines of daylit_room.rad).
tail -n +26 "$room/daylit_room.rad" > "$tmp/room_only.rad"
score() {  # score REF OUT -> "rms max bias" in %, on luminance
  python3 - "$1" "$2" <<'PY'
import sys, math
lum = lambda v: 0.265074126*v[0] + 0.670114631*v[1] + 0.064811243*v[2]
ref = [[float(x) for x in l.split()[:3]] for l in open(sys.argv[1]) if l.strip()]
out = [[float(x) for x in l.split()[:3]] for l in open(sys.argv[2]) if l.strip()]
assert len(ref) == len(out), "count mismatch"
e = [lum(o) / lum(r) - 1 for r, o in zip(ref, out)]
print("rms %.2f %% max %.2f %% bias %+.2f %%" % (100 * math.sqrt(sum(x * x for x in e) / len(e)),
      100 * max(abs(x) for x in e), 100 * sum(e) / len(e)))
PY
}
for sky in c s; do
  cat "$room/sky_gensky_$sky.rad" "$tmp/room_only.rad" > "$tmp/scene_$sky.rad"
  (cd "$tmp" && PATH=$rad/bin:$PATH RAYPATH=.:$rad/lib oconv -f "scene_$sky.rad" > "scene_$sky.oct")
  ref=$room/ref/workplane_I_ab2_gensky_$sky.txt
  echo "== gensky $(grep '^!gensky' "$room/sky_gensky_$sky.rad" | cut -d' ' -f2-)  ($opts)"
  for i in $(seq 1 "$runs"); do
    s=$(date +%s.%N)
    # shellcheck disable=SC2086
    RAYPATH=$tmp/no_cal "$lz" $opts -seed "$i" "$tmp/scene_$sky.rad" < "$room/workplane.pts" > "$tmp/lz"
    m=$(date +%s.%N)
    # shellcheck disable=SC2086
    PATH=$rad/bin:$PATH RAYPATH=.:$rad/lib rtrace $opts -u+ "$tmp/scene_$sky.oct" \
      < "$room/workplane.pts" > "$tmp/rad"
    e=$(date +%s.%N)
    printf 'run %d: lazyrad %.2fs %s | radiance %.2fs %s\n' "$i" \
      "$(echo "$m - $s" | bc)" "$(score "$ref" "$tmp/lz")" \
      "$(echo "$e - $m" | bc)" "$(score "$ref" "$tmp/rad")"
    sleep 1
  done
done
