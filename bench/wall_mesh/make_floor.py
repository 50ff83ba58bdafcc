#!/usr/bin/env python3
"""Binary STL of the square [0,L]^2 at z = 0, facing +z, n x n cells of two
triangles with alternating diagonals and jittered interior vertices (fixed
seed). Usage: make_floor.py out.stl n [L]"""
import random, struct, sys

out, n = sys.argv[1], int(sys.argv[2])
L = float(sys.argv[3]) if len(sys.argv) > 3 else 0.3
rng = random.Random(5)
h = L / n
P = {}
for j in range(n + 1):
    for i in range(n + 1):
        x, y = i * h, j * h
        if 0 < i < n: x += 0.3 * h * rng.uniform(-1, 1)
        if 0 < j < n: y += 0.3 * h * rng.uniform(-1, 1)
        P[i, j] = (x, y, 0.0)
tris = []
for j in range(n):
    for i in range(n):
        a, b, c, d = P[i, j], P[i + 1, j], P[i, j + 1], P[i + 1, j + 1]
        tris += [(a, b, d), (a, d, c)] if (i + j) % 2 == 0 else [(a, b, c), (b, d, c)]
with open(out, "wb") as f:
    f.write(b"POLYDEM bench floor".ljust(80, b" "))
    f.write(struct.pack("<I", len(tris)))
    for t in tris:
        f.write(struct.pack("<3f", 0, 0, 1))
        for v in t: f.write(struct.pack("<3f", *v))
        f.write(b"\0\0")
print(out, len(tris), "triangles")
