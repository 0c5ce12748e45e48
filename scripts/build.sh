#!/usr/bin/env bash
# Configures and builds lazyrad. Usage: scripts/build.sh [release|sanitize|plain]
#   release  (default) build/      Release with profile-guided optimisation, what
#                                  every measurement uses (below)
#   sanitize           build-asan/ AddressSanitizer + UndefinedBehaviorSanitizer,
#                                  warnings as errors (what CI tests)
#   plain              build-plain/ Release without the profile, for quick builds
#
# release is built in three steps: an instrumented rtrace in build-pgo/, the
# training jobs of scripts/pgo-train.sh, which leave their branch and call
# counts in build-pgo/profile/, then build/ compiled with those counts. While
# the instrumented program and the training script are unchanged, the profile
# is kept and build/ is rebuilt incrementally; otherwise both are made anew,
# build/ from scratch (about 4 minutes on 2 cores): use plain while editing.
set -euo pipefail
cd "$(dirname "$0")/.."
kind=${1:-release}
jobs=$(nproc 2>/dev/null || echo 2)
case "$kind" in
  release)
    profile=$PWD/build-pgo/profile
    cmake -S . -B build-pgo -DCMAKE_BUILD_TYPE=Release -DRT_PGO=generate \
          -DRT_PGO_DIR="$profile" -DRT_BUILD_TESTS=OFF -DRT_BUILD_BENCHMARKS=OFF >/dev/null
    cmake --build build-pgo --target rtrace -j "$jobs"
    # A profile is made for one instrumented program and training: rebuilt
    # (and build/ with it) only when either changed. The counts themselves
    # cannot tell: two runs of the same training leave different counts in
    # some files, so they are not compared.
    stamp=$(md5sum build-pgo/bin/rtrace scripts/pgo-train.sh | md5sum)
    if [ ! -d "$profile" ] || [ "$(cat build/pgo-profile.md5 2>/dev/null)" != "$stamp" ]; then
      rm -rf "$profile"  # the counts of a new run are added to any left from before
      scripts/pgo-train.sh build-pgo/bin/rtrace
      rm -f build/pgo-profile.md5
    fi
    cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DRT_PGO=use -DRT_PGO_DIR="$profile" >/dev/null
    # Objects compiled with an older profile: start again.
    [ -f build/pgo-profile.md5 ] || cmake --build build --target clean
    cmake --build build -j "$jobs"
    echo "$stamp" > build/pgo-profile.md5
    ;;
  sanitize)
    cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRT_SANITIZE=ON -DRT_WERROR=ON >/dev/null
    cmake --build build-asan -j "$jobs"
    ;;
  plain)
    cmake -S . -B build-plain -DCMAKE_BUILD_TYPE=Release >/dev/null
    cmake --build build-plain -j "$jobs"
    ;;
  *) echo "build.sh: unknown build kind '$kind' (release, sanitize or plain)" >&2; exit 1 ;;
esac
