#!/usr/bin/env python3
"""Post-impact omega_y and V_z of the cylinder (log.impact RESULT lines) against
seed Eqs. 27-28 with the mass and I_yy of the faceted 20-gon prism. Prints the
deviations, writes impact.png."""
import math
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

from eq2728 import V, analytic, results

rows = [(t, w, v) for t, (w, v) in sorted(results("log.impact").items())]
wscale = max(abs(analytic(math.radians(t))[0]) for t, _, _ in rows)
print("theta  omega_y   Eq.27     dev      V_z       Eq.28     dev/V")
worst_w = worst_v = 0.0
for t, wy, vz in rows:
    wa, va = analytic(math.radians(t))
    dw, dv = (wy - wa) / abs(wa), (vz - va) / V
    worst_v = max(worst_v, abs(dv))
    if abs(wa) > 0.2 * wscale: worst_w = max(worst_w, abs(dw))
    print("%5.0f %9.4f %9.4f %+7.2f%% %9.5f %9.5f %+7.2f%%" % (t, wy, wa, 100 * dw, vz, va, 100 * dv))
print("max |d omega_y| / |Eq.27| where |Eq.27| > 20%% of its maximum: %.2f%%" % (100 * worst_w))
print("max |d V_z| / V: %.2f%%" % (100 * worst_v))
th = [10 + 0.5 * k for k in range(141)]
fig, ax = plt.subplots(2, 1, figsize=(6.5, 7), sharex=True)
ax[0].plot(th, [analytic(math.radians(t))[0] for t in th], "k-", label="Eq. 27")
ax[0].plot([r[0] for r in rows], [r[1] for r in rows], "o", label="fix wall/mesh")
ax[1].plot(th, [analytic(math.radians(t))[1] for t in th], "k-", label="Eq. 28")
ax[1].plot([r[0] for r in rows], [r[2] for r in rows], "o", label="fix wall/mesh")
ax[0].set_ylabel("omega_y after impact (rad/s)")
ax[1].set_ylabel("V_z after impact (m/s)")
ax[1].set_xlabel("theta (degrees)")
ax[0].legend()
ax[1].legend()
ax[0].set_title("42-vertex cylinder on a wall, V = 0.1 m/s, e = 0.85")
fig.tight_layout()
fig.savefig("impact.png", dpi=110)
