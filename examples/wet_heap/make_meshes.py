#!/usr/bin/env python3
"""Meshes of the wet heap example (ASCII STL): tube.stl, the tube of inner
diameter D and height H (n segments) that holds the column and is lifted;
floor.stl, a square plate of side L at z = 0 (PREFIXtube.stl and
PREFIXfloor.stl if a prefix is given: the oedometer example's heap).
    python3 make_meshes.py [D H n L [prefix]]"""
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "../dodeca_packing"))
sys.path.insert(0, os.path.join(here, "../oedometer"))
from make_cylinder import cylinder  # noqa: E402
from make_meshes import write  # noqa: E402  (the oedometer's ASCII STL writer)

D, H, n, L = (float(sys.argv[1]), float(sys.argv[2]), int(sys.argv[3]), float(sys.argv[4])) \
    if len(sys.argv) > 4 else (0.016, 0.08, 32, 0.13)
prefix = sys.argv[5] if len(sys.argv) > 5 else ""
h = L / 2
write(prefix + "tube.stl", cylinder(D, H, n, False))
write(prefix + "floor.stl", [((-h, -h, 0.0), (h, -h, 0.0), (h, h, 0.0)), ((-h, -h, 0.0), (h, h, 0.0), (-h, h, 0.0))])
