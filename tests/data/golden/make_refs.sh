#!/usr/bin/env bash
# Makes the Radiance pictures that tests/rvimage/golden_image_test.cpp compares
# rvimage with, using real Radiance 5.4a. The test only reads the committed
# .hdr files; this script is for a developer who has Radiance at hand.
#
#   tests/data/golden/make_refs.sh [radiance-dir] [paths-cornell] [paths-daylit]
#
# radiance-dir defaults to ../shared/reference/radiance-5.4a beside the
# repository (its bin/ and lib/). The two counts are the paths per pixel of the
# converged pictures (the defaults made the committed ones).
#
# Pictures, 64 pixels across, rays from `vwrays -ff -vf <scene>.vf`, the
# picture square-pixelled as vwrays -d says (cornell 64x64, daylit_room 64x48):
# - <scene>_ab0.hdr: rtrace -ab 0, everything else default. Deterministic.
# - cornell_ab1.hdr, daylit_room_ab2.hdr: the converged answer with 1 and 2
#   bounces. Each pixel is the mean of N independent path-traced estimates
#   (-aa 0 -ad 1 -as 0 -lw 1e-9 -u+: no cache, one sample per hemisphere, no
#   weight cut-off), the method of scenes/*/ref/*_I_abN.txt. Radiance's own
#   cached picture at any setting is a noisy, biased estimate of this. The
#   header records N and the per-pixel relative standard error of the mean
#   (green channel), its RMS and maximum over the pixels brighter than 1 % of
#   the picture's mean luminance (the floor of image/compare.h).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../../.." && pwd)"
rad="${1:-$root/../shared/reference/radiance-5.4a}"
pathsCornell="${2:-65536}"
pathsDaylit="${3:-131072}"
[ -x "$rad/bin/rtrace" ] || { echo "no Radiance in $rad" >&2; exit 1; }
export PATH="$rad/bin:$PATH" RAYPATH=".:$rad/lib"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT

# Direct light only.
direct() {  # scene
    local scene="$1" res
    (cd "$root/scenes/$scene" && oconv -f "$scene.rad" > "$tmp/$scene.oct")
    res=$(vwrays -d -x 64 -y 64 -vf "$root/scenes/$scene/$scene.vf")
    vwrays -ff -x 64 -y 64 -vf "$root/scenes/$scene/$scene.vf" |
        rtrace -ffc $res -ab 0 "$tmp/$scene.oct" > "$here/${scene}_ab0.hdr"
    echo "${scene}_ab0.hdr: $res"
}

# Converged: the mean of `paths` path-traced estimates per pixel.
converged() {  # scene bounces paths
    local scene="$1" ab="$2" n="$3" res w h out
    out="$here/${scene}_ab${ab}.hdr"
    (cd "$root/scenes/$scene" && oconv -f "$scene.rad" > "$tmp/$scene.oct")
    res=$(vwrays -d -x 64 -y 64 -vf "$root/scenes/$scene/$scene.vf")
    w=$(echo "$res" | awk '{print $2}')
    h=$(echo "$res" | awk '{print $4}')
    # The mean squares come from a second `total` reading a copy of the stream.
    mkfifo "$tmp/$scene.fifo"
    total -if3 -m -s2 -"$n" < "$tmp/$scene.fifo" > "$tmp/$scene.rms" &
    local squares=$!
    vwrays -ff -c "$n" -x 64 -y 64 -vf "$root/scenes/$scene/$scene.vf" |
        rtrace -fff -h -ab "$ab" -aa 0 -ad 1 -as 0 -lw 1e-9 -u+ "$tmp/$scene.oct" |
        tee "$tmp/$scene.fifo" | total -if3 -m -"$n" > "$tmp/$scene.mean"
    wait "$squares"
    # total -m -s2 prints sqrt(mean of squares). The standard error of the mean
    # is taken on the green channel, as in scenes/*/ref/, over the pixels whose
    # luminance (Radiance's bright()) is above the comparison floor.
    local stats
    stats=$(paste "$tmp/$scene.mean" "$tmp/$scene.rms" | awk -v n="$n" '
        { y[NR] = 0.265074126*$1 + 0.670114631*$2 + 0.064811243*$3; s += y[NR]
          v = $5*$5 - $2*$2; if (v < 0) v = 0
          r[NR] = $2 > 0 ? sqrt(v / (n - 1)) / $2 : 0 }
        END { floor = 0.01 * s / NR
              for (i = 1; i <= NR; i++) if (y[i] > floor) {
                  ss += r[i]*r[i]; k++; if (r[i] > mx) mx = r[i] }
              printf "%.3g %.3g %d", sqrt(ss / k), mx, k }')
    pvalue -r -h -H -d -y "$h" +x "$w" < "$tmp/$scene.mean" |
        getinfo -a "vwrays -ff -c $n -x 64 -y 64 -vf $scene.vf | rtrace -fff -h -ab $ab -aa 0 -ad 1 -as 0 -lw 1e-9 -u+ $scene.oct | total -if3 -m -$n" \
                   "paths per pixel: $n; relative standard error (green), over $(echo "$stats" | awk '{print $3}') pixels above 1 % of the mean: RMS $(echo "$stats" | awk '{print $1}'), max $(echo "$stats" | awk '{print $2}')" \
            > "$out"
    echo "${scene}_ab${ab}.hdr: $res, $n paths per pixel, relative standard error RMS/max: $stats"
}

direct cornell
direct daylit_room
converged cornell 1 "$pathsCornell" &
converged daylit_room 2 "$pathsDaylit" &
wait
