#!/usr/bin/env python3
"""The settled Raschig rings (ring_pack.png): left, the bed in perspective
(every sector of every ring drawn, shaded by its normal); right, the solid
fraction per 1 mm layer (analyze.py), the bulk value and the band of the
packing tables' ceramic rings (void fraction 0.73-0.74).

    /usr/bin/python3 plot_ring_pack.py [pack.180000.vtk] [pack.180000.txt]
"""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "..", "tools"))
sys.path.insert(0, here)
from render_vtk import read_vtk  # noqa: E402
from analyze import L, S, SOLID, bulk, profile, read_dump  # noqa: E402

vtk = sys.argv[1] if len(sys.argv) > 1 else "pack.180000.vtk"
dump = sys.argv[2] if len(sys.argv) > 2 else "pack.180000.txt"

pts, polys, cell = read_vtk(vtk)
ids = cell.get("id", np.zeros(len(polys), dtype=int))
light = np.array([0.4, -0.6, 0.7])
light /= np.linalg.norm(light)
rng = np.random.default_rng(3)
palette = {i: rng.uniform(0.25, 0.95, 3) for i in np.unique(ids)}
verts, colors = [], []
for k, p in enumerate(polys):
    v = pts[p]
    n = np.cross(v[1] - v[0], v[2] - v[0])
    nn = np.linalg.norm(n)
    if nn == 0:
        continue
    verts.append(v)
    colors.append(np.clip(palette[ids[k]] * (0.35 + 0.65 * abs(np.dot(n / nn, light))), 0, 1))

x, q = read_dump(dump)
zs, phi = profile(x, q, x[:, 2].max() + S)
mean, err, top, nl = bulk(zs, phi)

fig = plt.figure(figsize=(11, 6.2))
a = fig.add_subplot(1, 2, 1, projection="3d")
a.add_collection3d(Poly3DCollection(verts, facecolors=colors, edgecolors=(0, 0, 0, 0.25),
                                    linewidths=0.1))
zt = 1.1 * top + S
a.set_xlim(-0.006, L + 0.006)
a.set_ylim(-0.006, L + 0.006)
a.set_zlim(0, zt)
a.set_box_aspect((1, 1, zt / (L + 0.012)))
a.view_init(elev=16, azim=-62)
a.set_xlabel("x [m]")
a.set_ylabel("y [m]")
a.set_zlabel("z [m]")
a.set_title(f"{len(x)} Raschig rings settled (8 x 8 mm, wall 1 mm)")
b = fig.add_subplot(1, 2, 2)
b.axvspan(1 - 0.74, 1 - 0.73, color="tab:orange", alpha=0.35,
          label="ceramic rings, tables: 0.26-0.27")
b.plot(phi, 1e3 * zs, "-", color="tab:blue")
b.axvline(mean, color="k", ls="--", lw=1, label=f"bulk {mean:.3f} ± {err:.3f}")
b.axhspan(1e3 * 2 * S, 1e3 * (top - 2 * S), color="0.9", label="bulk layers")
b.set_xlabel("solid fraction of the layer (1 - void fraction)")
b.set_ylabel("height z [mm]")
b.set_xlim(0, 0.5)
b.legend(loc="upper right")
b.set_title("solid fraction per 1 mm layer")
fig.tight_layout()
fig.savefig("ring_pack.png", dpi=110)
print(f"wrote ring_pack.png; bulk solid fraction {mean:.4f} +- {err:.4f}, "
      f"envelope fraction {mean / SOLID:.4f}")
