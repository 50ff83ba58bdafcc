#!/usr/bin/env python3
"""Binary STL of a closed silo like the seed's (section 4.1): a vertical cylinder of
radius R from z = 0 to z = H on a cone ending in its apex at z = -D, axis through
(R, R), nth facets around, nz rows on the cylinder and nc rings on the cone, two
triangles per cell, normals pointing inside. Every strip between two generators is
planar, so coplanar merging (with a tolerance for the float32 vertices of binary STL,
merge 1e-6) reduces it to a few triangles per strip: the cost of a particle then
depends on the strip width, not on nz and nc.
Usage: make_silo.py out.stl nth nz nc [R H D]"""
import math, sys

from make_floor import write_stl


def main():
    out, nth, nz, nc = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4])
    R, H, D = (float(v) for v in sys.argv[5:8]) if len(sys.argv) > 7 else (0.15, 0.3, 0.1)
    def P(i, r, z):
        t = 2 * math.pi * (i % nth) / nth
        return (R + r * math.cos(t), R + r * math.sin(t), z)
    rows = [(R, H - H * k / nz) for k in range(nz + 1)]                     # cylinder, top down
    rows += [(R * (1 - k / nc), -D * k / nc) for k in range(1, nc + 1)]    # cone, to the apex
    tris = []
    for k in range(len(rows) - 1):
        (r0, z0), (r1, z1) = rows[k], rows[k + 1]
        for i in range(nth):
            a, b = P(i, r0, z0), P(i + 1, r0, z0)
            c, d = P(i, r1, z1), P(i + 1, r1, z1)
            if r1 == 0.0:
                tris.append((a, b, c))    # last ring: one triangle to the apex
            else:
                tris += [(a, d, c), (a, b, d)]
    # normals inside: towards the axis
    def inward(t):
        a, b, c = t
        u = [b[m] - a[m] for m in range(3)]
        v = [c[m] - a[m] for m in range(3)]
        n = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
        cx = sum(p[0] for p in t) / 3 - R
        cy = sum(p[1] for p in t) / 3 - R
        return n[0] * cx + n[1] * cy < 0
    assert all(inward(t) for t in tris), "orientation"
    write_stl(out, tris, b"POLYDEM bench silo")


if __name__ == "__main__":
    main()
