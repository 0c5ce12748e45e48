#!/usr/bin/env bash
# Converged -I -ab 1 irradiance of sensors.pts under every sky of skies.txt,
# with REAL Radiance 5.4a, for tests/golden/sky_test.cpp. Each sky is the
# generator's output plus the glow hemispheres a daylighting tool adds; the
# sun, where there is one, is a direct source and the sky one bounce.
# Writes
#   ref.txt             name sensor r g b rel_stderr (of the green channel)
#   radiance_skies.txt  Radiance's gensky/gendaylit output for each sky, which
#                       lazyrad's bundled generators must reproduce byte for byte
# A developer's tool; nothing in the build or tests runs it.
#   tests/data/sky/make_ref.sh [RADIANCE_DIR]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
rad=${1:-$here/../../../../shared/reference/radiance-5.4a}
export PATH=$rad/bin:$PATH RAYPATH=.:$rad/lib
cd "$here"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
python3 - "$tmp" <<'PY'
import math, subprocess, sys, time
tmp = sys.argv[1]
# Each estimate is one -ad DIVISIONS stratified sample of the hemisphere; the
# mean of RUNS x REPEATS independent estimates is the reference and their
# spread its standard error.
DIVISIONS, REPEATS, RUNS = 65536, 8, 4
hemispheres = ("skyfunc glow sky_glow 0 0 4 1 1 1 0\nsky_glow source sky 0 0 4 0 0 1 180\n"
               "skyfunc glow ground_glow 0 0 4 1 1 1 0\n"
               "ground_glow source ground 0 0 4 0 0 -1 180\n")
skies = [l.split(None, 1) for l in open("skies.txt") if l.strip() and not l.startswith("#")]
sensors = [l for l in open("sensors.pts").read().splitlines() if l.strip()]
gen_out, ref = [], []
for name, command in skies:
    command = command.strip()
    gen_out.append(f"=== {name}\n" + subprocess.run(command.split(), capture_output=True,
                                                     text=True, check=True).stdout)
    with open(f"{tmp}/sky.rad", "w") as f:
        f.write(f"!{command}\n" + hemispheres)
    with open(f"{tmp}/sky.oct", "wb") as f:
        subprocess.run(["oconv", f"{tmp}/sky.rad"], stdout=f, check=True)
    est = [[] for _ in sensors]
    for run in range(RUNS):
        # Radiance seeds -u+ from the clock in seconds: runs must start in
        # different seconds, or they repeat each other's random numbers.
        start = time.time()
        inp = "".join((s + "\n") * REPEATS for s in sensors)
        out = subprocess.run(["rtrace", "-h", "-I", "-ab", "1", "-aa", "0", "-ad", str(DIVISIONS),
                              "-as", "0", "-lw", "1e-9", "-u+", f"{tmp}/sky.oct"], input=inp,
                             text=True, capture_output=True, check=True).stdout.split("\n")
        for i in range(len(sensors)):
            for j in range(REPEATS):
                est[i].append([float(x) for x in out[i * REPEATS + j].split()])
        time.sleep(max(0.0, 1.1 - (time.time() - start)))
    for i, e in enumerate(est):
        n = len(e)
        m = [sum(v[c] for v in e) / n for c in range(3)]
        var = sum((v[1] - m[1]) ** 2 for v in e) / (n - 1)
        rel = math.sqrt(var / n) / m[1] if m[1] > 0 else 0.0
        ref.append("%s %d %.7e %.7e %.7e %.3e\n" % (name, i, m[0], m[1], m[2], rel))
        print(ref[-1], end="", flush=True)
with open("ref.txt", "w") as f:
    f.write("# name sensor(line of sensors.pts) r g b rel_stderr; real Radiance 5.4a "
            f"rtrace -I -ab 1 -aa 0 -ad {DIVISIONS} -as 0 -lw 1e-9 -u+, mean of "
            f"{RUNS * REPEATS} estimates (make_ref.sh)\n")
    f.writelines(ref)
with open("radiance_skies.txt", "w") as f:
    f.writelines(gen_out)
PY
