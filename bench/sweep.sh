#!/usr/bin/env bash
# Error against time for a list of rtrace settings on one scene.
#
#   bench/sweep.sh [-r rtrace] [-k runs] [-t title] [-o prefix] \
#       SCENE.rad POINTS REF.txt "COMMON OPTIONS" SETTINGS
#
#   -r  rtrace to run (default build/bin/rtrace)
#   -k  runs per setting (default 2, at least 2): seeds 1..k; the time kept is the
#       minimum over the runs (the machine is shared, so timings are noisy)
#   -t  title of the table and plot (default: the scene file name)
#   -o  output prefix (default docs/data/NAME): writes PREFIX.csv, PREFIX.md and
#       PREFIX.svg, or docs/plots/NAME.svg when PREFIX is docs/data/NAME
#
# SETTINGS has one setting per line, "METHOD OPTIONS..."; METHOD names the curve
# the point belongs to; '#' starts a comment. The pseudo-option "-spp K" means
# pure path tracing: -aa 0 -ad 1 -as 0 -lw 1e-9 with every input line repeated
# K times and the K estimates averaged (K independent paths per point).
#
# Per setting the CSV has: relative RMS error, max |relative error| and bias
# (mean relative error), all of luminance (0.265 R + 0.670 G + 0.065 B) against
# REF ("r g b rel_stderr" per line, as scenes/*/ref/) in %; the errors are the
# RMS over the k runs (max: the largest), bias their mean. Then the minimum wall
# time, every run's time, records created, rays traced and shadow rays (from
# rtrace -t, first run). The reference's own noise (RMS of rel_stderr) is the
# floor under every RMS error; it is printed in the table and drawn in the plot.
set -euo pipefail
cd "$(dirname "$0")/.."
rtrace=build/bin/rtrace runs=2 title="" prefix=""
while getopts "r:k:t:o:" flag; do
  case $flag in
    r) rtrace=$OPTARG ;; k) runs=$OPTARG ;; t) title=$OPTARG ;; o) prefix=$OPTARG ;;
    *) sed -n '2,26p' "$0" >&2; exit 2 ;;
  esac
done
shift $((OPTIND - 1))
[ $# -eq 5 ] || { sed -n '2,26p' "$0" >&2; exit 2; }
scene=$1 points=$2 ref=$3 common=$4 settings=$5
[ -x "$rtrace" ] || { echo "sweep: no $rtrace (scripts/build.sh release)" >&2; exit 1; }
[ "$runs" -ge 2 ] || runs=2
[ -n "$prefix" ] || prefix=docs/data/$(basename "$scene" .rad)
[ -n "$title" ] || title=$(basename "$scene")
name=$(basename "$prefix")
mkdir -p "$(dirname "$prefix")"
csv=$prefix.csv md=$prefix.md svg=$prefix.svg
case $prefix in docs/data/*) svg=docs/plots/$name.svg; mkdir -p docs/plots ;; esac

tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
now() { date +%s.%N; }

# errors OUT REF SPP: "rms max bias" in %, OUT holding SPP consecutive lines per point.
errors() {
  awk -v spp="$3" 'NR == FNR { ref[FNR] = 0.265074126*$1 + 0.670114631*$2 + 0.064811243*$3; next }
    { i = int((FNR - 1) / spp) + 1; sum[i] += 0.265074126*$1 + 0.670114631*$2 + 0.064811243*$3
      if (i > m) m = i }
    END { for (i = 1; i <= m; i++) { e = (sum[i] / spp - ref[i]) / ref[i]; s += e*e; b += e
            if (e < 0) e = -e; if (e > mx) mx = e }
          printf "%.6g %.6g %.6g\n", 100*sqrt(s/m), 100*mx, 100*b/m }' "$2" "$1"
}

floor=$(awk '{ s += $4*$4; n++ } END { printf "%.4g", 100*sqrt(s/n) }' "$ref")
echo "method,options,runs,rms_pct,max_pct,bias_pct,time_s,times_s,records,rays,shadow_rays" > "$csv"
grep -v '^[[:space:]]*\(#\|$\)' "$settings" | while read -r method opts; do
  spp=1 rtopts=$opts
  if [[ " $opts " == *" -spp "* ]]; then
    spp=$(awk '{ for (i = 1; i < NF; i++) if ($i == "-spp") print $(i+1) }' <<< "$opts")
    rtopts="$(sed 's/-spp [0-9]*//' <<< "$opts") -aa 0 -ad 1 -as 0 -lw 1e-9"
  fi
  awk -v k="$spp" '{ for (i = 0; i < k; i++) print }' "$points" > "$tmp/input"
  stats="" results="" times=""
  for ((seed = 1; seed <= runs; seed++)); do
    t0=$(now)
    # shellcheck disable=SC2086
    "$rtrace" -h -w -t 1000 $common $rtopts -seed $seed "$scene" < "$tmp/input" \
        > "$tmp/out" 2> "$tmp/err"
    t1=$(now)
    times+="$(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.3f", b - a }') "
    results+="$(errors "$tmp/out" "$ref" "$spp")"$'\n'
    [ -n "$stats" ] || stats=$(grep 'records per level' "$tmp/err" | tail -1)
  done
  # records: sum of "a/b/c" after "records per level"; rays: "R rays traced + S shadow rays"
  counts=$(awk '{ for (i = 1; i <= NF; i++) {
             if ($i == "level") { n = split($(i+1), r, "/"); for (j = 1; j <= n; j++) rec += r[j] }
             if ($i == "rays" && $(i+1) == "traced") rays = $(i-1)
             if ($i == "shadow") shadow = $(i-1) } }
           END { printf "%d,%d,%d", rec, rays, shadow }' <<< "$stats")
  line=$(awk -v times="$times" 'NF == 3 { s += $1*$1; if ($2 > mx) mx = $2; b += $3; n++ }
     END { k = split(times, t, " "); mn = t[1]; for (i = 2; i <= k; i++) if (t[i] < mn) mn = t[i]
           all = t[1]; for (i = 2; i <= k; i++) all = all "/" t[i]
           printf "%d,%.3f,%.3f,%+.3f,%.3f,%s", n, sqrt(s/n), mx, b/n, mn, all }' <<< "$results")
  echo "$method,\"$opts\",$line,$counts" >> "$csv"
  echo "sweep $name: $method $opts -> $line,$counts" >&2
done

# Markdown table, sorted by method then time.
{
  echo "**$title** (\`$common\`; $runs runs per setting, time = minimum; reference noise floor $floor % RMS)"
  echo
  echo "| method | options | RMS % | max % | bias % | time s (min) | runs s | records | rays | shadow rays |"
  echo "|---|---|---|---|---|---|---|---|---|---|"
  tail -n +2 "$csv" | awk -F'"' '{ split($1, a, ","); split($3, b, ",")
      printf "| %s | `%s` | %s | %s | %s | %s | %s | %s | %s | %s |\n",
             a[1], $2, b[3], b[4], b[5], b[6], b[7], b[8], b[9], b[10] }'
} > "$md"

awk -v title="$title" -v floor="$floor" -f bench/plot_svg.awk "$csv" > "$svg"
echo "sweep: wrote $csv $md $svg" >&2
