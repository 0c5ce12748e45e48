#!/usr/bin/env bash
# Radiance 5.4a's answers for the prism tests (Golden.PrismsRedirectAsRadiance
# and Golden.PrismIndirectAsRadiance). The tests read the committed *.txt; this
# script is for a developer who has Radiance at hand.
#
#   tests/data/prism/make_refs.sh [radiance-dir]
#
# room.rad: a closed room with a lamp above a prism2 panel, a spotlight above a
# turned prism1 ring and a mirror: room.pts are 96 floor sensors and 168 on the
# ceiling and a wall (-I), room.rays 200 random rays from inside the room
# (-ovRX). sun.rad: the sun through a tilted prism2 panel, 100 ground sensors,
# with virtual sources (-dr 2) and without (-dr 0: the panel blocks the sun).
# sun_mirror.rad: the same with a mirror wall, 192 sensors (sun_mirror.pts) at
# -dr 1 and -dr 2, where the sun off the mirror through the prism (an image of
# an image) lights 24 of them. All at -ab 0 -dj 0 -dt 0 -ss 0, where both
# programs' answers are fixed. sun_illum.rad: the panel an illum with the
# prism2 as its alternate, which relays the sun as the prism does.
# room_ab1.txt: the room's 96 floor sensors at -ab 1 -aa .1 -ad 1024 -as 256
# -ar 64, whose mean the indirect test compares (Radiance's own mean moves by
# about 0.2 % from one run of this script to the next: 0.13936-0.13974).
# room_inst.rad: the room with its panel as an octree instance
# (inst_panel.oct, made here and committed), the floor sensors (-I) and the
# random rays (-ov).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
source "$here/../radiance_refs.sh"
export RAYPATH=".:$rad/lib"
"$rad/bin/oconv" room.rad > "$tmp/room.oct"
"$rad/bin/oconv" sun.rad > "$tmp/sun.oct"
fixed="-h -ab 0 -dj 0 -dt 0 -ss 0"
"$rad/bin/rtrace" $fixed -I "$tmp/room.oct" < room.pts > room_I.txt 2>/dev/null
"$rad/bin/rtrace" $fixed -ovRX "$tmp/room.oct" < room.rays > room_ovRX.txt 2>/dev/null
for dr in 2 0; do
    "$rad/bin/rtrace" $fixed -dr $dr -I "$tmp/sun.oct" < sun.pts > "sun_I_dr$dr.txt" 2>/dev/null
done
"$rad/bin/oconv" sun_mirror.rad > "$tmp/sun_mirror.oct"
for dr in 1 2; do
    "$rad/bin/rtrace" $fixed -dr $dr -I "$tmp/sun_mirror.oct" < sun_mirror.pts \
        > "sun_mirror_I_dr$dr.txt" 2>/dev/null
done
"$rad/bin/oconv" sun_illum.rad > "$tmp/sun_illum.oct"
"$rad/bin/rtrace" $fixed -I "$tmp/sun_illum.oct" < sun.pts > sun_illum_I.txt 2>/dev/null
head -96 room.pts | "$rad/bin/rtrace" -h -I -ab 1 -aa .1 -ad 1024 -as 256 -ar 64 "$tmp/room.oct" \
    > room_ab1.txt 2>/dev/null
"$rad/bin/oconv" inst_panel.rad > inst_panel.oct
"$rad/bin/oconv" room_inst.rad > "$tmp/room_inst.oct"
head -96 room.pts | "$rad/bin/rtrace" $fixed -I "$tmp/room_inst.oct" > room_inst_I.txt 2>/dev/null
"$rad/bin/rtrace" $fixed -ov "$tmp/room_inst.oct" < room.rays > room_inst_ov.txt 2>/dev/null
