#!/usr/bin/env python3
"""Pictures of the hopper example: four snapshots (with the meshes) and the
discharge curve from the log.
    /usr/bin/python3 plot_hopper.py [log.hopper] [prefix]
writes hopper.png (snapshots) and hopper_discharge.png (grains in the hopper
and force on the floor against time)."""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../tools"))
import render_vtk  # noqa: E402

log = sys.argv[1] if len(sys.argv) > 1 else "log.hopper"
prefix = sys.argv[2] if len(sys.argv) > 2 else "hopper"


def thermo(path):
    rows, header = [], None
    with open(path) as f:
        for line in f:
            w = line.split()
            if w and w[0] == "Step":
                header = w
                continue
            if header and len(w) == len(header):
                try:
                    rows.append([float(x) for x in w])
                except ValueError:
                    pass
    return header, np.array(rows)


steps = sorted(int(f.split(".")[1]) for f in os.listdir(".") if f.startswith(prefix + ".") and f.endswith(".vtk"))
dt = 8.0e-6
want = [0.04, 0.2, 0.32, steps[-1] * dt]
pick = [min(steps, key=lambda s: abs(s * dt - t)) for t in want]
titles = ["pouring", "settled on the closed gate", "discharging", "discharged"]
fig = plt.figure(figsize=(10, 10), dpi=100)
lims = (np.array([-0.07, -0.07, 0.02]), np.array([0.07, 0.07, 0.2]))
meshes = ["hopper.stl", "floor.stl"]
for k, (s, t) in enumerate(zip(pick, titles)):
    ax = fig.add_subplot(2, 2, k + 1, projection="3d")
    m = meshes + (["gate.stl"] if s * dt <= 0.2 else [])
    render_vtk.draw(ax, f"{prefix}.{s}.vtk", m, elev=18, azim=-60, limits=lims)
    ax.set_axis_off()
    ax.set_title(f"{t}, t = {s * dt:.2f} s", fontsize=10)
fig.suptitle("POLYDEM hopper: 400 dodecahedra (blue), cubes (orange), 24-gon pellets (green)",
             fontsize=11)
fig.subplots_adjust(left=0, right=1, bottom=0, top=0.94, wspace=0, hspace=0.02)
fig.savefig("hopper.png")
print("wrote hopper.png")

h, d = thermo(log)
t = d[:, h.index("Time")]
n_in = d[:, h.index("v_inhopper")]
mass = None
with open(log) as f:
    for line in f:
        if "particle(s) inserted (mass" in line:
            mass = float(line.split("(mass")[1].split(")")[0])
# steady discharge: a line through the samples with 20-80 % of the grains left
sel = (t > 0.2) & (n_in < 0.8 * n_in.max()) & (n_in > 0.2 * n_in.max())
rate = -np.polyfit(t[sel], n_in[sel], 1)[0]
mgrain = mass / d[-1, h.index("Atoms")]
# Beverloo et al. (1961): W = C rho_b sqrt(g) (D - k d)^2.5, C = 0.58, k = 1.5,
# rho_b = 0.6 rho, d = the volume-equivalent diameter of the mean grain
rho, D = 1500.0, 0.032
dgr = (6.0 * mgrain / (np.pi * rho)) ** (1.0 / 3.0)
W = 0.58 * 0.6 * rho * np.sqrt(9.81) * (D - 1.5 * dgr) ** 2.5
print(f"discharge: {rate:.0f} grains/s = {rate * mgrain:.4f} kg/s; Beverloo {W:.4f} kg/s "
      f"(d = {dgr * 1e3:.2f} mm); floor load at the end {-d[-1, h.index('f_floor[3]')]:.4f} N, "
      f"weight {mass * 9.81:.4f} N")
fig, ax = plt.subplots(figsize=(6, 3.6), dpi=110)
ax.plot(t, d[:, h.index("v_inhopper")], label="grains in the hopper")
ax.plot(t, d[:, h.index("Atoms")], "--", label="grains inserted")
ax.axvline(0.2, color="gray", lw=0.8)
ax.text(0.205, 20, "gate removed", fontsize=8, color="gray")
ax.set_xlabel("time (s)")
ax.set_ylabel("grains")
ax2 = ax.twinx()
ax2.plot(t, -d[:, h.index("f_floor[3]")], color="C2", lw=0.8, label="load on the floor (N)")
ax2.set_ylabel("vertical load on the floor (N)", color="C2")
ax2.axhline(mass * 9.81, color="C2", ls=":", lw=0.8)
ax2.text(0.01, mass * 9.81 * 1.03, "weight of the grains", fontsize=8, color="C2")
ax.legend(loc="upper left", bbox_to_anchor=(0.1, 0.88), fontsize=8)
fig.tight_layout()
fig.savefig("hopper_discharge.png")
print("wrote hopper_discharge.png")
