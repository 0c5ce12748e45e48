#!/usr/bin/env python3
# Writes blinds.xml: a Klems-basis BSDF file (LBNL/Klems Full, as WINDOW
# writes them) for an exterior venetian blind, from a simple model rather
# than a measurement. A developer's tool; the file it writes is committed.
#
# Radiance's front of the file (+z, the side its surface normal faces) is
# the outside here; light entering from there is the file's "Transmission
# Back" (WINDOW's front is Radiance's back). Local y is the up vector (the
# material's `0 0 1`: the slats run along local x).
# - Straight through: the share of the opening the slats leave clear for
#   the light's profile angle ψ (its elevation across the slats), 0.8
#   cos⁴(ψ + 15°): most for light from slightly below horizontal, none for
#   high sun.
# - The light the slats stop: 35 % of it leaves the room side spread toward
#   the ceiling (a cosine lobe about 40° above the normal), plus 0.01/sr
#   everywhere.
# - Reflection: 0.12/sr outside, 0.08/sr inside (Lambertian).
import math
import os

import sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                "tests", "direct"))
from generate_bsdf import FULL, klems_xml, patches  # noqa: E402


def main():
    p = patches(FULL)
    n = len(p)
    # Patch centres as front-exiting unit vectors.
    vec = []
    for t, f, _ in p:
        t, f = math.radians(t), math.radians(f)
        vec.append((math.sin(t) * math.cos(f), math.sin(t) * math.sin(f), math.cos(t)))
    lobe_axis = (0.0, math.sin(math.radians(40)), math.cos(math.radians(40)))
    lobe = [max(0.0, sum(a * b for a, b in zip(v, lobe_axis))) for v in vec]
    lobe_norm = sum(w * ohm for w, (_, _, ohm) in zip(lobe, p))
    t = [[0.01] * n for _ in range(n)]  # t[outgoing][incident]
    for i in range(n):
        # Incident patch i as the direction toward the light (front incident:
        # x and y negated from the front-exiting vector).
        x, y, z = -vec[i][0], -vec[i][1], vec[i][2]
        psi = math.atan2(y, z)
        clear = 0.8 * max(0.0, math.cos(psi + math.radians(15))) ** 4
        # Straight through: the same patch on the other side.
        t[i][i] += clear / p[i][2]
        for o in range(n):
            t[o][i] += 0.35 * (1 - clear) * lobe[o] / lobe_norm
    r_out = [[0.12] * n for _ in range(n)]
    r_in = [[0.08] * n for _ in range(n)]
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "blinds.xml")
    with open(path, "w") as f:
        f.write(klems_xml({"Transmission Back": t, "Reflection Back": r_out,
                           "Reflection Front": r_in}, "LBNL/Klems Full",
                          wavelengths=("Visible",), digits=4))


if __name__ == "__main__":
    main()
