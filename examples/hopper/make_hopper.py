#!/usr/bin/env python3
"""Meshes of the main example (binary STL, SI units, normals towards the grains):
  hopper.stl  a conical funnel (outlet radius r0 at z0, radius R at z1) under a
              cylinder of radius R up to z2
  gate.stl    a disk closing the outlet (normal up), removed to discharge
  floor.stl   a square tray of half width F at z = 0 with a rim of height H
              (normals inward and up)
Usage: make_hopper.py [nseg]"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from stl_mesh import faces, write_stl  # noqa: E402

n = int(sys.argv[1]) if len(sys.argv) > 1 else 48
r0, z0, R, z1, z2, F, H = 0.016, 0.10, 0.05, 0.16, 0.24, 0.15, 0.02


def write(path, tris, check):
    for t in tris:
        assert faces(t, check), (path, t)
    write_stl(path, tris, "POLYDEM hopper example")
    print(path, len(tris), "triangles")


ang = [2 * math.pi * k / n for k in range(n)]
ring = lambda r, z: [(r * math.cos(a), r * math.sin(a), z) for a in ang]
lo, mid, top = ring(r0, z0), ring(R, z1), ring(R, z2)
tris = []
for k in range(n):
    j = (k + 1) % n
    for a, b in ((lo, mid), (mid, top)):
        # quad a[k] a[j] b[j] b[k]; (b-a)x(c-a) must point to the axis
        tris += [(a[k], b[k], a[j]), (a[j], b[k], b[j])]
write("hopper.stl", tris, lambda c: (-c[0], -c[1], 0.0))
gate = [((0, 0, z0), lo[k], lo[(k + 1) % n]) for k in range(n)]
write("gate.stl", gate, lambda c: (0, 0, 1))
A, B, C, D = (-F, -F, 0), (F, -F, 0), (F, F, 0), (-F, F, 0)
E, G, I, J = (-F, -F, H), (F, -F, H), (F, F, H), (-F, F, H)
quad = lambda a, b, c, d: [(a, b, c), (a, c, d)]
floor = quad(A, B, C, D) + quad(A, E, G, B) + quad(B, G, I, C) + quad(C, I, J, D) + quad(D, J, E, A)
write("floor.stl", floor, lambda c: (-c[0], -c[1], 1.0))
