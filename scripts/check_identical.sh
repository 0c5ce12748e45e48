#!/usr/bin/env bash
# Checks that two builds give byte-identical output, for refactorings that must
# not change what the programs write: rtrace at -ab 0 and at -ab 2 with a fixed
# seed and correlated sampling (-u-, so results repeat) on the shared scenes,
# -I at the same points, the camera rays with -ovlpnNm, small rvimage pictures
# in every output format (jittered, with every layer), xform's scene text, and
# the messages and exit codes of a few failing runs.
#
#   scripts/check_identical.sh BIN_BEFORE BIN_AFTER
#
# BIN_BEFORE and BIN_AFTER are directories holding rtrace, rvimage and xform (a
# copy of an earlier build/bin, and build/bin). SCENES (default: this
# repository's scenes/) holds cornell/, daylit_room/, furnace/, skyplane/.
# Prints one line per run and exits 1 if any output differs.
set -euo pipefail
[ $# -eq 2 ] || { echo "usage: check_identical.sh BIN_BEFORE BIN_AFTER" >&2; exit 2; }
before=$(cd "$1" && pwd) after=$(cd "$2" && pwd)
scenes=${SCENES:-"$(cd "$(dirname "$0")/.." && pwd)/scenes"}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/before" "$work/after"

same=0 differ=0
# check NAME INPUT PROGRAM ARGS...: runs PROGRAM from both builds in their own
# directories with INPUT on standard input; compares standard output, standard
# error, the exit status and the pictures the run wrote.
check() {
  local name=$1 input=$2 program=$3
  shift 3
  for side in before after; do
    local bin=$before
    [ "$side" = after ] && bin=$after
    # Called by name through PATH, so argv[0] (which headers and picture
    # metadata record) is the same for both builds.
    (cd "$work/$side" && set +e
     PATH="$bin:$PATH" "$program" "$@" < "$input" > "$name.out" 2> "$name.err"
     echo $? > "$name.status")
  done
  local files=("$name.out" "$name.err" "$name.status")
  for extra in "$work/before/$name"*.{hdr,exr,png}; do
    [ -e "$extra" ] && files+=("$(basename "$extra")")
  done
  local result=identical
  for f in "${files[@]}"; do
    cmp -s "$work/before/$f" "$work/after/$f" || result="DIFFERS ($f)"
  done
  if [ "$result" = identical ]; then same=$((same + 1)); else differ=$((differ + 1)); fi
  local bytes
  bytes=$(cd "$work/after" && cat "${files[@]}" | wc -c)
  printf '%-32s %d files %8s bytes  %s\n' "$name" "${#files[@]}" "$bytes" "$result"
}

cornell=$scenes/cornell daylit=$scenes/daylit_room
furnace=$scenes/furnace skyplane=$scenes/skyplane
fixed=(-u- -seed 1)
for set in "cornell floor $cornell/cornell.rad $cornell/floor.pts" \
           "cornell edges $cornell/cornell.rad $cornell/edges.pts" \
           "daylit workplane $daylit/daylit_room.rad $daylit/workplane.pts" \
           "furnace points $furnace/furnace.rad $furnace/points.txt" \
           "skyplane points $skyplane/skyplane.rad $skyplane/points.txt"; do
  read -r scene points rad pts <<< "$set"
  check "${scene}_${points}_ab0" "$pts" rtrace -h -ab 0 "$rad"
  check "${scene}_${points}_ab2" "$pts" rtrace -h -ab 2 "${fixed[@]}" "$rad"
  check "${scene}_${points}_I_ab2" "$pts" rtrace -h -I -ab 2 "${fixed[@]}" "$rad"
done
check furnace_rays_av_ab2 "$furnace/rays.txt" rtrace -h -av 1 1 1 -aw 0 -ab 2 "${fixed[@]}" \
  "$furnace/furnace.rad"
check cornell_cam32_ab0_ovlpnNm "$cornell/cam32.rays" rtrace -h -ab 0 -ovlpnNm "$cornell/cornell.rad"
check daylit_cam32x24_ab0_ovlpnNm "$daylit/cam32x24.rays" rtrace -h -ab 0 -ovlpnNm \
  "$daylit/daylit_room.rad"
check cornell_floor_I_ab1_ff "$cornell/floor.pts" rtrace -h -I -ab 1 -faf "${fixed[@]}" \
  "$cornell/cornell.rad"
# Two threads (the batched path): at -ab 0 the result does not depend on which
# thread takes which ray. (At -ab 1 and above, -n 2 runs differ from each other.)
check cornell_floor_I_ab0_n2 "$cornell/floor.pts" rtrace -h -I -ab 0 -n 2 "${fixed[@]}" \
  "$cornell/cornell.rad"

view=(-vf "$cornell/cornell.vf" -x 32 -y 32)
check rvimage_cornell_ab1 /dev/null rvimage -ab 1 "${fixed[@]}" "${view[@]}" -pj 0.7 \
  -layers all -o rvimage_cornell_ab1.exr "$cornell/cornell.rad"
check rvimage_cornell_hdr /dev/null rvimage -ab 1 "${fixed[@]}" "${view[@]}" \
  -o rvimage_cornell_hdr.pic.hdr "$cornell/cornell.rad"
check rvimage_cornell_png /dev/null rvimage -ab 1 "${fixed[@]}" "${view[@]}" -layers records \
  -o rvimage_cornell_png.png "$cornell/cornell.rad"

check xform_cornell /dev/null xform -s 2 -rz 30 -t 1 2 3 "$cornell/cornell.rad"

# Messages and exit codes.
check rtrace_defaults /dev/null rtrace -ab 2 -I -defaults
check rtrace_version /dev/null rtrace -version
check rtrace_bad_option /dev/null rtrace -ab x "$cornell/cornell.rad"
check rtrace_no_scene /dev/null rtrace -ab 1
check rtrace_bad_n /dev/null rtrace -n 0 "$cornell/cornell.rad"
check rtrace_missing_scene /dev/null rtrace -h missing.rad
echo "1 2 x" > "$work/bad_ray.txt"
check rtrace_bad_ray "$work/bad_ray.txt" rtrace -h "$cornell/cornell.rad"
check rvimage_defaults /dev/null rvimage -defaults
check rvimage_no_output /dev/null rvimage "${view[@]}" "$cornell/cornell.rad"
check rvimage_bad_layer /dev/null rvimage -layers nope -o x.exr "$cornell/cornell.rad"

echo "$same identical, $differ different"
[ "$differ" -eq 0 ]
