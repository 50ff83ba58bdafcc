#!/usr/bin/env python3
"""The 3-D ball mill's power draw (in.bond: bond_rev_<friction>.txt, one row
per revolution) against Bond's ball-mill power correlation in its metric form
(Rowland and Kjos, "Rod and ball mills", in Mineral Processing Plant
Design, SME 1978; as given in Wills' Mineral Processing Technology):
    P / M_balls [kW/t] = 4.879 D^0.3 (3.2 - 3 J) f_c (1 - 0.1 / 2^(9 - 10 f_c))
D the mill's inside diameter [m], J the fraction of its volume the ball
charge fills (bulk), f_c the fraction of the critical speed (the term for
balls larger than a 3.3 m mill needs is zero here). Bond's figure is per
tonne of balls with the ore in their voids, so the run with ore (in.bond
-var ore 1, tag ore_0.5) is held against the same figure. Prints a table
and writes bond.png (the charge seen along the axis at the end of each run,
and the power per revolution).
    /usr/bin/python3 bond.py [run tag ...]     (default 0.5 1.0 ore_0.5: the
                                                ball-drum friction, ore_ with ore)"""
import glob
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

D, W, N, RB, RHO, RPM = 0.1, 0.05, 324, 0.004, 7800.0, 100.0
v_ball = 4.0 / 3.0 * math.pi * RB ** 3
J = N * v_ball / (0.6 * math.pi * (D / 2) ** 2 * W)
fc = RPM / (42.3 / math.sqrt(D))
M = N * v_ball * RHO
kw_t = 4.879 * D ** 0.3 * (3.2 - 3 * J) * fc * (1 - 0.1 / 2 ** (9 - 10 * fc))
P_bond = kw_t * M    # kW/t x kg = W
runs = sys.argv[1:] if len(sys.argv) > 1 else ["0.5", "1.0", "ore_0.5"]
print(f"J = {J:.3f}, f_c = {fc:.3f}, ball mass {M:.3f} kg; Bond: {kw_t:.2f} kW/t = {P_bond:.2f} W")
print("| run | revolution | torque on the drum [N m] | M g x_cm [N m] | power [W] | / Bond |")
print("|---|---|---|---|---|---|")
fig, ax = plt.subplots(1, 2, figsize=(11, 3.8), dpi=110, gridspec_kw={"width_ratios": [1.3, 1]})


def label(tag):
    if tag.startswith("ore_"):
        return f"balls and ore, ball-drum friction {tag[4:]}"
    return f"balls, ball-drum friction {tag}"



for c, muw in enumerate(runs):
    try:
        rows = [[float(x) for x in l.split()] for l in open(f"bond_rev_{muw}.txt")
                if l.strip() and l[0] != "#"]
    except FileNotFoundError:
        continue
    power = [r[3] for r in rows]
    for k, r in enumerate(rows):
        print(f"| {muw} | {k + 1} | {r[1]:.4f} | {r[2]:.4f} | {r[3]:.3f} | {r[3] / P_bond:.2f} |")
    mean = sum(power[1:]) / len(power[1:])
    print(f"run {muw}, revolutions 2-{len(rows)}: mean power {mean:.3f} W = "
          f"{mean / P_bond:.2f} of Bond's")
    ax[1].plot(range(1, len(power) + 1), power, "o-", color=f"C{c}", label=label(muw))
    snap = sorted(glob.glob(f"bond_{muw}.*.txt"), key=lambda f: int(f.split(".")[-2]))
    if snap:
        pts = np.loadtxt(snap[-1], skiprows=9)
        ball = pts[:, 4] > 0.0035    # the balls' radius 4 mm, the ore's corners 3 mm
        ax[0].scatter(pts[ball, 1] * 1e3 + 110 * c, pts[ball, 3] * 1e3, s=9, color=f"C{c}")
        ax[0].scatter(pts[~ball, 1] * 1e3 + 110 * c, pts[~ball, 3] * 1e3, s=4, color="0.35")
        t = np.linspace(0, 2 * np.pi, 200)
        ax[0].plot(110 * c + 50 * np.cos(t), 50 * np.sin(t), "k-", lw=0.8)
        ax[0].text(110 * c, -62, label(muw).replace(", ", ",\n"), ha="center", va="top",
                   fontsize=7)
ax[0].set_aspect("equal")
ax[0].set_ylim(-80, 55)
ax[0].set_xticks([])
ax[0].set_xlabel("each drum 10 cm across, turning clockwise in this view")
ax[0].set_ylabel("z (mm)")
ax[0].set_title("the charge at the end (seen along the axis; ore grey)", fontsize=9)
ax[1].axhline(P_bond, color="C3", ls="--", label=f"Bond's correlation: {P_bond:.2f} W")
ax[1].set_xlabel("revolution")
ax[1].set_ylabel("power draw (W)")
ax[1].set_ylim(0, 1.15 * P_bond)
ax[1].set_title(f"3-D ball mill D = 10 cm, J = {J:.2f}, {fc:.0%} of critical speed", fontsize=9)
ax[1].legend(fontsize=8)
fig.tight_layout()
fig.savefig("bond.png")
print("wrote bond.png")
