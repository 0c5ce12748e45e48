#!/bin/sh
# Regenerates the real-Radiance ambient records next to a wall that
# tests/ambient/hessian_radiance_test.cpp compares lazyrad's Hessian records
# with. Needs Radiance 5.4a's rtrace, oconv, genbox, xform and lookamb (by
# default the reference build of /work/shared/reference/radiance-5.4a); the
# tests never run it.
#
# Scene: a floor [-6,6]² at z = 0 under a uniform glow sky of radiance 1 (no
# direct sources), and a wall box [w, w+0.2] × [-5,5] × [0,1], either black
# plastic or a glow of radiance 0.3 (never exactly 0, so that Radiance's
# super-sampling is not stopped by its 0/0 NaN). 25 floor points (0, y, 0),
# y = -3 … 3 in steps of 0.25, each make one level-0 record at the default
# -ad 1024 -as 512 -aa .1 and -ar 512 (cube size 12.00002: minarad 0.0234,
# maxarad 1.5). Six runs with separate ambient files and -u+ (time-seeded,
# one second apart) give 150 independent records per case.
#
# Output: wall_<black|glow>_<w>.txt, `lookamb -d -h` lines: pos(3) normal(3)
# u(3) level weight r0 r1 value(3) gpos(2) gdir(2) corral.
set -e
RADIANCE=${RADIANCE:-/work/shared/reference/radiance-5.4a}
export PATH=$RADIANCE/bin:$PATH RAYPATH=.:$RADIANCE/lib
out=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
for kind in black glow; do
  if [ $kind = black ]; then wallmat="void plastic wallmat 0 0 5 0 0 0 0 0"
  else wallmat="void glow wallmat 0 0 4 .3 .3 .3 0"; fi
  for w in 0.05 0.2; do
    cat > scene.rad <<EOR
void glow skyglow 0 0 4 1 1 1 0
skyglow source sky 0 0 4 0 0 1 180
void plastic grey 0 0 5 .5 .5 .5 0 0
grey polygon floor 0 0 12  -6 -6 0  6 -6 0  6 6 0  -6 6 0
$wallmat
!genbox wallmat wall 0.2 10 1 | xform -t $w -5 0
EOR
    oconv scene.rad > scene.oct
    : > "$out/wall_${kind}_$w.txt"
    for run in 1 2 3 4 5 6; do
      rm -f run.amb
      for y in $(seq -3 0.25 3); do echo "0 $y 1 0 0 -1"; done |
        rtrace -h- -u+ -ab 1 -ad 1024 -as 512 -aa .1 -ar 512 -af run.amb scene.oct > /dev/null
      lookamb -d -h run.amb >> "$out/wall_${kind}_$w.txt"
      sleep 1
    done
  done
done
