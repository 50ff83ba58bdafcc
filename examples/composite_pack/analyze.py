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
import argparse

import numpy as np

L = 0.03        # periodic box side [m]
S = 0.002       # scale: arms 6 x 2 x 2 mm
ARM = 3 * S     # cross size [m]
RB = S * np.sqrt(1.5 ** 2 + 0.5 ** 2 + 0.5 ** 2)    # bounding radius


def read_dump(path):
    rows, take = [], False
    for line in open(path):
        if line.startswith("ITEM: ATOMS"):
            take = True
            continue
        if line.startswith("ITEM:"):
            take = False
            continue
        if take:
            rows.append([float(v) for v in line.split()])
    a = np.array(rows)
    return a[:, 1:4], a[:, 4:8]


def rotation(q):
    w, x, y, z = q / np.linalg.norm(q)
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


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
    plateau = np.median(phi[(zs > 2 * ARM) & (phi > 0.5 * phi.max())])
    top = zs[np.flatnonzero(phi > 0.5 * plateau).max()]
    sel = (zs > 2 * ARM) & (zs < top - 2 * ARM)
    return phi[sel].mean(), phi[sel].std() / np.sqrt(max(1, sel.sum() // 3)), top, sel.sum()


if __name__ == "__main__":
    ap = argparse.ArgumentParser()
    ap.add_argument("dump", nargs="?", default="pack.120000.txt")
    ap.add_argument("--profile", default="phi_z.txt")
    a = ap.parse_args()
    x, q = read_dump(a.dump)
    zs, phi = profile(x, q, x[:, 2].max() + RB)
    np.savetxt(a.profile, np.column_stack([zs, phi]), header="z [m]  solid fraction", fmt="%.6g")
    mean, err, top, n = bulk(zs, phi)
    print(f"{len(x)} crosses; bed surface (half plateau) {1e3 * top:.1f} mm; bulk solid fraction "
          f"{mean:.4f} +- {err:.4f} over {n} layers of 1 mm; mean over the bed "
          f"{len(x) * 7 * S ** 3 / (L * L * top):.4f}")
