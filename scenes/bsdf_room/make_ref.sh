#!/usr/bin/env bash
# Converged -ab 2 irradiance at grid.pts with REAL Radiance 5.4a under each
# sky, as ../df_room's reference is made (scenes/README.md): the mean of N
# independent path-traced estimates per point (-aa 0 -ad 1 -as 0 -lw 1e-9
# -u+), in chunks. Writes ref/grid_I_ab2_SKY.txt: r g b rel_stderr (green).
# A developer's tool; nothing in the build or tests runs it.
#   scenes/bsdf_room/make_ref.sh SKY [PATHS_PER_POINT] [RADIANCE_DIR]
#   (SKY: sky for the overcast sky.rad, sun_sky for sun_sky.rad)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
sky=${1:?usage: make_ref.sh sky|sun_sky [PATHS] [RADIANCE_DIR]}
n=${2:-1000000}
rad=${3:-$here/../../../shared/reference/radiance-5.4a}
export PATH=$rad/bin:$PATH RAYPATH=.:$rad/lib
cd "$here"
mkdir -p ref
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
oconv "$sky.rad" room.rad > "$tmp/room.oct"
# Radiance seeds -u+ from the clock in seconds: chunks must start in different
# seconds, or they repeat each other's random numbers.
chunk=20000
python3 - "$tmp" "$n" "$chunk" "$sky" <<'PY'
import math, subprocess, sys, time
tmp, n, chunk, sky = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), sys.argv[4]
pts = [l for l in open("grid.pts").read().splitlines() if l.strip()]
s = [[0.0] * 3 for _ in pts]; s2 = [0.0] * len(pts); done = 0
while done < n:
    k = min(chunk, n - done)
    start = time.time()
    inp = "".join((p + "\n") * k for p in pts)
    out = subprocess.run(["rtrace", "-h", "-I", "-ab", "2", "-aa", "0", "-ad", "1", "-as", "0",
                          "-lw", "1e-9", "-u+", f"{tmp}/room.oct"], input=inp, text=True,
                         capture_output=True, check=True).stdout.split("\n")
    for i in range(len(pts)):
        for j in range(k):
            v = [float(x) for x in out[i * k + j].split()]
            for c in range(3): s[i][c] += v[c]
            s2[i] += v[1] * v[1]
    done += k
    time.sleep(max(0.0, 1.1 - (time.time() - start)))
with open(f"ref/grid_I_ab2_{sky}.txt", "w") as f:
    for i in range(len(pts)):
        m = [x / n for x in s[i]]
        var = max(0.0, s2[i] / n - m[1] * m[1])
        f.write("%.6e %.6e %.6e %.4e\n" % (m[0], m[1], m[2], math.sqrt(var / n) / m[1]))
PY
