"""Triangle meshes for fix wall/mesh, shared by the mesh scripts of the examples
and benchmarks (they put tools/ on sys.path): a triangle's normal and whether it
faces a given way, binary STL with unit normals, and the triangulation of a
grid of vertices. A triangle is three (x, y, z) points; its normal is
(t1 - t0) x (t2 - t0)."""
import math
import struct


def normal(t):
    """(t1 - t0) x (t2 - t0), not normalised"""
    u = [t[1][i] - t[0][i] for i in range(3)]
    v = [t[2][i] - t[0][i] for i in range(3)]
    return (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])


def faces(t, towards):
    """whether t's normal has a positive component along towards(c), c its centroid"""
    c = [sum(p[i] for p in t) / 3 for i in range(3)]
    return sum(a * b for a, b in zip(normal(t), towards(c))) > 0


def write_stl(path, tris, title):
    """binary STL: title (str) in the 80-byte header, each facet's unit normal"""
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


def grid_triangles(P, nx, ny):
    """Two triangles per cell of the (nx+1) x (ny+1) vertex grid P[i, j], alternating
    diagonals; with i along x and j along y, they face +z."""
    tris = []
    for j in range(ny):
        for i in range(nx):
            a, b, c, d = P[i, j], P[i + 1, j], P[i, j + 1], P[i + 1, j + 1]
            tris += [(a, b, d), (a, d, c)] if (i + j) % 2 == 0 else [(a, b, c), (b, d, c)]
    return tris
