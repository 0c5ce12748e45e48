#!/usr/bin/env python3
"""A 40 x 40 m room lit by 400 ceiling lamps (20 x 20 small light polygons,
facing down) over 100 desks: a scene with many light sources, for the
obstructor cache's cost (README, "The direct calculation"). Prints the scene;
with --points, ten work-plane sensors instead.

  python3 bench/make_lamp_grid.py > lamps.rad
  python3 bench/make_lamp_grid.py --points > lamps.pts
  ../shared/tools/side-by-side -n 7 build-plain/bin/rtrace "-h -I -ab 0" lamps.rad lamps.pts
"""
import sys

if "--points" in sys.argv:
    for i in range(10):
        print(f"{3 + 3.7 * i:.2f} {3.3 + 3.1 * i:.2f} 0.8 0 0 1")
    sys.exit(0)
out = ["void light lum 0 0 3 20 20 20", "void plastic white 0 0 5 .6 .6 .6 0 0",
       "white polygon floor 0 0 12 0 0 0 40 0 0 40 40 0 0 40 0",
       "white polygon ceil 0 0 12 0 0 3 0 40 3 40 40 3 40 0 3"]
for i in range(20):
    for j in range(20):
        x, y = 1 + 2 * i, 1 + 2 * j
        out.append(f"lum polygon l{20 * i + j} 0 0 12 {x} {y} 2.99 {x} {y + .6} 2.99 "
                   f"{x + .6} {y + .6} 2.99 {x + .6} {y} 2.99")
for i in range(10):
    for j in range(10):
        x, y = 2 + 4 * i, 2 + 4 * j
        out.append(f"white polygon d{i}_{j} 0 0 12 {x} {y} .75 {x + 1.5} {y} .75 "
                   f"{x + 1.5} {y + .8} .75 {x} {y + .8} .75")
print("\n".join(out))
