#!/bin/sh
# Regenerates the reference outputs of the bundled gensky and gendaylit from
# real Radiance 5.4a. Run from anywhere; commit the *_expected.txt it writes.
#
#   tests/data/gensky/make_refs.sh [radiance-bin-dir]
#
# Each non-comment line of <program>_cases.txt is one command line in shell
# word syntax. It runs with the Radiance bin directory first on PATH, so the
# program's argv[0] (echoed in its first output line) is the bare name. For
# each case <program>_expected.txt gets a block
#
#   === <case number> status <exit status>
#   --- stdout <byte count>
#   <exactly that many bytes>
#   --- stderr <byte count>
#   <exactly that many bytes>
#
# which tests/tools/sky_tools_test.cpp replays against the bundled programs.
# Giving the bundled tools' directory (build/bin) instead shows how they
# differ: diff the result against the committed files (git diff).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
bin=${1:-$here/../../../../shared/reference/radiance-5.4a/bin}
bin=$(cd "$bin" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

for program in gensky gendaylit; do
    cases=$here/${program}_cases.txt
    [ -f "$cases" ] || continue
    expected=$here/${program}_expected.txt
    : > "$tmp/expected"
    n=0
    grep -v '^#' "$cases" | grep -v '^[[:space:]]*$' | while IFS= read -r line; do
        n=$((n + 1))
        status=0
        (cd "$tmp" && PATH="$bin:$PATH" sh -c "$line" > "$tmp/out" 2> "$tmp/err" < /dev/null) || status=$?
        if [ "$status" -ge 128 ]; then
            echo "$program case $n crashed (status $status): $line" >&2
            exit 1
        fi
        {
            printf '=== %d status %d\n' "$n" "$status"
            printf -- '--- stdout %d\n' "$(wc -c < "$tmp/out")"
            cat "$tmp/out"
            printf -- '--- stderr %d\n' "$(wc -c < "$tmp/err")"
            cat "$tmp/err"
        } >> "$tmp/expected"
    done
    mv "$tmp/expected" "$expected"
    echo "$expected: $(grep -c '^===' "$expected") cases"
done
