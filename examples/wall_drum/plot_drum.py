#!/usr/bin/env python3
"""Drum run summary: torque on the drum about its axis (f_drum[5]) and kinetic
energies vs time from the log; containment: every vertex of every grain in
every dump inside the drum (radius R, 0 <= y <= W, up to the contact overlap).
Usage: plot_drum.py [log [vtk-prefix [R [W [png]]]]]
defaults: log.drum drum 0.05 0.011 drum_torque.png (the 34-grain example);
in.drum_big: plot_drum.py log.drum_big.np2 drum_big 0.15 0.022 drum_big_torque.png"""
import glob, math, re, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

arg = sys.argv[1:] + [None] * 5
logf = arg[0] or "log.drum"
prefix = arg[1] or "drum"
R = float(arg[2] or 0.05)
W = float(arg[3] or 0.011)
png = arg[4] or "drum_torque.png"

t, ke, er, tq, nc, na = [], [], [], [], [], []
cols = None
for line in open(logf):
    w = line.split()
    if w[:2] == ["Step", "Time"]:
        cols = {name: k for k, name in enumerate(w)}
        continue
    if cols and len(w) == len(cols) and re.match(r"^\d+$", w[0]):
        t.append(float(w[cols["Time"]])); na.append(int(w[cols["Atoms"]]))
        ke.append(float(w[cols["KinEng"]])); er.append(float(w[cols["c_erot"]]))
        tq.append(float(w[cols["f_drum[5]"]])); nc.append(float(w[cols["f_drum[7]"]]))
    elif cols and w[:1] == ["Loop"]:
        cols = None
rev = 60.0 / 45.0
late = [q for q, s in zip(tq, t) if s >= 2 * rev]
print("samples %d, time %.3f s = %.2f revolutions, atoms min %d max %d" % (len(t), t[-1], t[-1] / rev, min(na), max(na)))
if late:
    print("torque on the drum about y after 2 revolutions: mean %.4g N m, min %.4g, max %.4g" % (sum(late) / len(late), min(late), max(late)))
rmax, ylo, yhi, nd = 0.0, 1e9, -1e9, 0
for f in sorted(glob.glob(prefix + ".*.vtk")):
    words = open(f).read().split()
    i = words.index("POINTS")
    n = int(words[i + 1])
    p = [float(x) for x in words[i + 3:i + 3 + 3 * n]]
    for k in range(n):
        x, y, z = p[3 * k:3 * k + 3]
        rmax = max(rmax, math.hypot(x, z)); ylo = min(ylo, y); yhi = max(yhi, y)
    nd += 1
print("%d dumps: largest vertex radius %.5f m (drum %g), vertex y in [%.5f, %.5f] (drum [0, %g])" % (nd, rmax, R, ylo, yhi, W))
fig, ax = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
ax[0].plot([s / rev for s in t], tq)
ax[0].set_ylabel("torque on drum, y (N m)")
ax[1].plot([s / rev for s in t], ke, label="translational KE")
ax[1].plot([s / rev for s in t], er, label="rotational KE")
ax[1].set_ylabel("J")
ax[1].set_xlabel("revolutions (45 rpm)")
ax[1].legend()
fig.tight_layout()
fig.savefig(png, dpi=110)
