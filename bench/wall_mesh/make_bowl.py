#!/usr/bin/env python3
"""Binary STL of a gently curved floor: the square [0,L]^2 lifted onto the
sphere z = Rc - sqrt(Rc^2 - (x - L/2)^2 - (y - L/2)^2) (a shallow bowl of
radius of curvature Rc, default 1 m), n x n cells of two triangles with
alternating diagonals, facing up. No two triangles are coplanar, so coplanar
merging (fix wall/mesh merge) cannot coarsen it: the worst case for the cost
per particle against the facet count. Usage: make_bowl.py out.stl n [L] [Rc]"""
import math, sys

from make_floor import grid_triangles, write_stl

out, n = sys.argv[1], int(sys.argv[2])
L = float(sys.argv[3]) if len(sys.argv) > 3 else 0.3
Rc = float(sys.argv[4]) if len(sys.argv) > 4 else 1.0
h = L / n
P = {}
for j in range(n + 1):
    for i in range(n + 1):
        x, y = i * h, j * h
        P[i, j] = (x, y, Rc - math.sqrt(Rc * Rc - (x - L / 2) ** 2 - (y - L / 2) ** 2))
write_stl(out, grid_triangles(P, n, n), b"POLYDEM bench bowl")
