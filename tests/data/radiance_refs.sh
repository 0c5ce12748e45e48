# Sourced by the make_refs.sh scripts of tests/data/*/ after they set `here`
# (their own folder): finds real Radiance 5.4a (the script's first argument,
# else ../shared/reference/radiance-5.4a beside the checkout), makes `tmp` a
# scratch folder removed on exit, and runs from `here`.
rad="${1:-$here/../../../../shared/reference/radiance-5.4a}"
[ -x "$rad/bin/rtrace" ] || { echo "no Radiance in $rad" >&2; exit 1; }
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
cd "$here"
