#!/usr/bin/env python3
"""The ball mill's picture (ball_mill.png): left, the charge seen along the
drum's axis after the last revolution (balls orange, ore blue); right, per
revolution, the torque of the charge on the drum against the torque arm
M g x_cm and against M g x_cm - dL/T (the balance, mill_balance.py), and the
power draw.

    /usr/bin/python3 plot_ball_mill.py [mill.375000.vtk] [mill_rev.txt] [log.ball_mill]
"""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from render_vtk import read_vtk  # noqa: E402
from mill_balance import mill_balance  # noqa: E402

vtk = sys.argv[1] if len(sys.argv) > 1 else "mill.375000.vtk"
rev = sys.argv[2] if len(sys.argv) > 2 else "mill_rev.txt"
log = sys.argv[3] if len(sys.argv) > 3 else "log.ball_mill"

pts, polys, cell = read_vtk(vtk)
light = np.array([0.35, -0.75, 0.55])
light /= np.linalg.norm(light)
shape = cell.get("shape", np.zeros(len(polys), dtype=int))
ball = shape.max()    # the second template (polyhedron_shape ball)
verts, colors = [], []
for k, p in enumerate(polys):
    v = pts[p]
    n = np.cross(v[1] - v[0], v[2] - v[0])
    nn = np.linalg.norm(n)
    if nn == 0 or n[1] / nn > -1e-9:    # faces the viewer (-y) only
        continue
    base = np.array([0.95, 0.5, 0.1]) if shape[k] == ball else np.array([0.15, 0.4, 0.7])
    verts.append(v[:, [0, 2]])
    colors.append(np.clip(base * (0.4 + 0.6 * abs(np.dot(n / nn, light))), 0, 1))

d = np.array(mill_balance(log, rev))    # torque, arm, dL/T, power
fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4.8), gridspec_kw={"width_ratios": [1, 1.3]})
a.add_collection(PolyCollection(verts, facecolors=colors, edgecolors=(0, 0, 0, 0.3), linewidths=0.2))
t = np.linspace(0, 2 * np.pi, 200)
a.plot(0.05 * np.cos(t), 0.05 * np.sin(t), color="0.3", lw=1)
a.set_aspect("equal")
a.set_xlim(-0.055, 0.055)
a.set_ylim(-0.055, 0.055)
a.set_xlabel("x [m]")
a.set_ylabel("z [m]")
a.set_title("after 5 revolutions at 100 rpm (75 % critical)")
r = np.arange(1, len(d) + 1)
b.plot(r, -1e3 * d[:, 0], "o-", ms=8, label="torque of the charge on the drum, $-T_y$")
b.plot(r, -1e3 * d[:, 1], "s--", label="torque arm $-M g\\, x_{cm}$ (Hogg & Fuerstenau 1972)")
b.plot(r, -1e3 * (d[:, 1] - d[:, 2]), "x", ms=10, color="k",
       label="$-(M g\\, x_{cm} - \\Delta L_y / T)$: the balance")
b.set_xlabel("revolution")
b.set_xticks(r)
b.set_ylabel("torque [mN m]")
b.set_ylim(0, 1.4e3 * max(-d[:, 0].min(), -d[:, 1].min()))
b.legend(loc="lower right", fontsize=9)
b2 = b.twinx()
b2.plot(r, 1e3 * d[:, 3], "^:", color="tab:green", alpha=0.6)
b2.set_ylabel("power draw [mW]", color="tab:green")
b2.set_ylim(0, 1.4e3 * d[:, 3].max())
b.set_title("per revolution (averaged over every step)")
fig.tight_layout()
fig.savefig("ball_mill.png", dpi=110)
print("wrote ball_mill.png")
