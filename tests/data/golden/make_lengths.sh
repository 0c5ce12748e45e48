#!/usr/bin/env bash
# Makes the references for Golden.RayLengthsMatchRadiance,
# Golden.TraceReportsBlockedShadowRays and Golden.TraceFollowsShadowRaysToTheSun
# with real Radiance 5.4a. The first: 400 rays from random points of the
# mixed room (scenes/mixed) in random directions, and Radiance's -oLlRX for
# them at -ab 0 -dj 0 (deterministic):
# first-hit length, effective length, mirrored length (1e10 unless a pure
# specular reflection set it) and unmirrored length. The test only reads the
# committed files; this script is for a developer who has Radiance at hand.
#
#   tests/data/golden/make_lengths.sh [radiance-dir]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../../.." && pwd)"
# shellcheck source=radiance_setup.sh
source "$here/radiance_setup.sh"
python3 - > "$here/mixed_lengths.rays" <<'PY'
import random
random.seed(3)
for _ in range(400):
    o = [random.uniform(0.5, 5.5), random.uniform(0.5, 3.5), random.uniform(0.3, 2.5)]
    d = [random.gauss(0, 1) for _ in range(3)]
    print(*o, *d)
PY
"$rad/bin/oconv" "$root/scenes/mixed/mixed.rad" > "$tmp/mixed.oct"
"$rad/bin/rtrace" -h -oLlRX -ab 0 -dj 0 "$tmp/mixed.oct" < "$here/mixed_lengths.rays" \
    > "$here/mixed_lengths_oLlRX.txt"

# Golden.TraceReportsBlockedShadowRays: -otvsL (the ray tree: value, surface,
# length of every ray, tab-indented by depth) for 60 random rays in the
# cornell box at -ab 0 -dj 0 -dt 0 -ss 0 -u-. Shadow rays appear where
# something other than their source stops them (Radiance's raycont() in
# direct()); the cornell box's lamp is not a distant source, and there
# Radiance's obstructor cache hides none of them on these rays.
python3 - > "$here/cornell_trace.rays" <<'PY'
import random
rnd = random.Random(11)
for _ in range(60):
    o = [rnd.uniform(0.2, 5.3), rnd.uniform(0.2, 5.3), rnd.uniform(0.2, 5.2)]
    d = [rnd.gauss(0, 1) for _ in range(3)]
    print(' '.join(f'{x:.6f}' for x in o + d))
PY
(cd "$root/scenes/cornell" && "$rad/bin/oconv" cornell.rad > "$tmp/cornell.oct" &&
    "$rad/bin/rtrace" -h -ab 0 -dj 0 -dt 0 -ss 0 -u- -otvsL "$tmp/cornell.oct" \
        < "$here/cornell_trace.rays" > "$here/cornell_otvsL.txt")

# Golden.TraceFollowsShadowRaysToTheSun: -oTvsL in the daylit room (sun and
# sky) for 11 random rays, each traced by a process of its own, whose trees
# include a shadow ray that reaches the sun (reported as the sun, with -oT)
# and no shadow ray Radiance's obstructor cache would skip (it remembers
# blockers across rays, hence one process per ray). The rays were picked from
# 60 random ones by those two properties.
(cd "$root/scenes/daylit_room" && "$rad/bin/oconv" daylit_room.rad > "$tmp/daylit.oct" &&
    while IFS= read -r ray; do
        echo "$ray" | "$rad/bin/rtrace" -h -ab 0 -dj 0 -dt 0 -ss 0 -u- -oTvsL "$tmp/daylit.oct"
    done < "$here/daylit_sun_trace.rays" > "$here/daylit_sun_oTvsL.txt")

# Golden.CastOnlyOutputMatchesRadiance: every letter that needs no value
# (-oodcLpNswmM~) for the mixed room's 400 rays at -ab 2 with -af. Radiance
# then only intersects the rays (castonly) and leaves the ambient file alone:
# the script stops if it was created.
"$rad/bin/rtrace" -h -oodcLpNswmM~ -ab 2 -af "$tmp/cast.amb" "$tmp/mixed.oct" \
    < "$here/mixed_lengths.rays" > "$here/mixed_cast.txt"
[ ! -e "$tmp/cast.amb" ] || { echo "Radiance made $tmp/cast.amb in cast-only mode" >&2; exit 1; }

# Golden.TraceShowsValuesBeforeTheMedium: -oTvL in a room in fog (-me .1),
# whose lamp shines through a glass pane (fog_trace.rad, its walls from
# genbox): each traced ray's value is reported before the medium acts on it.
"$rad/bin/oconv" "$here/fog_trace.rad" > "$tmp/fog.oct"
"$rad/bin/rtrace" -h -w -me .1 .1 .1 -ab 0 -dj 0 -dt 0 -oTvL "$tmp/fog.oct" \
    < "$here/fog_trace.rays" > "$here/fog_trace_oTvL.txt"
