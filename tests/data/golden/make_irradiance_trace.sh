#!/usr/bin/env bash
# Makes the reference of Golden.IrradianceSensorsHaveNoTraceLineOfTheirOwn with
# real Radiance 5.4a: rtrace -I with trace output (-ovtvsL) on two lit cornell
# floor sensors. Radiance shades a sensor without raytrace(), so the trace
# has no line for the sensor itself, and shadow rays that reach their source
# are not shown (-ot): the output is the two values alone. (A sensor in a
# shadow is left out: Radiance's obstructor cache hides some blocked shadow
# rays, and lazyrad had none when this was made.) -dt 0 -dj 0: no
# estimated shadow tests, no jitter. The test only reads the committed file.
#
#   tests/data/golden/make_irradiance_trace.sh [radiance-dir]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
# shellcheck source=radiance_setup.sh
source "$here/radiance_setup.sh"
"$rad/bin/oconv" "$here/../../../scenes/cornell/cornell.rad" > "$tmp/cornell.oct"
sed -n '1p;40p' "$here/../../../scenes/cornell/floor.pts" > "$here/cornell_sensors.pts"
"$rad/bin/rtrace" -h -I -ab 0 -dj 0 -dt 0 -ss 0 -u- -ovtvsL "$tmp/cornell.oct" \
  < "$here/cornell_sensors.pts" > "$here/cornell_I_ovtvsL.txt"
