#!/usr/bin/env bash
# Converged reference values by brute-force path tracing through lazyrad itself:
# no cache, one sample per bounce (-aa 0 -ad 1 -as 0 -lw 1e-9), many independent
# repetitions of every input line, on all cores.
#
#   bench/reference.sh [options] SCENE.rad POINTS > REF.txt
#     -r PATH       rtrace to use (default build/bin/rtrace)
#     -p N          paths per input line (default 100000)
#     -b N          repetitions per rtrace process (default 2000; rounded so p = k*b)
#     -j N          parallel processes (default: nproc)
#     -s N          first seed (default 1000); batch k uses seed s+k
#     -o "OPTS"     rtrace options that define the quantity, e.g. "-I -ab 2"
#                   (default "-I -ab 2"); the path-tracing options are appended
#
# Output: one line per input line, "r g b rel_stderr" (%e), the format of the
# Radiance references in scenes/*/ref/: the mean of all estimates, and the
# standard error of the green channel's mean divided by that mean. Statistics
# (luminance RMS of rel_stderr, paths, seconds) go to stderr.
#
# Why repeated lines: with -u+ (the default) every input line has its own random
# stream, seeded by -seed and its position in the input, so N copies of a point
# are N independent estimates; a batch is one rtrace process with its own seed.
set -euo pipefail
cd "$(dirname "$0")/.."
rtrace=build/bin/rtrace paths=100000 batch=2000 jobs=$(nproc 2>/dev/null || echo 2)
seed=1000 opts="-I -ab 2"
while getopts "r:p:b:j:s:o:" flag; do
  case $flag in
    r) rtrace=$OPTARG ;; p) paths=$OPTARG ;; b) batch=$OPTARG ;; j) jobs=$OPTARG ;;
    s) seed=$OPTARG ;; o) opts=$OPTARG ;;
    *) sed -n '2,20p' "$0" >&2; exit 2 ;;
  esac
done
shift $((OPTIND - 1))
[ $# -eq 2 ] || { sed -n '2,20p' "$0" >&2; exit 2; }
scene=$1 points=$2
[ -x "$rtrace" ] || { echo "reference: no $rtrace (scripts/build.sh release)" >&2; exit 1; }
[ "$batch" -le "$paths" ] || batch=$paths
batches=$(( (paths + batch - 1) / batch ))

tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
awk -v b="$batch" '{ for (i = 0; i < b; i++) print }' "$points" > "$tmp/input"
start=$(date +%s.%N)

# One worker: batches k = w, w+jobs, ...; each writes per-line partial sums
# n, Σr, Σg, Σb, Σg² (in double, by awk).
worker() {
  local w=$1 k
  for ((k = w; k < batches; k += jobs)); do
    # shellcheck disable=SC2086
    "$rtrace" -h -w $opts -aa 0 -ad 1 -as 0 -lw 1e-9 -seed $((seed + k)) "$scene" \
        < "$tmp/input" |
      awk -v b="$batch" '{ i = int((NR - 1) / b); n[i]++; r[i] += $1; g[i] += $2; bl[i] += $3
                           g2[i] += $2 * $2; if (i + 1 > m) m = i + 1 }
        END { for (i = 0; i < m; i++) printf "%d %d %.17g %.17g %.17g %.17g\n", i, n[i], r[i], g[i], bl[i], g2[i] }' \
        > "$tmp/part.$k"
  done
}
for ((w = 0; w < jobs; w++)); do worker "$w" & done
wait

end=$(date +%s.%N)
cat "$tmp"/part.* | awk -v secs="$(awk -v a="$start" -v b="$end" 'BEGIN { print b - a }')" '
  { i = $1; n[i] += $2; r[i] += $3; g[i] += $4; b[i] += $5; g2[i] += $6; if (i + 1 > m) m = i + 1 }
  END {
    for (i = 0; i < m; i++) {
      mr = r[i] / n[i]; mg = g[i] / n[i]; mb = b[i] / n[i]
      var = (g2[i] - n[i] * mg * mg) / (n[i] - 1); if (var < 0) var = 0
      rel = mg > 0 ? sqrt(var / n[i]) / mg : 0
      printf "%e %e %e %.3e\n", mr, mg, mb, rel
      s += rel * rel
    }
    printf "reference: %d lines, %d paths each, RMS rel_stderr %.3f%%, %.1f s\n",
           m, n[0], 100 * sqrt(s / m), secs > "/dev/stderr"
  }'
