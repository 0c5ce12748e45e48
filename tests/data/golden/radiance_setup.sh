# Sourced (not run) by the make_*.sh reference scripts in this folder, after
# they set `here` to it: finds real Radiance 5.4a (the script's first
# argument, or ../shared beside the checkout), puts its library on RAYPATH,
# and makes a scratch folder $tmp that is removed when the script exits.
# The tests never run these scripts; they only read the files they wrote.
rad="${1:-$(cd "$here/../../.." && pwd)/../shared/reference/radiance-5.4a}"
[ -x "$rad/bin/rtrace" ] || { echo "no Radiance in $rad" >&2; exit 1; }
export RAYPATH=".:$rad/lib"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
