#!/usr/bin/env bash
# Runs one libFuzzer target for SECONDS, then minimises what it found back into the
# committed corpus (tests/fuzz/corpus/TARGET, -merge=1, see below). Crashes land in
# build-fuzz/artifacts/TARGET/; replay one with build-fuzz/bin/fuzz_TARGET FILE and,
# once fixed, copy it to tests/fuzz/regressions/TARGET/.
#
#   scripts/fuzz.sh scene|rays|ambfile|cal|octree|mesh|datafile|bsdf|font|picture|view|options|exr|rvimage SECONDS
#
# Environment: BUILD (default build-fuzz), RT_FUZZ_MERGE=0 skips the final merge,
# extra libFuzzer flags in FUZZ_FLAGS.
set -euo pipefail
target=${1:?usage: fuzz.sh scene|rays|ambfile|cal|octree|mesh|datafile|bsdf|font|picture|view|options|exr|rvimage SECONDS}
seconds=${2:?usage: fuzz.sh scene|rays|ambfile|cal|octree|mesh|datafile|bsdf|font|picture|view|options|exr|rvimage SECONDS}
root=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD:-$root/build-fuzz}
case $target in
  scene) max_len=4096; keep_len=1024; extra=(-dict="$root/tests/fuzz/scene.dict") ;;
  rays) max_len=4096; keep_len=512; extra=() ;;
  ambfile) max_len=65536; keep_len=2048; extra=() ;;
  cal) max_len=2048; keep_len=512; extra=() ;;
  octree) max_len=16384; keep_len=4096; extra=() ;;
  mesh) max_len=32768; keep_len=4096; extra=() ;;
  datafile) max_len=4096; keep_len=1024; extra=() ;;
  bsdf) max_len=16384; keep_len=4096; extra=() ;;
  font) max_len=4096; keep_len=1024; extra=() ;;
  picture) max_len=4096; keep_len=1024; extra=() ;;
  view) max_len=1024; keep_len=512; extra=() ;;
  options) max_len=1024; keep_len=512; extra=() ;;
  exr) max_len=8192; keep_len=2048; extra=() ;;
  rvimage) max_len=1024; keep_len=512; extra=() ;;
  *) echo "fuzz.sh: unknown target $target (scene, rays, ambfile, cal, octree, mesh, datafile, bsdf, font, picture, view, options, exr, rvimage)" >&2; exit 2 ;;
esac

if [[ ! -f $build/CMakeCache.txt ]]; then
  CC=clang CXX=clang++ cmake -S "$root" -B "$build" -DRT_FUZZ=ON \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRT_BUILD_BENCHMARKS=OFF
fi
cmake --build "$build" -j"$(nproc)" --target "fuzz_$target"

corpus=$root/tests/fuzz/corpus/$target
work=$build/corpus/$target
artifacts=$build/artifacts/$target
mkdir -p "$work" "$artifacts"
log=$build/fuzz-$target.log
echo "fuzz.sh: fuzz_$target for ${seconds}s, log $log"
status=0
"$build/bin/fuzz_$target" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
  -max_len="$max_len" -print_final_stats=1 -artifact_prefix="$artifacts/" \
  "${extra[@]}" ${FUZZ_FLAGS:-} "$work" "$corpus" > "$log" 2>&1 || status=$?
grep -E "^#[0-9]+[[:space:]]+DONE|ERROR|SUMMARY|stat::|Test unit written" "$log" || true

if [[ ${RT_FUZZ_MERGE:-1} != 0 ]]; then
  # Minimise into the committed corpus: hand-written seeds (readable names) stay,
  # libFuzzer's files (named by their SHA-1) are replaced by the merge, which keeps
  # only inputs that add coverage, cut to $keep_len bytes to keep the repository small.
  merged=$build/corpus/$target.merged
  rm -rf "$merged" && mkdir -p "$merged"
  "$build/bin/fuzz_$target" -merge=1 -max_len="$keep_len" -timeout=10 -rss_limit_mb=2048 \
    "$merged" "$corpus" "$work" > "$build/merge-$target.log" 2>&1
  find "$corpus" -maxdepth 1 -type f -regextype posix-extended -regex '.*/[0-9a-f]{40}' -delete
  cp "$merged"/* "$corpus"/
  for seed in "$corpus"/*; do  # drop the merge's copy of a seed
    [[ -f $seed ]] || continue
    sha=$(sha1sum "$seed" | cut -d' ' -f1)
    if [[ $(basename "$seed") != "$sha" && -f $corpus/$sha ]]; then rm -f "$corpus/$sha"; fi
  done
  echo "fuzz.sh: corpus $corpus: $(ls "$corpus" | wc -l) files, $(cat "$corpus"/* | wc -c) bytes"
fi
exit "$status"
