#!/usr/bin/env bash
# Configures and builds lazyrad. Usage: scripts/build.sh [release|sanitize]
#   release  (default) build/      Release, what every measurement uses
#   sanitize           build-asan/ AddressSanitizer + UndefinedBehaviorSanitizer,
#                                  warnings as errors (what CI tests)
set -euo pipefail
cd "$(dirname "$0")/.."
kind=${1:-release}
jobs=$(nproc 2>/dev/null || echo 2)
case "$kind" in
  release)  dir=build;      flags=(-DCMAKE_BUILD_TYPE=Release) ;;
  sanitize) dir=build-asan; flags=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DRT_SANITIZE=ON -DRT_WERROR=ON) ;;
  *) echo "build.sh: unknown build kind '$kind' (release or sanitize)" >&2; exit 1 ;;
esac
cmake -S . -B "$dir" "${flags[@]}" >/dev/null
cmake --build "$dir" -j "$jobs"
