#!/usr/bin/env bash
# Memory and load time of instancing (issue 15): one 100 000-triangle mesh
# placed once, 10 times and 1000 times, and the same mesh inside an instanced
# octree placed 1000 times. Each scene is loaded and traced with a single ray;
# /usr/bin/time -v gives the wall time and the peak resident memory. With
# instancing both should stay flat as the count grows: one copy of the mesh
# plus the instance table. Real Radiance's rtrace runs on the same scenes
# (octrees made by its oconv, not timed), for comparison in the same run.
#   bench/instances.sh LAZYRAD_RTRACE [RADIANCE_DIR]
# The mesh is made with real Radiance's obj2mesh (a benchmark may use it; the
# build and the tests never do).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
lz=$(realpath "${1:?usage: instances.sh LAZYRAD_RTRACE [RADIANCE_DIR]}")
rad=${2:-$root/../shared/reference/radiance-5.4a}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
cd "$tmp"
# A 224 x 224 grid of quads on a bumpy sheet: 100 352 triangles with normals.
awk 'BEGIN { n = 224; for (i = 0; i <= n; i++) for (j = 0; j <= n; j++) {
    x = i / n; y = j / n; z = 0.05 * sin(12 * x) * cos(9 * y)
    printf "v %.6f %.6f %.6f\nvn 0 0 1\n", x, y, z }
  for (i = 0; i < n; i++) for (j = 0; j < n; j++) {
    a = i * (n + 1) + j + 1; b = a + n + 1
    printf "f %d//%d %d//%d %d//%d\nf %d//%d %d//%d %d//%d\n", a, a, b, b, b + 1, b + 1, a, a, b + 1, b + 1, a + 1, a + 1 } }' \
  > sheet.obj
"$rad/bin/obj2mesh" sheet.obj sheet.rtm
head_scene='void plastic grey 0 0 5 .5 .5 .5 0 0
void light lamp 0 0 3 10 10 10
lamp sphere bulb 0 0 4 20 20 30 1
grey polygon floor 0 0 12 -1 -1 -1  60 -1 -1  60 60 -1  -1 60 -1'
place() {  # place COUNT TYPE FILE
  awk -v n="$1" -v type="$2" -v file="$3" 'BEGIN { k = int(sqrt(n) + 0.999)
    for (i = 0; i < n; i++) printf "grey %s p%d 5 %s -t %d %d 0 0 0\n", type, i, file, (i % k) * 1.5, int(i / k) * 1.5 }'
}
printf 'void plastic grey 0 0 5 .5 .5 .5 0 0\ngrey mesh m 1 sheet.rtm 0 0\n' > sheet_inst.rad
"$rad/bin/oconv" -f sheet_inst.rad > sheet_inst.oct
measure() {  # measure COMMAND... -> "seconds megabytes" of one ray through it
  echo "20 20 10 0 0 -1" | RAYPATH=.:$rad/lib /usr/bin/time -v "$@" > /dev/null 2> time.txt
  awk -F': ' '/Elapsed \(wall clock\)/ { n = split($2, t, ":"); s = 0; for (i = 1; i <= n; i++) s = s * 60 + t[i] }
    /Maximum resident set size/ { m = $2 / 1024 } END { printf "%s %.0f", s, m }' time.txt
}
echo "| scene | lazyrad: load + one ray (s) | peak memory (MB) | Radiance: rtrace on oconv's octree (s) | peak memory (MB) |"
echo "|---|---|---|---|---|"
for case in "1 mesh sheet.rtm" "10 mesh sheet.rtm" "1000 mesh sheet.rtm" "1000 instance sheet_inst.oct"; do
  set -- $case
  { echo "$head_scene"; place "$1" "$2" "$3"; } > scene.rad
  "$rad/bin/oconv" scene.rad > scene.oct
  read -r lt lm <<< "$(measure "$lz" -h -ab 0 scene.rad)"
  read -r rt rm <<< "$(measure "$rad/bin/rtrace" -h -ab 0 scene.oct)"
  echo "| $1 x $2 of $3 | $lt | $lm | $rt | $rm |"
done
