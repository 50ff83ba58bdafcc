#!/usr/bin/env python3
"""Rolling spheres example: the stop distance of each sphere from the log
against the closed form d = 7 v0^2 / (10 mu_r g); writes rolling.png.
    /usr/bin/python3 plot_rolling.py [log.rolling]"""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../tools"))
from compare_log import thermo_tables  # noqa: E402

MU_R = [0.05, 0.1, 0.2, 0.3, 0.5]
V0, G = 0.1, 9.81

data = np.array(thermo_tables(sys.argv[1] if len(sys.argv) > 1 else "log.rolling")[-1][1])
t = data[:, 1]
fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.2))
measured = []
print("| mu_r | stop distance (mm) | closed form (mm) | difference | stop time (s) | closed form (s) |")
print("|---|---|---|---|---|---|")
for k, mu in enumerate(MU_R):
    x = data[:, 2 + k] - data[0, 2 + k]
    v = data[:, 7 + k]
    i = int(np.argmax(v <= 0.0))    # first sample at rest
    # the stop between samples i-1 and i, at constant deceleration
    dec = (v[i - 1] - v[i]) / (t[i] - t[i - 1])
    d = x[i - 1] + v[i - 1] ** 2 / (2 * dec)
    ts = t[i - 1] + v[i - 1] / dec
    dc, tc = 7 * V0**2 / (10 * mu * G), 7 * V0 / (5 * mu * G)
    measured.append(d)
    print(f"| {mu:.2f} | {1e3 * d:.4f} | {1e3 * dc:.4f} | {100 * (d / dc - 1):+.3f} % | {ts:.4f} | {tc:.4f} |")
    line, = ax1.plot(t, 1e3 * x, lw=2, label=f"$\\mu_r$ = {mu}")
    tt = np.linspace(0, tc, 100)
    ax1.plot(tt, 1e3 * (V0 * tt - 0.5 * (5 / 7) * mu * G * tt**2), "k--", lw=0.8)
ax1.set_xlabel("time (s)")
ax1.set_ylabel("distance rolled (mm)")
ax1.set_title("spheres rolling on a mesh floor (dashed: closed form)")
ax1.legend()
mus = np.linspace(0.04, 0.55, 200)
ax2.plot(mus, 1e3 * 7 * V0**2 / (10 * mus * G), "k-", label=r"$7v_0^2/(10\mu_r g)$")
ax2.plot(MU_R, 1e3 * np.array(measured), "o", ms=8, label="POLYDEM (fix wall/mesh)")
ax2.set_xlabel(r"rolling friction $\mu_r$")
ax2.set_ylabel("stop distance (mm)")
ax2.set_title(r"stop distance, $v_0$ = 0.1 m/s")
ax2.legend()
fig.tight_layout()
fig.savefig("rolling.png", dpi=110)
