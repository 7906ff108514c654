#!/usr/bin/env python3
"""Writes convergent_plates.stl: the four plates of convergent_duct.toml (the two 30-degree
convergent plates and the lower duct's two sides) as one ASCII STL mesh of 8 triangles, each
plate's quadrilateral split along its diagonal from its first to its third vertex. The
coordinates (m) are written as in the scene file, so that both read to the same doubles.
  python3 scenarios/scenes/convergent_plates.py > scenarios/scenes/convergent_plates.stl
"""

PLATES = {  # name: vertices in order around the plate, m (convergent_duct.toml)
    "convergent_left": ["0.0 0.0 0.48", "0.0 0.1 0.48", "0.05 0.1 0.3934", "0.05 0.0 0.3934"],
    "convergent_right": ["0.3 0.0 0.48", "0.3 0.1 0.48", "0.25 0.1 0.3934", "0.25 0.0 0.3934"],
    "lower_left": ["0.05 0.0 0.0", "0.05 0.1 0.0", "0.05 0.1 0.3934", "0.05 0.0 0.3934"],
    "lower_right": ["0.25 0.0 0.0", "0.25 0.1 0.0", "0.25 0.1 0.3934", "0.25 0.0 0.3934"],
}

print("solid convergent_plates")
for name, (a, b, c, d) in PLATES.items():
    for triangle in ((a, b, c), (a, c, d)):
        print("  facet normal 0 0 0")  # carom orients a triangle by its vertices' order
        print("    outer loop")
        for vertex in triangle:
            print(f"      vertex {vertex}")
        print("    endloop")
        print("  endfacet")
print("endsolid convergent_plates")
