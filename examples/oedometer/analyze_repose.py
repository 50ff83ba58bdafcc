#!/usr/bin/env python3
"""Angle of repose of the oedometer's spheres (in.repose) and Jaky's
K0 = 1 - sin(phi) from it, against the K0 the oedometer measured.
    /usr/bin/python3 analyze_repose.py [repose_heap.txt]
The heap's surface as in ../wet_heap/analyze.py: the highest sphere top in
radial rings 4 mm wide, above the top of the fixed spheres (z = 8.4 mm), and
the slope of a line through it between 15 % and 85 % of the heap's height."""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../wet_heap"))
from analyze import angle, load, surface  # noqa: E402

d = load(sys.argv[1] if len(sys.argv) > 1 else "repose_heap.txt")
r, h, rr, top = surface(d, width=0.004, zbase=0.0084)
phi, slope, icpt, sel, H = angle(r, h)
print(f"heap of {len(d['x'])} spheres: height {H * 1e3:.1f} mm, angle of repose {phi:.1f} deg; "
      f"Jaky K0 = 1 - sin(phi) = {1 - math.sin(math.radians(phi)):.3f}")
