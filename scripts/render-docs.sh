#!/usr/bin/env bash
# Regenerates, in one command, the pictures in docs/images/ (see docs/images.md).
#   scripts/render-docs.sh [build-dir]      (default: build/, made by scripts/build.sh release)
# The golden images of tests/rvimage/golden_image_test.cpp are not made here: they
# are real Radiance's pictures, made by tests/data/golden/make_refs.sh, so that
# lazyrad is never compared with its own output.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$root/build}"
[ -d "$build" ] || "$root/scripts/build.sh" release
cmake --build "$build" -j2 --target rvimage >/dev/null
rv="$build/bin/rvimage"
out="$root/docs/images"
mkdir -p "$out"

# Two-bounce renders with the demo's ambient settings; -seed 0 makes them repeatable.
# -layers records with a .png output also writes <name>_records.png.
common=(-seed 0 -x 384 -y 384 -ad 1024 -as 512 -aa .1 -ar 256 -layers records -rscale 0.3)
(cd "$root/scenes/cornell" &&
  "$rv" -t 30 -vf cornell.vf -ab 2 "${common[@]}" -o "$out/cornell.png" cornell.rad)
(cd "$root/scenes/daylit_room" &&
  "$rv" -t 30 -vf daylit_room.vf -ab 3 "${common[@]}" -o "$out/daylit_room.png" daylit_room.rad)
