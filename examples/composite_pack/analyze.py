#!/usr/bin/env python3
"""Solid fraction of the settled crosses (examples/composite_pack).

    /usr/bin/python3 analyze.py [pack.120000.txt] [--profile phi_z.txt]

Reads the final dump (id x y z qw qx qy qz) and tests Monte Carlo points
against every cross exactly: a point p is inside a cross at x with
orientation R and scale s when, in its body frame u = R^T (p - x) / s, the
largest |u_k| is at most 3/2 and the other two at most 1/2 (three 3 x 1 x 1
bars along the body axes; the composite's body frame is the input frame, the
cross being symmetric). Periodic images across x and y are included. Prints
the solid fraction per 1 mm layer and the bulk value between 2 arm lengths
above the floor and 2 arm lengths below the bed's surface (where the
profile falls to half its plateau).
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from render_vtk import read_dump, rotation  # noqa: E402,F401
from packing_grid import bed_main, bulk_of_profile  # noqa: E402

L = 0.03        # periodic box side [m]
S = 0.002       # scale: arms 6 x 2 x 2 mm
ARM = 3 * S     # cross size [m]
RB = S * np.sqrt(1.5 ** 2 + 0.5 ** 2 + 0.5 ** 2)    # bounding radius


def inside(pts, x, q):
    """mask of the points inside the cross (x, q) or one of its x/y images"""
    R = rotation(q)
    hit = np.zeros(len(pts), dtype=bool)
    for ix in (-1, 0, 1):
        for iy in (-1, 0, 1):
            c = x + np.array([ix * L, iy * L, 0.0])
            near = np.all(np.abs(pts - c) <= RB, axis=1)
            if not near.any():
                continue
            u = np.abs((pts[near] - c) @ R) / S
            u.sort(axis=1)
            hit[np.flatnonzero(near)[(u[:, 2] <= 1.5) & (u[:, 1] <= 0.5)]] = True
    return hit


def profile(x, q, zmax, per_mm=20000, seed=1):
    rng = np.random.default_rng(seed)
    zs, phi = [], []
    for z0 in np.arange(0.0, zmax, 0.001):
        pts = rng.uniform([0, 0, z0], [L, L, z0 + 0.001], size=(per_mm, 3))
        hit = np.zeros(per_mm, dtype=bool)
        cand = np.flatnonzero(np.abs(x[:, 2] - (z0 + 0.0005)) <= RB + 0.0005)
        for k in cand:
            hit |= inside(pts, x[k], q[k])
        zs.append(z0 + 0.0005)
        phi.append(hit.mean())
    return np.array(zs), np.array(phi)


def bulk(zs, phi):
    return bulk_of_profile(zs, phi, 2 * ARM, 3)


def describe(x, mean, err, top, n):
    return (f"{len(x)} crosses; bed surface (half plateau) {1e3 * top:.1f} mm; bulk solid fraction "
            f"{mean:.4f} +- {err:.4f} over {n} layers of 1 mm; mean over the bed "
            f"{len(x) * 7 * S ** 3 / (L * L * top):.4f}")


if __name__ == "__main__":
    bed_main("pack.120000.txt", profile, RB, bulk, describe)
