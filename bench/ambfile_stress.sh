#!/usr/bin/env bash
# The shared-ambient-file stress test at full size (issue 18): 32 writer
# processes appending to one file at a time, 224 over a run with 400 records
# each, SIGKILLs at random moments (20 a second) and 5 % of appends stopping
# short (half failing as a full disk, half killing the writer mid-record).
# Every record a writer synced must be in the file once and every record must
# pass Radiance's validity rules; ctest runs the same test small
# (tests/ambfiles/stress_test.cpp).
#
#   bench/ambfile_stress.sh [RUNS] [BUILD]     (default 3 runs, build/)
#
# Each run prints one line; the exit status is 1 if any run failed. Sizes can
# be changed with CONCURRENT, WRITERS, RECORDS, KILLS, SHORT (environment).
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-3}
build=${2:-build}
tool=$build/bin/ambfile_stress
if [[ ! -x $tool ]]; then
  cmake --build "$build" --target ambfile_stress >/dev/null
fi
dir=$(mktemp -d); trap 'rm -rf "$dir"' EXIT
status=0
for ((i = 1; i <= runs; i++)); do
  rm -rf "${dir:?}"/*
  "$tool" "$dir" "${CONCURRENT:-32}" "${WRITERS:-224}" "${RECORDS:-400}" "${KILLS:-20}" \
    "${SHORT:-0.05}" "$i" || status=1
done
exit $status
