#!/usr/bin/env bash
# Converged -ab 2 irradiance at workplane.pts under two gensky skies, with REAL
# Radiance 5.4a, as the other scenes' references are made (scenes/README.md):
# the room of daylit_room.rad without its own sky and sun (its first 25 lines),
# under sky_gensky_c.rad (`gensky -ang 42.8 -15.9 -c -B 100`) or
# sky_gensky_s.rad (`+s`, the sun near the scene's own sun), each with the
# glow hemispheres a daylighting tool adds. The mean of N independent
# path-traced estimates per point (-aa 0 -ad 1 -as 0 -lw 1e-9 -u+), in chunks;
# Radiance's rcalc and total sum each point's chunk.
# Writes ref/workplane_I_ab2_gensky_<sky>.txt: r g b rel_stderr (green
# channel). A developer's tool; nothing in the build or tests runs it.
#   scenes/daylit_room/make_sky_refs.sh [PATHS_PER_POINT] [SKIES] [RADIANCE_DIR]
# SKIES is "c s" (default) or either one.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
n=${1:-400000}
skies=${2:-c s}
rad=${3:-$here/../../../shared/reference/radiance-5.4a}
export PATH=$rad/bin:$PATH RAYPATH=.:$rad/lib
cd "$here"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
tail -n +26 daylit_room.rad > "$tmp/room_only.rad"
for sky in $skies; do
  oconv -f "sky_gensky_$sky.rad" "$tmp/room_only.rad" > "$tmp/room_$sky.oct"
done
chunk=20000
python3 - "$tmp" "$n" "$chunk" "$skies" <<'PY'
import math, subprocess, sys, time
tmp, n, chunk, skies = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), sys.argv[4].split()
pts = [l for l in open("workplane.pts").read().splitlines() if l.strip()]
for sky in skies:
    s = [[0.0] * 3 for _ in pts]; s2 = [0.0] * len(pts); done = 0
    while done < n:
        k = min(chunk, n - done)
        start = time.time()
        with open(f"{tmp}/in", "w") as f:
            f.write("".join((p + "\n") * k for p in pts))
        # Per point: the sums of r, g, b and of g squared over its k paths.
        sums = subprocess.run(
            f"rtrace -h -I -ab 2 -aa 0 -ad 1 -as 0 -lw 1e-9 -u+ {tmp}/room_{sky}.oct < {tmp}/in"
            f" | rcalc -e '$1=$1;$2=$2;$3=$3;$4=$2*$2' | total -{k}", shell=True, text=True,
            capture_output=True, check=True).stdout.split("\n")
        for i in range(len(pts)):
            v = [float(x) for x in sums[i].split()]
            for c in range(3): s[i][c] += v[c]
            s2[i] += v[3]
        done += k
        print(f"{sky}: {done}/{n}", file=sys.stderr, flush=True)
        # Radiance seeds -u+ from the clock in seconds: chunks must start in
        # different seconds, or they repeat each other's random numbers.
        time.sleep(max(0.0, 1.1 - (time.time() - start)))
    with open(f"ref/workplane_I_ab2_gensky_{sky}.txt", "w") as f:
        for i in range(len(pts)):
            m = [x / n for x in s[i]]
            var = max(0.0, s2[i] / n - m[1] * m[1])
            f.write("%.6e %.6e %.6e %.4e\n" % (m[0], m[1], m[2], math.sqrt(var / n) / m[1]))
PY
