#!/usr/bin/env bash
# Radiance 5.4a's -ovW for Golden.InvisibleSourcesFollowRadiance at -dv+ and
# -dv-: a glow of radius 2 seen directly and through a glass pane (with -dv-
# Radiance counts the whole primary path's length against the radius), and a
# light polygon from the front and the back (with -dv- both give no light and
# a zero coefficient W). The test reads the committed *.txt; this script is
# for a developer who has Radiance at hand.
#
#   tests/data/sourcevis/make_refs.sh [radiance-dir]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
rad="${1:-$here/../../../../shared/reference/radiance-5.4a}"
[ -x "$rad/bin/rtrace" ] || { echo "no Radiance in $rad" >&2; exit 1; }
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
cd "$here"
"$rad/bin/oconv" glow_through_glass.rad > "$tmp/scene.oct"
for dv in + -; do
    "$rad/bin/rtrace" -h -ab 0 -dv$dv -ovW "$tmp/scene.oct" < rays.txt 2>/dev/null \
        > "ovW_dv$dv.txt"
done
