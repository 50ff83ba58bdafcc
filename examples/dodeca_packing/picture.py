#!/usr/bin/env python3
"""Picture of one settled packing: the dodecahedra in the cylinder (side view,
the cylinder drawn as a wire frame) beside its packing-fraction profile phi(z)
with the two fill heights.

    picture.py run.vtk D_CIRC out.png [--title ...]"""
import argparse
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from analyze import analyze  # noqa: E402
sys.path.insert(0, __file__.rsplit("/", 1)[0] + "/../../tools")
from render_vtk import read_vtk  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("vtk")
    ap.add_argument("d", type=float)
    ap.add_argument("png")
    ap.add_argument("--title", default=None)
    a = ap.parse_args()
    pts, polys, cell = read_vtk(a.vtk)
    r, zs, phi = analyze(a.vtk, a.d, 0.05, 120)

    fig = plt.figure(figsize=(9, 7), dpi=110)
    ax = fig.add_axes([0.0, 0.02, 0.5, 0.92], projection="3d")
    light = np.array([0.4, -0.5, 0.77])
    light /= np.linalg.norm(light)
    cmap = plt.get_cmap("viridis")
    ids = cell["id"]
    faces, colors = [], []
    for poly, pid in zip(polys, ids):
        v = pts[poly]
        n = np.cross(v[1] - v[0], v[2] - v[0])
        shade = 0.45 + 0.55 * abs(np.dot(n / np.linalg.norm(n), light))
        c = np.array(cmap((pid * 0.618) % 1.0)[:3]) * shade
        faces.append(v)
        colors.append(np.clip(c, 0, 1))
    ax.add_collection3d(Poly3DCollection(faces, facecolors=colors, edgecolors=(0, 0, 0, 0.3),
                                         linewidths=0.2))
    t = np.linspace(0, 2 * np.pi, 121)
    for z in (0.0, 0.2):
        ax.plot(0.05 * np.cos(t), 0.05 * np.sin(t), z, color="0.4", lw=0.8)
    for k in range(0, 120, 15):
        ax.plot([0.05 * np.cos(t[k])] * 2, [0.05 * np.sin(t[k])] * 2, [0, 0.2], color="0.6", lw=0.5)
    ax.plot(0.05 * np.cos(t), 0.05 * np.sin(t), 0.16, color="k", ls="--", lw=1.0)
    ax.set_xlim(-0.055, 0.055)
    ax.set_ylim(-0.055, 0.055)
    ax.set_zlim(0, 0.2)
    ax.set_box_aspect((0.11, 0.11, 0.2), zoom=1.0)
    ax.view_init(elev=12, azim=-60)
    ax.set_axis_off()
    ax.set_title(a.title or "63 dodecahedra, d = %.1f cm (dashed: 16 cm)" % (100 * a.d), fontsize=10)

    ax2 = fig.add_axes([0.58, 0.09, 0.39, 0.84])
    ax2.plot(phi, 100 * zs, color="C0", lw=1)
    ax2.axvline(r["phi_b"], color="C2", ls="-", lw=1, label="phi_b = %.3f" % r["phi_b"])
    ax2.axvline(0.5 * r["phi_b"], color="C2", ls=":", lw=1, label="phi_b / 2")
    ax2.axhline(100 * r["H_top"], color="C3", lw=1, label="H_top = %.1f cm" % (100 * r["H_top"]))
    ax2.axhline(100 * r["H_half"], color="C1", lw=1, label="H_half = %.1f cm" % (100 * r["H_half"]))
    ax2.axhline(16, color="k", ls="--", lw=1, label="seed: 16 cm")
    ax2.axhspan(100 * 0.5 * a.d, 100 * (r["H_top"] - 1.5 * a.d), color="0.92", label="bulk range")
    ax2.set_xlabel("solid fraction of the section, phi(z)")
    ax2.set_ylabel("z (cm)")
    ax2.set_ylim(0, 20)
    ax2.set_xlim(0, 1)
    ax2.legend(fontsize=8, loc="upper right")
    fig.savefig(a.png)
    print("wrote", a.png)


if __name__ == "__main__":
    main()
