#!/usr/bin/env bash
# Radiance 5.4a's answers for two golden tests of its shading rules. The tests
# read the committed *.txt; this script is for a developer who has Radiance at
# hand.
#
#   tests/data/shading_rules/make_refs.sh [radiance-dir]
#
# Golden.TransBackFacesFollowBv: a `trans` polygon seen from its back
# (view.rays: the first ray meets the back, the second the front) and a sensor
# lit through one trans polygon's front and another's back (shadow.pts, -I),
# each at -bv+ and -bv-. With -bv- Radiance 5.4a passes rays through a trans
# back face as through any other material.
#
# Golden.InvisibleSourcesFollowRadiance: -ovW at -dv+ and -dv- for a glow of
# radius 2 seen directly and through a glass pane (with -dv- Radiance counts
# the whole primary path's length against the radius), and a light polygon
# from the front and the back (with -dv- both give no light and a zero
# coefficient W).
#
# Golden.MediumLowersSourcePartitionWeight: -ov at -ab 0 -dj 0 -dt 0 -ss 0 for
# 60 random rays in the cornell box inside a global medium (-me .05 -ma .8
# -mg .5): Radiance divides the lamp for the shadow rays' weight, which the
# viewing ray's path through the medium lowers.
#
# Golden.ShadowRaysAreNeverCut: a sensor lit through a glass pane at the
# default limits, with -lw .95 -lr 10 (the transmitted shadow ray's weight,
# .88, below -lw) and with -lw .95 -lr -10 (Russian roulette): Radiance
# follows a shadow ray and its children whatever their weight.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
source "$here/../radiance_refs.sh"
for bv in + -; do
    for scene in trans_view trans_rough_view; do
        "$rad/bin/oconv" "$scene.rad" > "$tmp/$scene.oct"
        "$rad/bin/rtrace" -h -ab 0 -dj 0 -ss 0 -bv$bv -ov "$tmp/$scene.oct" < view.rays \
            > "${scene}_bv$bv.txt"
    done
    "$rad/bin/oconv" trans_shadow.rad > "$tmp/trans_shadow.oct"
    "$rad/bin/rtrace" -h -I -ab 0 -dj 0 -bv$bv -ov "$tmp/trans_shadow.oct" < shadow.pts \
        > "trans_shadow_bv$bv.txt"
done
"$rad/bin/oconv" glow_through_glass.rad > "$tmp/glow.oct"
for dv in + -; do
    "$rad/bin/rtrace" -h -ab 0 -dv$dv -ovW "$tmp/glow.oct" < glow_rays.txt 2>/dev/null \
        > "glow_ovW_dv$dv.txt"
done
(cd "$here/../../../scenes/cornell" && "$rad/bin/oconv" cornell.rad > "$tmp/cornell.oct" &&
    "$rad/bin/rtrace" -h -ab 0 -dj 0 -dt 0 -ss 0 -me .05 .05 .05 -ma .8 .8 .8 -mg .5 -ov \
        "$tmp/cornell.oct" < "$here/medium_rays.txt" > "$here/medium_ov.txt")
"$rad/bin/oconv" shadow_commitment.rad > "$tmp/commit.oct"
for limits in "" "-lw .95 -lr 10" "-lw .95 -lr -10"; do
    echo "0 0 0 0 0 1" | "$rad/bin/rtrace" -h -I -ab 0 $limits "$tmp/commit.oct"
done > shadow_commitment.txt
