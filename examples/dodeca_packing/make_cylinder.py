#!/usr/bin/env python3
"""Cylinder meshes for the dodecahedron packing (seed section 3.3), binary STL,
axis z, every normal pointing into the cylinder (towards the particles: fix
wall/mesh walls are one-sided).

    make_cylinder.py out.stl D H nseg [floor|open] [z0]

D inner diameter, H height, nseg segments around (vertices on the circle of
diameter D), z0 the bottom (default 0). 'floor' closes the bottom with a fan
of nseg triangles (normal +z); 'open' gives a bare tube (the loading tube
stacked above the container)."""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from stl_mesh import faces, write_stl  # noqa: E402


def cylinder(D, H, n, floor, z0=0.0):
    R = D / 2
    ring = [(R * math.cos(2 * math.pi * k / n), R * math.sin(2 * math.pi * k / n)) for k in range(n)]
    z1 = z0 + H
    tris = []
    for k in range(n):
        (x0, y0), (x1, y1) = ring[k], ring[(k + 1) % n]
        a, b, c, d = (x0, y0, z0), (x1, y1, z0), (x0, y0, z1), (x1, y1, z1)
        tris += [(a, c, b), (b, c, d)]          # side: (t1-t0)x(t2-t0) points to the axis
        if floor:
            tris.append(((0.0, 0.0, z0), (x0, y0, z0), (x1, y1, z0)))   # floor: +z
    return tris


def check_inward(tris, z0, H):
    """every normal points into the cylinder: towards the axis (side) or up (floor)"""
    for t in tris:
        assert faces(t, lambda c: (-c[0], -c[1], z0 + H / 2 - c[2])), t


def main():
    out, D, H, n = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), int(sys.argv[4])
    floor = (sys.argv[5] if len(sys.argv) > 5 else "floor") == "floor"
    z0 = float(sys.argv[6]) if len(sys.argv) > 6 else 0.0
    tris = cylinder(D, H, n, floor, z0)
    check_inward(tris, z0, H)
    write_stl(out, tris, "POLYDEM cylinder D %g H %g nseg %d %s" % (D, H, n, "floor" if floor else "open"))
    print(out, len(tris), "triangles")


if __name__ == "__main__":
    main()
