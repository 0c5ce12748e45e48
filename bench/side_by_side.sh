#!/usr/bin/env bash
# Whole-program speed against real Radiance 5.4a, side by side on this machine
# (issue 17): ../shared/tools/side-by-side alternates lazyrad's rtrace and
# Radiance's on each job below and prints both times, the speed-up (Radiance's
# minimum over lazyrad's) and both errors against the converged references.
# The table goes to standard output and, with -w, replaces the side-by-side
# section of docs/benchmarks.md, naming the machine and the date.
#
#   bench/side_by_side.sh [-w] [-n PAIRS] LAZYRAD_RTRACE [JOBS]
#     JOBS  subset of: floor edges daylit floor_fast mixed floor_fast_oct shelf
#           bsdf_overcast bsdf_sun bsdf_tree (default all)
#
# Every speed-up is a ratio measured in this run; the absolute times are only
# for reading the table. Lazyrad-only options can be passed through a wrapper
# script given as LAZYRAD_RTRACE.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
write=0 pairs=3
while getopts "wn:" o; do case $o in w) write=1 ;; n) pairs=$OPTARG ;; *) exit 2 ;; esac; done
shift $((OPTIND - 1))
lz=$(realpath "${1:?usage: side_by_side.sh [-w] [-n PAIRS] LAZYRAD_RTRACE [JOBS]}")
jobs=${2:-floor edges daylit floor_fast mixed floor_fast_oct shelf bsdf_overcast bsdf_sun bsdf_tree}
sbs=$root/../shared/tools/side-by-side
[ -x "$sbs" ] || { echo "side_by_side.sh: $sbs not found (needs ../shared)" >&2; exit 2; }
defaults="-ad 1024 -as 512 -aa .1 -ar 256"
job() {  # name -> "description|options|scene|points|reference or -[|folder to run in]"
  local s=$root/scenes
  local hb="-h -I -aa .1 -ab 2 -ad 2048 -ar 64"  # honeybee's daylight-factor recipe
  case $1 in
    floor) echo "cornell floor, 84 points|-h -I -ab 2 $defaults|$s/cornell/cornell.rad|$s/cornell/floor.pts|$s/cornell/ref/floor_I_ab2.txt" ;;
    edges) echo "cornell edges, 40 points|-h -I -ab 2 $defaults|$s/cornell/cornell.rad|$s/cornell/edges.pts|$s/cornell/ref/edges_I_ab2.txt" ;;
    daylit) echo "daylit work plane, 96 points|-h -I -ab 4 $defaults|$s/daylit_room/daylit_room.rad|$s/daylit_room/workplane.pts|$s/daylit_room/ref/workplane_I_ab4.txt" ;;
    floor_fast) echo "cornell floor, fast settings|-h -I -ab 2 -ad 256 -as 128 -aa .2 -ar 64|$s/cornell/cornell.rad|$s/cornell/floor.pts|$s/cornell/ref/floor_I_ab2.txt" ;;
    # The same job from a frozen octree (oconv -f: self-contained, its reals
    # rounded to about 31 bits), given to both programs: the rounding once
    # made lazyrad make far more records (README, "Frozen octrees").
    floor_fast_oct) echo "cornell floor, fast settings, frozen octree|-h -I -ab 2 -ad 256 -as 128 -aa .2 -ar 64|$root/tests/data/octree/cornell_frozen.oct|$s/cornell/floor.pts|$s/cornell/ref/floor_I_ab2.txt" ;;
    # The daylit room with a mirrored light shelf: the sun also comes in
    # through a virtual source (-dr), in both programs.
    shelf) echo "daylit room with a mirror light shelf, 96 points|-h -I -ab 4 $defaults|$s/shelf_room/shelf_room.rad|$s/daylit_room/workplane.pts|$s/shelf_room/ref/workplane_I_ab4.txt" ;;
    mixed) echo "mixed room (curved, metal, trans, glass, 5 source kinds), 120 points|-h -I -ab 2 $defaults|$s/mixed/mixed.rad|$s/mixed/workplane.pts|-" ;;
    # The df_room with an exterior venetian blind as a BSDF file, as honeybee
    # runs such a model: frozen octrees made by Radiance's oconv -f, run in
    # the scene's folder, where both programs find blinds.xml on RAYPATH.
    bsdf_overcast) echo "BSDF blinds room, overcast sky, 96 points|$hb|$s/bsdf_room/bsdf_room_overcast.oct|$s/bsdf_room/grid.pts|$s/bsdf_room/ref/grid_I_ab2_sky.txt|$s/bsdf_room" ;;
    bsdf_sun) echo "BSDF blinds room, sun and sky, 96 points|$hb|$s/bsdf_room/bsdf_room_sun.oct|$s/bsdf_room/grid.pts|$s/bsdf_room/ref/grid_I_ab2_sun_sky.txt|$s/bsdf_room" ;;
    bsdf_tree) echo "BSDF tensor-tree glazing room, overcast sky, 96 points|$hb|$s/bsdf_room/bsdf_room_tree.oct|$s/bsdf_room/grid.pts|$s/bsdf_room/ref/grid_I_ab2_tree_sky.txt|$s/bsdf_room" ;;
    *) echo "side_by_side.sh: unknown job '$1'" >&2; exit 2 ;;
  esac
}
table=$(mktemp); log=$(mktemp); trap 'rm -f "$table" "$log"' EXIT
{
  echo "| job | options | lazyrad min (median) s | Radiance min (median) s | speed-up | RMS error lazyrad / Radiance |"
  echo "|---|---|---|---|---|---|"
} > "$table"
for name in $jobs; do
  IFS='|' read -r desc opts scene points ref dir <<< "$(job "$name")"
  echo "== $desc: $opts" >&2
  args=(-n "$pairs")
  [ "$ref" != - ] && args+=(-r "$ref")
  (cd "${dir:-.}" && "$sbs" "${args[@]}" "$lz" "$opts" "$scene" "$points") | tee "$log" >&2
  python3 - "$desc" "$opts" "$log" >> "$table" <<'PY'
import re, sys, statistics as st
desc, opts, log = sys.argv[1], sys.argv[2], open(sys.argv[3]).read()
s = re.search(r"lazyrad min ([\d.]+)s median ([\d.]+)s \| radiance min ([\d.]+)s median ([\d.]+)s \| speed-up ([\d.]+)x \(median ([\d.]+)x\)", log)
el = [float(x) for x in re.findall(r"lazyrad rms=([\d.]+)%", log)]
er = [float(x) for x in re.findall(r"radiance rms=([\d.]+)%", log)]
err = f"{st.mean(el):.2f} % / {st.mean(er):.2f} %" if el else "no reference"
print(f"| {desc} | `{opts.replace('-h ', '')}` | {s[1]} ({s[2]}) | {s[3]} ({s[4]}) | "
      f"**{s[5]}x** ({s[6]}x) | {err} |")
PY
done
cat "$table"
if [ "$write" = 1 ]; then
  doc=$root/docs/benchmarks.md
  cpu=$(lscpu 2>/dev/null | sed -n 's/^Model name: *//p' | head -1)
  {
    echo "<!-- side-by-side:begin (written by bench/side_by_side.sh -w) -->"
    echo "Measured $(date -u +%Y-%m-%d) on ${cpu:-unknown CPU}, $(nproc) cores, with"
    echo "\`bench/side_by_side.sh -w -n $pairs $1\` (lazyrad commit"
    echo "$(git -C "$root" rev-parse --short HEAD)$(git -C "$root" diff --quiet || echo ', with local changes')): $pairs alternating pairs per job, one process each;"
    echo "the speed-up is Radiance's minimum time over lazyrad's (in brackets: medians);"
    echo "errors are luminance RMS against the converged references, the mean over the pairs."
    echo
    cat "$table"
    echo "<!-- side-by-side:end -->"
  } > "$table.section"
  python3 - "$doc" "$table.section" <<'PY'
import sys
doc, sec = sys.argv[1], open(sys.argv[2]).read().rstrip("\n")
text = open(doc).read()
b, e = "<!-- side-by-side:begin", "<!-- side-by-side:end -->"
if b in text:
    i = text.index(b); j = text.index(e) + len(e)
    text = text[:i] + sec + text[j:]
else:
    text = text.rstrip("\n") + "\n\n## Whole program, side by side with Radiance\n\n" + sec + "\n"
open(doc, "w").write(text)
PY
  rm -f "$table.section"
  echo "wrote $doc" >&2
fi
