#!/usr/bin/env python3
"""Writes ring.stl: a Raschig ring of outer diameter = length = 1 and wall
1/8 (the ceramic rings of the packing tables: 1 in with a 1/8 in wall, 2 in
with a 1/4 in wall), as a closed surface. The circles are 12-gons whose area
equals the circle's (vertex radius sqrt(pi/3) times the circle's), so the
ring's solid volume pi/4 (1 - 0.75^2) and its envelope pi/4 are the round
ring's. Scaled in the input (polyhedron_shape ... scale).

    /usr/bin/python3 make_ring.py        # writes ring.stl
"""
import math

N = 12                    # sides of the polygons
D, LEN, WALL = 1.0, 1.0, 0.125
S = math.sqrt(math.pi / ((N / 2) * math.sin(2 * math.pi / N)))    # equal area
RO, RI, H = 0.5 * D * S, (0.5 * D - WALL) * S, 0.5 * LEN


def corner(rad, k, z):
    a = (2 * (k % N) - 1) * math.pi / N
    return (rad * math.cos(a), rad * math.sin(a), z)


def facet(f, a, b, c):
    f.write(" facet normal 0 0 0\n  outer loop\n")
    for p in (a, b, c):
        f.write("   vertex %.17g %.17g %.17g\n" % p)
    f.write("  endloop\n endfacet\n")


with open("ring.stl", "w") as f:
    f.write("solid ring\n")
    for k in range(N):
        o0, o1 = (lambda z: corner(RO, k, z)), (lambda z: corner(RO, k + 1, z))
        i0, i1 = (lambda z: corner(RI, k, z)), (lambda z: corner(RI, k + 1, z))
        facet(f, o0(-H), o1(-H), o1(H)); facet(f, o0(-H), o1(H), o0(H))      # outside
        facet(f, i0(-H), i0(H), i1(H)); facet(f, i0(-H), i1(H), i1(-H))      # inside
        facet(f, i0(H), o0(H), o1(H)); facet(f, i0(H), o1(H), i1(H))         # top
        facet(f, i0(-H), o1(-H), o0(-H)); facet(f, i0(-H), i1(-H), o1(-H))   # bottom
    f.write("endsolid ring\n")
