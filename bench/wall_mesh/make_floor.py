#!/usr/bin/env python3
"""Binary STL of the square [0,L]^2 at z = 0, facing +z, n x n cells of two
triangles with alternating diagonals and jittered interior vertices (fixed
seed; by up to 0.2 of a cell, so that no triangle folds over: 0.3, used
before 2026-11-22 10:00, folded 7 triangles of the 150k mesh).
Usage: make_floor.py out.stl n [L]"""
import os, random, struct, sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from stl_mesh import grid_triangles  # noqa: E402  (make_bowl.py imports it from here)


def write_stl(out, tris, header):
    with open(out, "wb") as f:
        f.write(header.ljust(80, b" "))
        f.write(struct.pack("<I", len(tris)))
        for t in tris:
            f.write(struct.pack("<3f", 0, 0, 1))
            for v in t: f.write(struct.pack("<3f", *v))
            f.write(b"\0\0")
    print(out, len(tris), "triangles")


def main():
    out, n = sys.argv[1], int(sys.argv[2])
    L = float(sys.argv[3]) if len(sys.argv) > 3 else 0.3
    rng = random.Random(5)
    h = L / n
    P = {}
    for j in range(n + 1):
        for i in range(n + 1):
            x, y = i * h, j * h
            if 0 < i < n: x += 0.2 * h * rng.uniform(-1, 1)
            if 0 < j < n: y += 0.2 * h * rng.uniform(-1, 1)
            P[i, j] = (x, y, 0.0)
    write_stl(out, grid_triangles(P, n, n), b"POLYDEM bench floor")


if __name__ == "__main__":
    main()
