#!/usr/bin/env python3
"""Oedometer example: per load step the lid's force against its target
(mean over the last 40 % of the hold), the mean vertical stress
sigma_v = (|F_lid| + |F_floor|) / (2 A) (frictionless walls: the weight goes
to the floor), the mean horizontal stress sigma_h = (normal force on the
tube) / (2 pi R h), h the lid's height, and K0 = sigma_h / sigma_v; writes
PREFIX.png (PREFIX: that of the run's files, PREFIX_lid.txt and
PREFIX_wall.txt; default oedometer). The hold of each load step is read from
the load's staircase (in.oedometer's -var hold). PHI (degrees, optional):
the bed's own angle of repose (analyze_repose.py), drawn as Jaky's line.
    /usr/bin/python3 analyze.py [PREFIX [PHI]]"""
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

R, START, DT = 0.03, 50000, 1.6e-5
A = math.pi * R**2


def tube_areas(path="tube.stl"):
    tris, cur = [], []
    for line in open(path):
        w = line.split()
        if w and w[0] == "vertex":
            cur.append(np.array([float(x) for x in w[1:]]))
            if len(cur) == 3:
                tris.append(0.5 * np.linalg.norm(np.cross(cur[1] - cur[0], cur[2] - cur[0])))
                cur = []
    return np.array(tris)


PREFIX = sys.argv[1] if len(sys.argv) > 1 else "oedometer"
PHI = float(sys.argv[2]) if len(sys.argv) > 2 else None


def wall_snapshots(path=PREFIX + "_wall.txt"):
    snaps, lines = {}, open(path).read().split("\n")
    k = 0
    while k < len(lines):
        w = lines[k].split()
        if len(w) == 2 and not lines[k].startswith("#"):
            step, n = int(w[0]), int(w[1])
            snaps[step] = np.array([float(lines[k + 1 + i].split()[1]) for i in range(n)])
            k += n + 1
        else:
            k += 1
    return snaps


lid = np.loadtxt(PREFIX + "_lid.txt")
step, t, load, Flid, Ffloor, zlid = lid[:, 0], lid[:, 1], lid[:, 2], lid[:, 3], lid[:, 4], lid[:, 5]
HOLD = int(step[np.nonzero(np.diff(load))[0][0] + 1]) - START    # the first rise of the load
areas = tube_areas()
walls = wall_snapshots()
rows = []
print("| sigma_v target (kPa) | lid force (N) | target (N) | difference | sigma_v mean (kPa) | sigma_h mean (kPa) | K0 |")
print("|---|---|---|---|---|---|---|")
for k in range(4):
    lo, hi = START + k * HOLD + 0.6 * HOLD, START + (k + 1) * HOLD
    sel = (step >= lo) & (step < hi)
    F, target = Flid[sel].mean(), load[sel].mean()
    sv = (Flid[sel] - Ffloor[sel]).mean() / (2 * A)    # the floor is pushed down
    ws = [s for s in walls if lo <= s < hi]
    h = zlid[sel].mean()
    sh = np.mean([np.sum(walls[s] * areas) for s in ws]) / (2 * math.pi * R * h)
    rows.append((target / A, F, target, sv, sh))
    print(f"| {target / A / 1e3:.0f} | {F:.4f} | {target:.4f} | {100 * (F / target - 1):+.3f} % | "
          f"{sv / 1e3:.3f} | {sh / 1e3:.3f} | {sh / sv:.3f} |")

fig, (a1, a2) = plt.subplots(1, 2, figsize=(11, 4.2))
a1.plot(t, Flid, lw=1, label="force on the lid")
a1.plot(t, load, "k--", lw=1, label="servo target")
a1.set_xlabel("time (s)")
a1.set_ylabel("force (N)")
a1.set_title("servo-controlled lid: four load steps")
a2b = a1.twinx()
a2b.plot(t, 1e3 * (zlid - zlid[0]), color="tab:red", lw=1)
a2b.set_ylabel("lid displacement (mm)", color="tab:red")
a1.legend(loc="center left")
sv = np.array([r[3] for r in rows]) / 1e3
sh = np.array([r[4] for r in rows]) / 1e3
a2.plot(sv, sh, "o-", label="POLYDEM (mean over the bed)")
for phi in (20, 30):
    k0 = 1 - math.sin(math.radians(phi))
    a2.plot([0, sv.max() * 1.1], [0, k0 * sv.max() * 1.1], ":", label=f"Jaky, phi = {phi} deg (K0 = {k0:.2f})")
if PHI is not None:
    k0 = 1 - math.sin(math.radians(PHI))
    a2.plot([0, sv.max() * 1.1], [0, k0 * sv.max() * 1.1], "--", color="k",
            label=f"Jaky, the bed's angle of repose {PHI:g} deg (K0 = {k0:.2f})")
a2.set_xlabel(r"mean vertical stress $\sigma_v$ (kPa)")
a2.set_ylabel(r"mean horizontal stress $\sigma_h$ (kPa)")
a2.set_title("oedometric stress path")
a2.legend()
fig.tight_layout()
fig.savefig(PREFIX + ".png", dpi=110)
