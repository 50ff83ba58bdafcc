#!/usr/bin/env python3
"""Drum run summary: torque on the drum about its axis (f_drum[5]) and kinetic
energies vs time from log.drum; containment: every vertex of every grain in
every dump (drum.*.vtk) inside the drum (radius 0.05 m, 0 <= y <= 0.011 m, up
to the contact overlap). Writes drum_torque.png."""
import glob, math, re
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

t, ke, er, tq, nc, na = [], [], [], [], [], []
inthermo = False
for line in open("log.drum"):
    w = line.split()
    if w[:2] == ["Step", "Time"]:
        inthermo = True
        continue
    if inthermo and len(w) == 7 and re.match(r"^\d+$", w[0]):
        t.append(float(w[1])); na.append(int(w[2])); ke.append(float(w[3]))
        er.append(float(w[4])); tq.append(float(w[5])); nc.append(float(w[6]))
    elif inthermo and w[:1] == ["Loop"]:
        inthermo = False
rev = 60.0 / 45.0
late = [q for q, s in zip(tq, t) if s >= 2 * rev]
print("samples %d, time %.3f s = %.2f revolutions, atoms min %d max %d" % (len(t), t[-1], t[-1] / rev, min(na), max(na)))
if late:
    print("torque on the drum about y after 2 revolutions: mean %.4g N m, min %.4g, max %.4g" % (sum(late) / len(late), min(late), max(late)))
rmax, ylo, yhi, nd = 0.0, 1e9, -1e9, 0
for f in sorted(glob.glob("drum.*.vtk")):
    words = open(f).read().split()
    i = words.index("POINTS")
    n = int(words[i + 1])
    p = [float(x) for x in words[i + 3:i + 3 + 3 * n]]
    for k in range(n):
        x, y, z = p[3 * k:3 * k + 3]
        rmax = max(rmax, math.hypot(x, z)); ylo = min(ylo, y); yhi = max(yhi, y)
    nd += 1
print("%d dumps: largest vertex radius %.5f m (drum 0.05), vertex y in [%.5f, %.5f] (drum [0, 0.011])" % (nd, rmax, ylo, yhi))
fig, ax = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
ax[0].plot([s / rev for s in t], tq)
ax[0].set_ylabel("torque on drum, y (N m)")
ax[1].plot([s / rev for s in t], ke, label="translational KE")
ax[1].plot([s / rev for s in t], er, label="rotational KE")
ax[1].set_ylabel("J")
ax[1].set_xlabel("revolutions (45 rpm)")
ax[1].legend()
fig.tight_layout()
fig.savefig("drum_torque.png", dpi=110)
