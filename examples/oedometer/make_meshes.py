#!/usr/bin/env python3
"""Meshes of the oedometer example (ASCII STL): tube.stl, a tube of inner
diameter D and height H, n segments around (make_cylinder.py of the packing
example); floor.stl, a disk of radius D/2 at z = 0; lid.stl, a disk of
radius D/2 - gap at height H, which fix wall/mesh moves down by 'move
servo'. The tube's triangles stay in file order (fix wall/mesh merge no),
so analyze.py knows each one's height.
    python3 make_meshes.py [D H n gap]"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../dodeca_packing"))
from make_cylinder import cylinder  # noqa: E402

def write(path, tris):
    """ASCII STL of the triangles (also used by ../wet_heap/make_meshes.py)"""
    with open(path, "w") as f:
        f.write("solid mesh\n")
        for t in tris:
            f.write("  facet normal 0 0 0\n    outer loop\n")
            for v in t:
                f.write("      vertex %.9g %.9g %.9g\n" % v)
            f.write("    endloop\n  endfacet\n")
        f.write("endsolid mesh\n")


def disk(r, z, n):
    ring = [(r * math.cos(2 * math.pi * k / n), r * math.sin(2 * math.pi * k / n)) for k in range(n)]
    return [((0.0, 0.0, z), (x0, y0, z), (x1, y1, z))
            for (x0, y0), (x1, y1) in zip(ring, ring[1:] + ring[:1])]


if __name__ == "__main__":
    D, H, n, gap = (float(sys.argv[1]), float(sys.argv[2]), int(sys.argv[3]), float(sys.argv[4])) \
        if len(sys.argv) > 4 else (0.06, 0.12, 48, 0.001)
    write("tube.stl", cylinder(D, H, n, False))
    write("floor.stl", disk(D / 2, 0.0, n))
    write("lid.stl", disk(D / 2 - gap, H, n))
