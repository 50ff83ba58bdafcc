#!/usr/bin/env python3
"""Render a POLYDEM polyhedra snapshot (dump polyhedron/vtk, legacy VTK
polydata) to a PNG with matplotlib: every face drawn, shaded by its normal,
coloured by shape.

    python3 tools/render_vtk.py snapshot.vtk picture.png [--elev 20 --azim -60]
"""
import argparse
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402


def read_vtk(path):
    with open(path) as f:
        words = f.read().split()
    i = 0
    pts, polys, cell = None, [], {}
    while i < len(words):
        w = words[i]
        if w == "POINTS":
            n = int(words[i + 1])
            pts = np.array(words[i + 3:i + 3 + 3 * n], dtype=float).reshape(n, 3)
            i += 3 + 3 * n
        elif w == "POLYGONS":
            n = int(words[i + 1])
            i += 3
            for _ in range(n):
                k = int(words[i])
                polys.append([int(x) for x in words[i + 1:i + 1 + k]])
                i += 1 + k
        elif w == "SCALARS":
            name = words[i + 1]
            i += 6  # SCALARS name int 1 LOOKUP_TABLE default
            cell[name] = np.array(words[i:i + len(polys)], dtype=int)
            i += len(polys)
        else:
            i += 1
    if pts is None:
        raise ValueError(f"{path}: no POINTS section")
    return pts, polys, cell


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("vtk")
    ap.add_argument("png")
    ap.add_argument("--elev", type=float, default=22)
    ap.add_argument("--azim", type=float, default=-58)
    ap.add_argument("--title", default=None)
    a = ap.parse_args()

    pts, polys, cell = read_vtk(a.vtk)
    shapes = cell.get("shape", np.ones(len(polys), dtype=int))
    palette = plt.get_cmap("tab10")
    light = np.array([0.4, -0.5, 0.77])
    light /= np.linalg.norm(light)
    faces, colors = [], []
    for poly, s in zip(polys, shapes):
        v = pts[poly]
        n = np.cross(v[1] - v[0], v[2] - v[0])
        nn = np.linalg.norm(n)
        shade = 0.45 + 0.55 * abs(np.dot(n / nn, light)) if nn > 0 else 0.6
        c = np.array(palette((int(s) - 1) % 10)[:3]) * shade
        faces.append(v)
        colors.append(np.clip(c, 0, 1))

    fig = plt.figure(figsize=(7, 7), dpi=110)
    ax = fig.add_subplot(111, projection="3d")
    coll = Poly3DCollection(faces, facecolors=colors, edgecolors=(0, 0, 0, 0.25),
                            linewidths=0.2)
    ax.add_collection3d(coll)
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    c, r = 0.5 * (lo + hi), 0.5 * (hi - lo).max()
    ax.set_xlim(c[0] - r, c[0] + r)
    ax.set_ylim(c[1] - r, c[1] + r)
    ax.set_zlim(c[2] - r, c[2] + r)
    ax.view_init(elev=a.elev, azim=a.azim)
    ax.set_xlabel("x")
    ax.set_ylabel("y")
    ax.set_zlabel("z")
    ax.set_title(a.title or f"{a.vtk.split('/')[-1]}: {len(polys)} faces")
    fig.tight_layout()
    fig.savefig(a.png)
    print(f"render_vtk: wrote {a.png}")


if __name__ == "__main__":
    sys.exit(main())
