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
import struct
import sys


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


def normal(t):
    u = [t[1][i] - t[0][i] for i in range(3)]
    v = [t[2][i] - t[0][i] for i in range(3)]
    return (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])


def check_inward(tris, z0, H):
    """every normal points into the cylinder: towards the axis (side) or up (floor)"""
    for t in tris:
        c = [sum(p[i] for p in t) / 3 for i in range(3)]
        n = normal(t)
        inside = (-c[0], -c[1], z0 + H / 2 - c[2])
        assert sum(n[i] * inside[i] for i in range(3)) > 0, t


def write_stl(path, tris, title):
    with open(path, "wb") as f:
        f.write(title.encode().ljust(80, b" ")[:80])
        f.write(struct.pack("<I", len(tris)))
        for t in tris:
            n = normal(t)
            ln = math.sqrt(sum(x * x for x in n))
            f.write(struct.pack("<3f", *(x / ln for x in n)))
            for p in t:
                f.write(struct.pack("<3f", *p))
            f.write(b"\0\0")


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
