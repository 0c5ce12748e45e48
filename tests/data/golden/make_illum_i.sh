#!/usr/bin/env bash
# Makes the reference of Golden.IrradianceAtHitMetersAnIllumsAlternate with
# real Radiance 5.4a: rtrace -i (irradiance at the first surface) on rays
# that meet illum windows with a plastic, a glass, a mirror and no alternate
# (illum_i.rad). Radiance meters the alternate as its Lambertian meter, passes
# through a glass one and through an illum without one. -dt 0: no estimated
# shadow tests. The test only reads the committed file.
#
#   tests/data/golden/make_illum_i.sh [radiance-dir]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
# shellcheck source=radiance_setup.sh
source "$here/radiance_setup.sh"
"$rad/bin/oconv" "$here/illum_i.rad" > "$tmp/illum_i.oct"
"$rad/bin/rtrace" -h -w -i -dt 0 -ovs "$tmp/illum_i.oct" < "$here/illum_i.rays" > "$here/illum_i_ovs.txt"
