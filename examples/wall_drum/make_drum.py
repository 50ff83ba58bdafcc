#!/usr/bin/env python3
"""Closed drum mesh: cylinder of diameter D (axis y, from y = 0 to y = W) with
both end caps, normals pointing inside. nseg segments around.
Usage: make_drum.py out.stl D W nseg"""
import math, struct, sys

out, D, W, n = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), int(sys.argv[4])
R = D / 2
ring = [(R * math.cos(2 * math.pi * k / n), R * math.sin(2 * math.pi * k / n)) for k in range(n)]
tris = []
for k in range(n):
    (x0, z0), (x1, z1) = ring[k], ring[(k + 1) % n]
    a, b, c, d = (x0, 0, z0), (x1, 0, z1), (x0, W, z0), (x1, W, z1)
    # side: inward normal -(x, 0, z); order so that (b-a)x(c-a) points inside
    tris += [(a, b, c), (b, d, c)]
    tris += [((0, 0, 0), (x1, 0, z1), (x0, 0, z0))]      # cap y = 0, normal +y
    tris += [((0, W, 0), (x0, W, z0), (x1, W, z1))]      # cap y = W, normal -y
def nrm(t):
    u = [t[1][i] - t[0][i] for i in range(3)]; v = [t[2][i] - t[0][i] for i in range(3)]
    return (u[1]*v[2]-u[2]*v[1], u[2]*v[0]-u[0]*v[2], u[0]*v[1]-u[1]*v[0])
# check orientation: every normal points towards the drum's centre line
for t in tris:
    c = [sum(p[i] for p in t) / 3 for i in range(3)]
    nn = nrm(t)
    inward = (-c[0], W / 2 - c[1], -c[2])
    assert sum(nn[i] * inward[i] for i in range(3)) > 0, t
with open(out, "wb") as f:
    f.write(b"POLYDEM drum".ljust(80, b" "))
    f.write(struct.pack("<I", len(tris)))
    for t in tris:
        f.write(struct.pack("<3f", *nrm(t)))
        for p in t: f.write(struct.pack("<3f", *p))
        f.write(b"\0\0")
print(out, len(tris), "triangles")
