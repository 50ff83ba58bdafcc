#!/usr/bin/env python3
"""Meshes of the seed's silo (polyhedral-multigpu-dem section 4.1, Fig. 19),
binary STL, axis z, every normal pointing into the silo (towards the grains).

    make_silo.py silo.stl lid.stl [--nth 216] [--per-wave 8] [--cone-rows 48]

Seed: total height 10.6 m, cylinder diameter 2.1 m, hopper outlet 0.67 m,
corrugated side walls, about 150,000 triangles. Not in the seed, chosen here
(README): hopper half-angle 30 deg from the vertical (cone height 1.238 m),
horizontal (ring) corrugations of pitch 0.25 m and depth 0.05 m (the radius
runs from 1.05 m at the crests to 1.10 m in the troughs, a cosine, starting at
a crest where the cylinder meets the cone), as on corrugated-steel silos.
silo.stl: the cone (z = 0 .. 1.238 m) and the corrugated cylinder (to
z = 10.6 m), nth segments around; lid.stl: the closed outlet (a fan of nth
triangles at z = 0)."""
import argparse
import math
import struct

R, R0, HTOT = 1.05, 0.335, 10.6
ALPHA = math.radians(30.0)
HCONE = (R - R0) / math.tan(ALPHA)
PITCH, DEPTH = 0.25, 0.05


def radius(z):
    if z <= HCONE:
        return R0 + z * math.tan(ALPHA)
    return R + 0.5 * DEPTH * (1.0 - math.cos(2.0 * math.pi * (z - HCONE) / PITCH))


def rings(per_wave, cone_rows):
    zs = [HCONE * k / cone_rows for k in range(cone_rows + 1)]
    nw = int(round((HTOT - HCONE) / PITCH * per_wave))
    zs += [HCONE + (HTOT - HCONE) * k / nw for k in range(1, nw + 1)]
    return zs


def write_stl(path, tris):
    with open(path, "wb") as f:
        f.write(b"POLYDEM silo".ljust(80, b" "))
        f.write(struct.pack("<I", len(tris)))
        for a, b, c in tris:
            u = [b[i] - a[i] for i in range(3)]
            v = [c[i] - a[i] for i in range(3)]
            n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
            ln = math.sqrt(sum(x * x for x in n)) or 1.0
            f.write(struct.pack("<12fH", *[x / ln for x in n], *a, *b, *c, 0))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("silo")
    ap.add_argument("lid")
    ap.add_argument("--nth", type=int, default=216)
    ap.add_argument("--per-wave", type=int, default=8)
    ap.add_argument("--cone-rows", type=int, default=48)
    a = ap.parse_args()
    n = a.nth
    ang = [2.0 * math.pi * k / n for k in range(n)]
    zs = rings(a.per_wave, a.cone_rows)
    pts = [[(radius(z) * math.cos(t), radius(z) * math.sin(t), z) for t in ang] for z in zs]
    tris = []
    for j in range(len(zs) - 1):
        for k in range(n):
            p0, p1 = pts[j][k], pts[j][(k + 1) % n]
            q0, q1 = pts[j + 1][k], pts[j + 1][(k + 1) % n]
            tris += [(p0, q0, p1), (p1, q0, q1)]     # (t1-t0)x(t2-t0) points to the axis
    for a_, b_, c_ in tris[:2]:
        u = [b_[i] - a_[i] for i in range(3)]
        v = [c_[i] - a_[i] for i in range(3)]
        nrm = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
        assert nrm[0] * a_[0] + nrm[1] * a_[1] < 0.0, "normal must point into the silo"
    lid = [((0.0, 0.0, 0.0), pts[0][k], pts[0][(k + 1) % n]) for k in range(n)]   # +z
    write_stl(a.silo, tris)
    write_stl(a.lid, lid)
    print("%s: %d triangles (%d rings x %d around; cone height %.4f m); %s: %d triangles"
          % (a.silo, len(tris), len(zs), n, HCONE, a.lid, len(lid)))


if __name__ == "__main__":
    main()
