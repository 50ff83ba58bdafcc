#!/usr/bin/env python3
"""Solid occupancy of a packing of convex particles on a regular grid, for
porosity and packing-fraction maps (examples/fixed_bed, examples/silo).

    from packing_grid import hulls, occupancy
    H = hulls("final.vtk")                  # per particle: vertices, hull planes
    solid = occupancy(H, xs, ys, zs)        # bool array (len(xs), len(ys), len(zs))

A grid point is solid if it lies in a particle's convex hull (n.x + c <= 0
for every face plane); each particle tests only the points of its bounding
box."""
import sys

import numpy as np
from scipy.spatial import ConvexHull

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from render_vtk import read_vtk  # noqa: E402


def hulls(path):
    """[(vertices, hull equations)] per particle of a dump polyhedron/vtk file, by atom ID"""
    pts, polys, cell = read_vtk(path)
    verts = {}
    for f, pid in zip(polys, cell["id"]):
        verts.setdefault(int(pid), set()).update(f)
    out = []
    for pid in sorted(verts):
        P = pts[sorted(verts[pid])]
        out.append((P, ConvexHull(P).equations))
    return out


def occupancy(H, xs, ys, zs):
    """bool array: grid point (xs[i], ys[j], zs[k]) inside a particle"""
    solid = np.zeros((len(xs), len(ys), len(zs)), dtype=bool)
    for P, eq in H:
        lo, hi = P.min(axis=0), P.max(axis=0)
        i0, i1 = np.searchsorted(xs, lo[0]), np.searchsorted(xs, hi[0])
        j0, j1 = np.searchsorted(ys, lo[1]), np.searchsorted(ys, hi[1])
        k0, k1 = np.searchsorted(zs, lo[2]), np.searchsorted(zs, hi[2])
        if i1 <= i0 or j1 <= j0 or k1 <= k0:
            continue
        g = np.stack(np.meshgrid(xs[i0:i1], ys[j0:j1], zs[k0:k1], indexing="ij"), axis=-1)
        solid[i0:i1, j0:j1, k0:k1] |= np.all(g @ eq[:, :3].T + eq[:, 3] <= 0.0, axis=-1)
    return solid
