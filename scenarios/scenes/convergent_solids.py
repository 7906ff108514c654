#!/usr/bin/python3
"""Writes convergent_solids.stl: the glass outside the convergent duct's flow passage as two
closed, outward-oriented prisms (the duct's depth y = 0-0.1 m), for convergent_duct_air.toml,
where the gas must not flow behind the plates.

    /usr/bin/python3 scenarios/scenes/convergent_solids.py [OUT.stl]

Each prism is a convex polygon in the x-z plane extruded along y: left (0, 0), (0.05, 0),
(0.05, 0.3934), (0, 0.48); right mirrored about x = 0.15. Its inner faces are the convergent
plate (30 degrees to the vertical, z = 0.48 -> 0.3934 m) and the lower duct's side (x = 0.05 or
0.25 m, down to the floor); the others lie on the box walls, where no bead reaches them.
"""
import sys

import numpy as np

DEPTH = 0.1
LEFT = [(0.0, 0.0), (0.05, 0.0), (0.05, 0.3934), (0.0, 0.48)]
RIGHT = [(0.3 - x, z) for x, z in LEFT]


def prism(polygon):
    """Triangles (3 x 3 arrays of vertices) of the polygon extruded over 0 <= y <= DEPTH, each
    counter-clockwise seen from outside (outward normal by the right-hand rule)."""
    low = [np.array([x, 0.0, z]) for x, z in polygon]
    high = [np.array([x, DEPTH, z]) for x, z in polygon]
    n = len(polygon)
    tris = []
    for k in range(1, n - 1):  # caps: fans
        tris.append([low[0], low[k], low[k + 1]])
        tris.append([high[0], high[k + 1], high[k]])
    for k in range(n):  # sides: two triangles per edge
        a, b = k, (k + 1) % n
        tris.append([low[a], high[a], high[b]])
        tris.append([low[a], high[b], low[b]])
    # Orient outward: the signed volume (divergence theorem) must be positive.
    volume = sum(np.dot(t[0], np.cross(t[1], t[2])) for t in tris) / 6.0
    if volume < 0:
        tris = [[t[0], t[2], t[1]] for t in tris]
    return tris


def main(path):
    with open(path, "w") as f:
        f.write("solid convergent_solids\n")
        for tri in prism(LEFT) + prism(RIGHT):
            normal = np.cross(tri[1] - tri[0], tri[2] - tri[0])
            normal /= np.linalg.norm(normal)
            f.write("  facet normal %.9g %.9g %.9g\n    outer loop\n" % tuple(normal))
            for v in tri:
                f.write("      vertex %.9g %.9g %.9g\n" % tuple(v))
            f.write("    endloop\n  endfacet\n")
        f.write("endsolid convergent_solids\n")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "convergent_solids.stl")
