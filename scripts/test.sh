#!/usr/bin/env bash
# The whole test suite on a fresh machine: installs what is missing, builds
# with ASan+UBSan and warnings as errors, runs every test with ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh sanitize
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
ctest --test-dir build-asan --output-on-failure -j "$(nproc 2>/dev/null || echo 2)"
