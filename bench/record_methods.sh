#!/usr/bin/env bash
# Classic, Hessian and mixed records (rtrace -ah- / -ah+ / -ahm, the last the
# default), with real Radiance 5.4a
# on the same jobs, on this machine: records per ambient level, rays (lazyrad
# only: hemisphere and specular + shadow rays), CPU seconds and
# luminance error against converged references (the error has the reference's
# own noise taken off in quadrature, bench/score.py).
#
#   bench/record_methods.sh RTRACE [SEEDS] [JOBS]
#     RTRACE  lazyrad's rtrace (e.g. build/bin/rtrace)
#     SEEDS   lazyrad seeds, default "0 1 2"; Radiance runs as many times
#             (-u+ seeds from the clock, so runs are a second apart)
#     JOBS    subset of: floor edges daylit dense dense_tool view daylit_dense
#             (default all)
# RADIANCE_BIN (default ../shared/reference/radiance-5.4a/bin) is used only
# here, for measurement; prints one line per run and a summary per job.
set -euo pipefail
cd "$(dirname "$0")/.."
lz=${1:?usage: record_methods.sh RTRACE [SEEDS] [JOBS]}
seeds=${2:-0 1 2}
jobs=${3:-floor edges daylit dense dense_tool view daylit_dense}
RAD=${RADIANCE_BIN:-$PWD/../shared/reference/radiance-5.4a/bin}
export RAYPATH=${RAYPATH:-.:$RAD/../lib}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
defaults="-ad 1024 -as 512 -aa .1 -ar 256"
tool="-aa .1 -ad 2048 -ar 64"
job() {  # name -> "scene points reference options"
  case $1 in
    floor) echo "scenes/cornell/cornell.rad scenes/cornell/floor.pts scenes/cornell/ref/floor_I_ab2.txt -h -I -ab 2 $defaults" ;;
    edges) echo "scenes/cornell/cornell.rad scenes/cornell/edges.pts scenes/cornell/ref/edges_I_ab2.txt -h -I -ab 2 $defaults" ;;
    daylit) echo "scenes/daylit_room/daylit_room.rad scenes/daylit_room/workplane.pts scenes/daylit_room/ref/workplane_I_ab4.txt -h -I -ab 4 $defaults" ;;
    dense) echo "scenes/cornell/cornell.rad scenes/cornell/floor_dense.pts scenes/cornell/ref/floor_dense_I_ab2.txt -h -I -ab 2 $defaults" ;;
    dense_tool) echo "scenes/cornell/cornell.rad scenes/cornell/floor_dense.pts scenes/cornell/ref/floor_dense_I_ab2.txt -h -I -ab 2 $tool" ;;
    view) echo "scenes/cornell/cornell.rad scenes/cornell/view128.rays scenes/cornell/ref/view128_ab2.txt -h -ab 2 $defaults" ;;
    daylit_dense) echo "scenes/daylit_room/daylit_room.rad scenes/daylit_room/workplane_dense.pts scenes/daylit_room/ref/workplane_dense_I_ab4.txt -h -I -ab 4 $defaults" ;;
  esac
}
levels() {  # ambient file -> "n0/n1/..." records per level
  "$RAD/lookamb" -h -d "$1" | awk '{n[$10]++; if ($10 > m) m = $10} END {s = ""; for (l = 0; l <= m; l++) s = s (l ? "/" : "") (n[l] + 0); print s}'
}
run() {  # label cmd... (stdin points, stdout values) -> prints "cpu records error"
  local label=$1; shift
  rm -f "$tmp/a.amb"
  /usr/bin/time -f "%U" -o "$tmp/t" "$1" -af "$tmp/a.amb" "${@:2}" < "$points" > "$tmp/out" 2> "$tmp/err" || { cat "$tmp/err" >&2; exit 1; }
  local cpu rays; cpu=$(tail -1 "$tmp/t")
  # lazyrad's -t summary counts the rays (hemisphere and specular + shadow);
  # Radiance's rtrace has no such count.
  rays=$(sed -n 's/.* \([0-9]*\) rays traced + \([0-9]*\) shadow rays.*/\1+\2/p' "$tmp/err" | tail -1)
  printf "%-28s cpu %6.2f s  records %-14s rays %-18s %s\n" "$label" "$cpu" "$(levels "$tmp/a.amb")" "${rays:--}" "$(python3 bench/score.py "$ref" "$tmp/out")"
}
for name in $jobs; do
  read -r scene points ref opts <<< "$(job "$name")"
  "$RAD/oconv" "$scene" > "$tmp/scene.oct"
  echo "== $name: rtrace $opts ($(wc -l < "$points") lines)"
  for s in $seeds; do
    for method in "classic -ah-" "hessian -ah+" "mixed -ahm"; do
      # shellcheck disable=SC2086
      run "lazyrad ${method% *} seed $s" "$lz" -t 100000 "${method#* }" -seed "$s" $opts "$scene"
    done
    sleep 1.1
    # shellcheck disable=SC2086
    run "radiance" "$RAD/rtrace" $opts "$tmp/scene.oct"
  done
done
