#!/usr/bin/env python3
"""Dense jobs of the kind daylighting tools and pictures make (issue 16):
- cornell/floor_dense.pts: the cornell floor on a 0.14 m grid (40 x 40, cell
  centres), facing up, 1 mm above it, without the points under the two blocks;
- daylit_room/workplane_dense.pts: the daylit room's work plane (0.8 m) on a
  0.2 m grid (20 x 30, cell centres), facing up;
The 128 x 128 picture's rays, cornell/view128.rays, come from lazyrad's vwrays:
  build/bin/vwrays -x 128 -y 128 -vf scenes/cornell/cornell.vf > scenes/cornell/view128.rays
Run from the repository root: python3 scenes/make_dense_jobs.py
"""
# Floor footprints of the cornell blocks (cornell.rad, z = 0 faces), counter-clockwise or not.
SHORT = [(2.87790284734, 0.417586687207), (1.3, 0.9), (1.78241331279, 2.47790284734),
         (3.36031616013, 1.99548953455)]
TALL = [(4.87790284734, 3.38241331279), (3.3, 2.9), (2.81758668721, 4.47790284734),
        (4.39548953455, 4.96031616013)]


def inside(poly, x, y):
    """Even-odd rule."""
    c = False
    n = len(poly)
    for i in range(n):
        (x0, y0), (x1, y1) = poly[i], poly[(i + 1) % n]
        if (y0 > y) != (y1 > y) and x < x0 + (y - y0) * (x1 - x0) / (y1 - y0):
            c = not c
    return c


def cornell_floor():
    out = []
    step = 0.139  # 40 cells over 5.56 m
    for i in range(40):
        for j in range(40):
            x, y = (i + 0.5) * step, (j + 0.5) * step
            if inside(SHORT, x, y) or inside(TALL, x, y):
                continue
            out.append(f"{x:.4f} {y:.4f} 0.001 0 0 1")
    return out


def daylit_workplane():
    return [f"{(i + 0.5) * 0.2:.3f} {(j + 0.5) * 0.2:.3f} 0.8 0 0 1"
            for i in range(20) for j in range(30)]


if __name__ == "__main__":
    for path, lines in (("scenes/cornell/floor_dense.pts", cornell_floor()),
                        ("scenes/daylit_room/workplane_dense.pts", daylit_workplane())):
        with open(path, "w") as f:
            f.write("\n".join(lines) + "\n")
        print(path, len(lines))
