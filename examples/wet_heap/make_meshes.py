#!/usr/bin/env python3
"""Meshes of the wet heap example (ASCII STL): tube.stl, the tube of inner
diameter D and height H (n segments) that holds the column and is lifted;
floor.stl, a square plate of side L at z = 0 (PREFIXtube.stl and
PREFIXfloor.stl if a prefix is given: the oedometer example's heap).
    python3 make_meshes.py [D H n L [prefix]]"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../dodeca_packing"))
from make_cylinder import cylinder  # noqa: E402

D, H, n, L = (float(sys.argv[1]), float(sys.argv[2]), int(sys.argv[3]), float(sys.argv[4])) \
    if len(sys.argv) > 4 else (0.016, 0.08, 32, 0.13)
prefix = sys.argv[5] if len(sys.argv) > 5 else ""


def write(path, tris):
    with open(path, "w") as f:
        f.write("solid mesh\n")
        for t in tris:
            f.write("  facet normal 0 0 0\n    outer loop\n")
            for v in t:
                f.write("      vertex %.9g %.9g %.9g\n" % v)
            f.write("    endloop\n  endfacet\n")
        f.write("endsolid mesh\n")


h = L / 2
write(prefix + "tube.stl", cylinder(D, H, n, False))
write(prefix + "floor.stl", [((-h, -h, 0.0), (h, -h, 0.0), (h, h, 0.0)), ((-h, -h, 0.0), (h, h, 0.0), (-h, h, 0.0))])
