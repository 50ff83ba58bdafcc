#!/usr/bin/env python3
"""Render a POLYDEM polyhedra snapshot (dump polyhedron/vtk, legacy VTK
polydata) to a PNG with matplotlib: every face drawn, shaded by its normal,
coloured by shape.

    python3 tools/render_vtk.py snapshot.vtk picture.png [--elev 20 --azim -60]
                                [--mesh wall.stl ...]

--mesh draws the edges of STL walls (ASCII or binary) as a light wireframe.
The functions read_vtk, read_stl, read_dump, rotation, faces_colors and draw
serve other scripts (examples).
"""
import argparse
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Line3DCollection, Poly3DCollection  # noqa: E402


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


def read_stl(path):
    """Triangles (n x 3 x 3) of an ASCII or binary STL file."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:5] == b"solid" and b"\0" not in data[:400]:
        v = [float(x) for w in data.decode().split("vertex")[1:] for x in w.split()[:3]]
        return np.array(v).reshape(-1, 3, 3)
    n = int.from_bytes(data[80:84], "little")
    rec = np.frombuffer(data[84:84 + 50 * n], dtype=np.uint8).reshape(n, 50)
    return rec[:, 12:48].copy().view("<f4").reshape(n, 3, 3).astype(float)


def read_dump(path):
    """Positions (n x 3) and quaternions (n x 4, w i j k) of a dump custom
    file of columns id x y z qw qi qj qk (its last snapshot's rows)."""
    rows, take = [], False
    for line in open(path):
        if line.startswith("ITEM:"):
            take = line.startswith("ITEM: ATOMS")
            if take:
                rows = []
            continue
        if take:
            rows.append([float(v) for v in line.split()])
    a = np.array(rows)
    return a[:, 1:4], a[:, 4:8]


def rotation(q):
    """Rotation matrix (body to lab) of a quaternion w, i, j, k."""
    w, x, y, z = q / np.linalg.norm(q)
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def faces_colors(pts, polys, cell, color_by="shape"):
    shapes = cell.get(color_by, cell.get("shape", np.ones(len(polys), dtype=int)))
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
    return faces, colors


def draw(ax, vtk, meshes=(), elev=22, azim=-58, limits=None):
    """Draw a snapshot (and mesh wireframes) into a 3-D axis; returns the
    number of faces. limits: (lo, hi) arrays, else the data's box."""
    pts, polys, cell = read_vtk(vtk)
    faces, colors = faces_colors(pts, polys, cell)
    allp = [pts]
    for m in meshes:
        tri = read_stl(m)
        edges = np.concatenate([tri[:, [0, 1]], tri[:, [1, 2]], tri[:, [2, 0]]])
        ax.add_collection3d(Line3DCollection(edges, colors=(0.35, 0.35, 0.4, 0.35),
                                             linewidths=0.4))
        allp.append(tri.reshape(-1, 3))
    ax.add_collection3d(Poly3DCollection(faces, facecolors=colors,
                                         edgecolors=(0, 0, 0, 0.25), linewidths=0.2))
    if limits is None:
        allp = np.concatenate(allp)
        limits = (allp.min(axis=0), allp.max(axis=0))
    lo, hi = limits
    c, r = 0.5 * (lo + hi), 0.5 * (hi - lo).max()
    ax.set_xlim(c[0] - r, c[0] + r)
    ax.set_ylim(c[1] - r, c[1] + r)
    ax.set_zlim(c[2] - r, c[2] + r)
    ax.view_init(elev=elev, azim=azim)
    return len(polys)


def draw_front(ax, pts, polys, cell, keep=None, cmap="viridis", zrange=None):
    """Orthographic front view (along +y, x to the right, z up) on a 2-D axis:
    the faces of each particle that face the viewer, particles drawn far to
    near; shaded by the face normal, coloured by the particle's height.
    keep(centroid) -> bool selects particles (e.g. a slice |y| < w).
    Returns the number of particles drawn."""
    from matplotlib.collections import PolyCollection
    by = {}
    for k, pid in enumerate(cell["id"]):
        by.setdefault(int(pid), []).append(k)
    light = np.array([0.35, -0.75, 0.55])
    light /= np.linalg.norm(light)
    parts = []
    for pid, ks in by.items():
        c = np.mean([pts[polys[k]].mean(axis=0) for k in ks], axis=0)
        if keep is None or keep(c):
            parts.append((c, ks))
    parts.sort(key=lambda t: -t[0][1])
    zs = np.array([c[2] for c, _ in parts]) if parts else np.zeros(1)
    zlo, zhi = zrange if zrange else (zs.min(), max(zs.max(), zs.min() + 1e-9))
    cm = plt.get_cmap(cmap)
    verts, colors = [], []
    for c, ks in parts:
        base = np.array(cm(0.15 + 0.75 * (c[2] - zlo) / (zhi - zlo))[:3])
        for k in ks:
            v = pts[polys[k]]
            n = np.cross(v[1] - v[0], v[2] - v[0])
            nn = np.linalg.norm(n)
            if nn == 0 or n[1] / nn > -1e-9:      # faces the viewer (-y) only
                continue
            shade = 0.35 + 0.65 * abs(np.dot(n / nn, light))
            verts.append(v[:, [0, 2]])
            colors.append(np.clip(base * shade, 0, 1))
    ax.add_collection(PolyCollection(verts, facecolors=colors, edgecolors=(0, 0, 0, 0.3), linewidths=0.15))
    ax.set_aspect("equal")
    return len(parts)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("vtk")
    ap.add_argument("png")
    ap.add_argument("--elev", type=float, default=22)
    ap.add_argument("--azim", type=float, default=-58)
    ap.add_argument("--title", default=None)
    ap.add_argument("--mesh", nargs="*", default=[], help="STL walls to draw as wireframes")
    a = ap.parse_args()

    fig = plt.figure(figsize=(7, 7), dpi=110)
    ax = fig.add_subplot(111, projection="3d")
    nf = draw(ax, a.vtk, a.mesh, a.elev, a.azim)
    ax.set_xlabel("x")
    ax.set_ylabel("y")
    ax.set_zlabel("z")
    ax.set_title(a.title or f"{a.vtk.split('/')[-1]}: {nf} faces")
    fig.tight_layout()
    fig.savefig(a.png)
    print(f"render_vtk: wrote {a.png}")


if __name__ == "__main__":
    sys.exit(main())
