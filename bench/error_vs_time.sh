#!/usr/bin/env bash
# Regenerates docs/error-vs-time.md (keeping its hand-written sections from
# "## Dense jobs" on), docs/data/*.csv and docs/plots/*.svg: error
# against wall time for every method on the five reference cases. About 5-10
# minutes on a 2-core machine (Release build; run nothing else meanwhile).
#
#   bench/error_vs_time.sh [-k runs] [path/to/rtrace]
set -euo pipefail
cd "$(dirname "$0")/.."
runs=2
while getopts "k:" flag; do
  case $flag in k) runs=$OPTARG ;; *) exit 2 ;; esac
done
shift $((OPTIND - 1))
rtrace=${1:-build/bin/rtrace}
[ -x "$rtrace" ] || { echo "error_vs_time: build first (scripts/build.sh release)" >&2; exit 1; }

# name|title|scene|points|reference|common options|settings
cases=(
  "cornell_floor|cornell floor, -I -ab 2 (84 points)|scenes/cornell/cornell.rad|scenes/cornell/floor.pts|scenes/cornell/ref/floor_I_ab2.txt|-I -ab 2|bench/sweeps/cornell_floor.txt"
  "cornell_edges|cornell edges, -I -ab 2 (40 points within 2 cm of walls)|scenes/cornell/cornell.rad|scenes/cornell/edges.pts|scenes/cornell/ref/edges_I_ab2.txt|-I -ab 2|bench/sweeps/cornell_floor.txt"
  "daylit_workplane|daylit_room work plane, -I -ab 4 (96 points)|scenes/daylit_room/daylit_room.rad|scenes/daylit_room/workplane.pts|scenes/daylit_room/ref/workplane_I_ab4.txt|-I -ab 4|bench/sweeps/daylit_workplane.txt"
  "furnace|furnace, -I -ab 3 -av 1 1 1 -aw 0 (analytic: pi/8)|scenes/furnace/furnace.rad|scenes/furnace/points.txt|scenes/furnace/ref/points_I_ab3_av1.txt|-I -ab 3 -av 1 1 1 -aw 0|bench/sweeps/analytic.txt"
  "skyplane|skyplane, -I -ab 1 (analytic: pi)|scenes/skyplane/skyplane.rad|scenes/skyplane/points.txt|scenes/skyplane/ref/points_I_ab1.txt|-I -ab 1|bench/sweeps/analytic.txt"
)

for c in "${cases[@]}"; do
  IFS='|' read -r name title scene points ref common settings <<< "$c"
  bench/sweep.sh -r "$rtrace" -k "$runs" -t "$title" -o "docs/data/$name" \
      "$scene" "$points" "$ref" "$common" "$settings"
done

# For one CSV: the fastest setting below each RMS target, and the factor by
# which the cache beats pure path tracing at equal error. Path tracing's error
# falls as 1/sqrt(paths), so its points are fitted with log e = C - log(t)/2
# and the time it needs for error e is t_pt(e) = 10^(2 (C - log e)).
analyse() {
  awk -F'"' '
    function lg(v) { return log(v) / log(10) }
    NR > 1 { split($1, a, ","); split($3, b, ","); m = a[1]; e = b[3] + 0; t = b[6] + 0
             n++; M[n] = m; O[n] = $2; E[n] = e; X[n] = b[4]; Tm[n] = t
             if (m == "pt" && e > 0) { C += lg(e) + lg(t) / 2; np++ } }
    END {
      split("1 3", targets, " ")
      for (k = 1; k <= 2; k++) {
        T = targets[k]; best = 0; bestc = 0
        for (i = 1; i <= n; i++) if (E[i] < T) {
          if (!best || Tm[i] < Tm[best]) best = i
          if (M[i] ~ /^aa\./ && (!bestc || Tm[i] < Tm[bestc])) bestc = i
        }
        if (!best) { printf "- below %d %% RMS: no setting reached it.\n", T; continue }
        printf "- below %d %% RMS, fastest: `%s` (%s), %.3g %% RMS / %s %% max in %.3g s", T, O[best], M[best], E[best], X[best], Tm[best]
        if (bestc && bestc != best) printf "; fastest cached: `%s`, %.3g %% in %.3g s", O[bestc], E[bestc], Tm[bestc]
        if (bestc && np > 0 && E[bestc] > 0) {
          tpt = 10 ^ (2 * (C / np - lg(E[bestc])))
          printf "; pure path tracing would need %.3g s for %.3g %%: the cache is %.2gx %s", tpt, E[bestc], (tpt > Tm[bestc] ? tpt / Tm[bestc] : Tm[bestc] / tpt), (tpt > Tm[bestc] ? "faster" : "slower")
        }
        printf ".\n"
      }
    }' "$1"
}

# The sections written by hand after the generated ones (from "## Dense jobs"
# on: measurements of other scripts) are kept as they are.
kept=$(mktemp); trap 'rm -f "$kept"' EXIT
[ -f docs/error-vs-time.md ] && sed -n '/^## Dense jobs/,$p' docs/error-vs-time.md > "$kept"
machine="$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//'), $(nproc) cores, $(awk '/MemTotal/ { printf "%.0f GB", $2 / 1048576 }' /proc/meminfo)"
{
  cat <<EOF
# Error against time

Every speed claim comes with the error it buys. This page gives, for the five
reference cases, the RMS relative error of luminance against the converged
reference for each setting of \`rtrace\`, against wall time: pure path tracing
(\`pt\`), no cache with one \`-ad\` hemisphere per bounce (\`aa0\`), and the
irradiance cache at several \`-aa\`, with \`-n 2\` variants. The cache rows use the
default record methods (mixed, \`-ahm\`, since 2026-12-02; the classic records before).

- **Generated** by \`bench/error_vs_time.sh\` on $(date -u +%Y-%m-%d) with \`$rtrace\` (Release,
  \`scripts/build.sh release\`). Machine: $machine, a shared VM.
- **Regenerate** everything on this page (about 5-10 minutes):
  \`\`\`sh
  scripts/build.sh release && bench/error_vs_time.sh
  \`\`\`
  One scene: \`bench/sweep.sh -t TITLE -o docs/data/NAME SCENE POINTS REF "OPTIONS" bench/sweeps/FILE\`.
- **Timing:** wall clock of one \`rtrace\` process, scene loading included. Each
  setting runs $runs times (seeds 1..$runs) and the **minimum** time is kept: other
  engineers use this 2-core machine at the same time, so single timings are noisy,
  and \`-n 2\` rows only show a speed-up when the second core is free.
- **Errors** (scenes/README.md): relative RMS over the points, max |relative
  error| and bias (mean relative error), on luminance, in %. With $runs runs, the
  RMS is the root of the mean square over the runs, max the largest, bias the mean.
  The reference's own noise (RMS of its rel_stderr, dashed in the plots) is the
  floor under every RMS error: an RMS near it is "converged".
- **Path tracing** (\`-spp K\`): \`-aa 0 -ad 1 -as 0 -lw 1e-9\` with each point
  repeated K times and the K estimates averaged; \`-ad 1\` gives one row of three
  azimuth divisions (Ward's minimum), so each bounce sends up to three rays. The
  factors "cache against path tracing" fit the path-tracing points with
  error ∝ 1/sqrt(time) and compare times at the cached setting's error.
- **Records** and **rays** come from \`rtrace -t\` (first run): records created, rays
  traced (hemisphere and specular rays) and shadow rays.

EOF
  for c in "${cases[@]}"; do
    IFS='|' read -r name title _ <<< "$c"
    echo "## $title"
    echo
    echo "![$title](plots/$name.svg)"
    echo
    analyse "docs/data/$name.csv"
    echo
    cat "docs/data/$name.md"
    echo
    echo "Data: [\`docs/data/$name.csv\`](data/$name.csv)."
    echo
  done
  cat <<'EOF'
## The reference generator

`bench/reference.sh` computes converged values through lazyrad itself: no cache,
`-aa 0 -ad 1 -as 0 -lw 1e-9`, every input line repeated (each copy is an
independent estimate), batches with their own `-seed`, one process per core.
It writes Radiance's reference format (`r g b rel_stderr`, rel_stderr of the
green channel's mean). `bench/refcheck.sh A B` tests two references against
their combined standard errors (z per point, chi², Wilson-Hilferty p-value).
See docs/benchmarks.md for the check against `scenes/cornell/ref/floor_I_ab2.txt`.
EOF
  if [ -s "$kept" ]; then
    echo
    cat "$kept"
  fi
} > docs/error-vs-time.md
rm -f docs/data/*.md
echo "error_vs_time: wrote docs/error-vs-time.md" >&2
