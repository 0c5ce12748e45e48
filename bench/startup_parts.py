#!/usr/bin/env python3
"""Where a run's fixed start-up goes: lazyrad's rtrace and Radiance's with no
rays, against three small C programs that isolate what loading and starting
Embree costs by itself (issue 17's fast cornell floor, about 0.12 s, is the
job where this weighs).

  bench/startup_parts.py [-n RUNS] LAZYRAD_RTRACE

The programs, compiled here with the system's cc and Embree:
  empty      a C program that returns at once;
  linked     the same, linked with libembree3 (loaded, relocated and
             initialised by the dynamic loader, with TBB and libstdc++);
  embree     the same, making an Embree device and committing a scene of
             one triangle (what any use of Embree pays before its first ray).
All five run in turn RUNS times (default 60), so that a noisy host slows
them alike; each line gives the minimum and the median wall time of starting
the program and waiting for it (Python's subprocess), in milliseconds.
Radiance's rtrace needs ../shared (skipped without it) and gets an octree
of the same scene made by its own oconv -f.
"""
import argparse
import os
import pathlib
import statistics
import subprocess
import sys
import tempfile
import time

root = pathlib.Path(__file__).resolve().parent.parent
ap = argparse.ArgumentParser()
ap.add_argument("-n", type=int, default=60, help="runs per program")
ap.add_argument("rtrace", help="lazyrad's rtrace")
args = ap.parse_args()

EMBREE = r"""
#include <embree3/rtcore.h>
int main(void) {
    RTCDevice d = rtcNewDevice(0);
    RTCScene s = rtcNewScene(d);
    RTCGeometry g = rtcNewGeometry(d, RTC_GEOMETRY_TYPE_TRIANGLE);
    float* v = (float*)rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0,
                                               RTC_FORMAT_FLOAT3, 12, 3);
    unsigned* i = (unsigned*)rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0,
                                                     RTC_FORMAT_UINT3, 12, 1);
    for (int k = 0; k < 9; ++k) v[k] = (k == 3 || k == 7) ? 1.0f : 0.0f;
    i[0] = 0; i[1] = 1; i[2] = 2;
    rtcCommitGeometry(g);
    rtcAttachGeometry(s, g);
    rtcReleaseGeometry(g);
    rtcCommitScene(s);
    rtcReleaseScene(s);
    rtcReleaseDevice(d);
    return 0;
}
"""
opts = "-h -I -ab 2 -ad 256 -as 128 -aa .2 -ar 64".split()
scene = root / "scenes/cornell/cornell.rad"

with tempfile.TemporaryDirectory() as tmp:
    tmp = pathlib.Path(tmp)
    (tmp / "empty.c").write_text("int main(void) { return 0; }\n")
    (tmp / "embree.c").write_text(EMBREE)
    cc = os.environ.get("CC", "cc")
    build = [
        [cc, "-O2", str(tmp / "empty.c"), "-o", str(tmp / "empty")],
        # --no-as-needed: keep the library although nothing calls it.
        [cc, "-O2", str(tmp / "empty.c"), "-o", str(tmp / "linked"),
         "-Wl,--no-as-needed", "-lembree3"],
        [cc, "-O2", str(tmp / "embree.c"), "-o", str(tmp / "embree"), "-lembree3"],
    ]
    for command in build:
        subprocess.run(command, check=True)
    programs = {
        "empty C program": [str(tmp / "empty")],
        "C program linked with Embree, no call": [str(tmp / "linked")],
        "C program: Embree device and a one-triangle scene": [str(tmp / "embree")],
        "lazyrad rtrace, no rays": [args.rtrace, *opts, str(scene)],
    }
    radiance = root / "../shared/reference/radiance-5.4a/bin"
    if (radiance / "rtrace").exists():
        env = dict(os.environ, RAYPATH=f".:{radiance.parent / 'lib'}")
        octree = tmp / "cornell.oct"
        with open(octree, "wb") as out:
            subprocess.run([str(radiance / "oconv"), "-f", str(scene)], stdout=out,
                           check=True, env=env)
        programs["Radiance rtrace, no rays"] = [str(radiance / "rtrace"), *opts, str(octree)]
    else:
        print("startup_parts.py: no ../shared: Radiance skipped", file=sys.stderr)
    times = {name: [] for name in programs}
    for _ in range(args.n):
        for name, command in programs.items():
            start = time.perf_counter()
            subprocess.run(command, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                           check=True)
            times[name].append(time.perf_counter() - start)
    for name, t in times.items():
        print(f"{name}: min {min(t) * 1e3:.2f} ms, median {statistics.median(t) * 1e3:.2f} ms")
