#!/usr/bin/env python3
"""Six ASCII STL walls of the same flat strip x in [0, 0.1], y in [-0.025, 0.025]
(z = 0, facing +z), lambda = L_c / L_m = 0.5, 1, 2, 4, 8 (regular, alternating
diagonals) and an irregular one (jittered vertices, lambda ~ 4). L_c = 0.025 m."""
import os
import random
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from stl_mesh import grid_triangles  # noqa: E402

LC, X1, Y0, Y1 = 0.025, 0.1, -0.025, 0.025

def write(name, tris):
    with open(name, "w") as f:
        f.write("solid %s\n" % name)
        for t in tris:
            f.write(" facet normal 0 0 1\n  outer loop\n")
            for v in t: f.write("   vertex %.17g %.17g 0\n" % v)
            f.write("  endloop\n endfacet\n")
        f.write("endsolid %s\n" % name)

def strip(lm, jitter=0.0, seed=1):
    nx, ny = max(1, round(X1 / lm)), max(1, round((Y1 - Y0) / lm))
    rng = random.Random(seed)
    P = {}
    for j in range(ny + 1):
        for i in range(nx + 1):
            x, y = i * X1 / nx, Y0 + j * (Y1 - Y0) / ny
            if 0 < i < nx: x += jitter * X1 / nx * rng.uniform(-1, 1)
            if 0 < j < ny: y += jitter * (Y1 - Y0) / ny * rng.uniform(-1, 1)
            P[i, j] = (x, y)
    return grid_triangles(P, nx, ny)

for lam in (0.5, 1, 2, 4, 8):
    t = strip(LC / lam)
    write("wall_lam%g.stl" % lam, t)
    print("wall_lam%g.stl" % lam, len(t), "triangles")
t = strip(LC / 4, jitter=0.35, seed=7)
write("wall_irregular.stl", t)
print("wall_irregular.stl", len(t), "triangles")
