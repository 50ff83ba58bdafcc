#!/usr/bin/env python3
"""Time-averaged velocity field, dynamic angle of repose and flow regime of
the drum (in.drum_field's drum_field.dump; seed section 3.4, Fig. 15).

    velocity_field.py [drum_field.dump] [--R 0.15] [--W 0.022] [--h 0.01]
                      [--png drum_field.png] [--summary summary_field.txt]

Method (README):
  grid      square cells of edge h in the x-z plane (the drum's axis is y);
            every snapshot adds each grain's centre velocity (vx, vz) to its
            cell; the field is the mean velocity per cell over all snapshots
            (cells with fewer than 20 samples left out), and n(x, z) the
            mean number of grain centres per cell per snapshot.
  bed       cells with n >= n_bulk / 2, n_bulk the median n of the cells more
            than 3 h inside the drum with n above the overall mean.
  surface   for each column of cells with |x| <= 0.6 R, the top of the bed:
            the highest z where n crosses n_bulk / 2 (linear between cells).
  angle     (a) bed angle from the centre of mass: the angle between the
            downward vertical and the line from the drum's centre to the
            grains' mean position (all samples); for a bed with a flat
            surface it equals the surface's inclination, whatever the fill;
            (b) the least-squares line through the surface points (degrees
            from the horizontal), with its rms residual: meaningful only
            where the surface is flat (rolling, cascading), not for a
            cataracting bed.
  regime    Froude number Fr = omega^2 R / g against Mellmann's (2001) map;
            from the field: the fraction of grain samples in dilute cells
            (0 < n < n_bulk / 2, i.e. in flight above the bed) and the highest
            angular position on the rising wall where the bed is still
            carried by the wall (lifting)."""
import argparse
import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def read_dump(path):
    snaps, cols = [], None
    with open(path) as f:
        while True:
            line = f.readline()
            if not line:
                break
            if line.startswith("ITEM: NUMBER OF ATOMS"):
                n = int(f.readline())
            elif line.startswith("ITEM: ATOMS"):
                cols = line.split()[2:]
                a = np.loadtxt([f.readline() for _ in range(n)], ndmin=2)
                snaps.append(a)
    return cols, snaps


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("dump", nargs="?", default="drum_field.dump")
    ap.add_argument("--R", type=float, default=0.15)
    ap.add_argument("--W", type=float, default=0.022)
    ap.add_argument("--h", type=float, default=0.01)
    ap.add_argument("--rpm", type=float, default=45.0)
    ap.add_argument("--png", default="drum_field.png")
    ap.add_argument("--summary", default="summary_field.txt")
    a = ap.parse_args()
    cols, snaps = read_dump(a.dump)
    ix, iz, ivx, ivz = (cols.index(c) for c in ("x", "z", "vx", "vz"))
    R, h = a.R, a.h
    nb = int(math.ceil(2 * R / h))
    edges = np.linspace(-R, R, nb + 1)
    cnt = np.zeros((nb, nb))
    svx = np.zeros((nb, nb))
    svz = np.zeros((nb, nb))
    for s in snaps:
        i = np.clip(((s[:, ix] + R) / h).astype(int), 0, nb - 1)
        k = np.clip(((s[:, iz] + R) / h).astype(int), 0, nb - 1)
        np.add.at(cnt, (i, k), 1)
        np.add.at(svx, (i, k), s[:, ivx])
        np.add.at(svz, (i, k), s[:, ivz])
    ns = len(snaps)
    n = cnt / ns
    ok = cnt >= 20
    vx = np.where(ok, svx / np.maximum(cnt, 1), np.nan)
    vz = np.where(ok, svz / np.maximum(cnt, 1), np.nan)
    xc = 0.5 * (edges[1:] + edges[:-1])
    X, Z = np.meshgrid(xc, xc, indexing="ij")
    inner = np.hypot(X, Z) < R - 3 * h
    dense = inner & (n > n[n > 0].mean())
    nbulk = np.median(n[dense])
    bed = n >= 0.5 * nbulk

    # free surface in the central columns
    sx, sz = [], []
    for i in range(nb):
        if abs(xc[i]) > 0.6 * R:
            continue
        col = n[i]
        top = [k for k in range(nb - 1) if col[k] >= 0.5 * nbulk and col[k + 1] < 0.5 * nbulk]
        if not top:
            continue
        k = top[-1]
        f = (col[k] - 0.5 * nbulk) / (col[k] - col[k + 1])
        sx.append(xc[i])
        sz.append(xc[k] + f * h)
    sx, sz = np.array(sx), np.array(sz)
    slope, icpt = np.polyfit(sx, sz, 1)
    angle = math.degrees(math.atan(abs(slope)))
    resid = sz - (slope * sx + icpt)

    xs = np.concatenate([s[:, ix] for s in snaps])
    zs_ = np.concatenate([s[:, iz] for s in snaps])
    xcm, zcm = xs.mean(), zs_.mean()
    com_angle = math.degrees(math.atan2(abs(xcm), -zcm))
    omega = a.rpm * 2 * math.pi / 60
    fr = omega ** 2 * R / 9.81
    dilute = (n > 0) & ~bed
    fly = cnt[dilute].sum() / cnt.sum()
    # lifting: highest polar angle (from the bottom, towards the rising side)
    # of bed cells touching the wall ring R - 2h < r < R
    ring = bed & (np.hypot(X, Z) > R - 2 * h)
    rising = -np.sign(omega)        # rotation +y: the wall rises at x < 0
    theta = np.degrees(np.arctan2(rising * X, -Z))    # 0 at the bottom, 90 at the rising side
    lift = theta[ring].max() if ring.any() else float("nan")
    vmax = np.nanmax(np.hypot(vx, vz))
    speed_wall = omega * R

    lines = [
        "snapshots %d, grains per snapshot %d, cell %.3g m, n_bulk %.3g grains per cell" % (ns, len(snaps[0]), h, nbulk),
        "Froude number omega^2 R / g = %.3f (omega %.3f rad/s, R %.3g m): Mellmann (2001) map: "
        "cataracting for 0.1 < Fr < 1 (cascading 1e-3..0.1, centrifuging >= 1)" % (fr, omega, R),
        "bed angle from the centre of mass (%.4f, %.4f) m: %.1f deg" % (xcm, zcm, com_angle),
        "surface line fit (|x| <= 0.6 R, %d columns): %.1f deg, rms residual %.2g m" % (len(sx), angle, resid.std()),
        "surface slope sign: %s" % ("rises towards -x (the rising wall side)" if slope < 0 else "rises towards +x"),
        "grain samples in dilute cells (in flight above the bed): %.1f %%" % (100 * fly),
        "bed carried up the rising wall to %.0f deg from the bottom" % lift,
        "largest mean cell speed %.3f m/s; wall speed omega R = %.3f m/s" % (vmax, speed_wall),
    ]
    text = "\n".join(lines)
    print(text)
    open(a.summary, "w").write(text + "\n")

    fig, ax = plt.subplots(figsize=(7.5, 7), dpi=110)
    sp = np.hypot(vx, vz)
    im = ax.pcolormesh(edges, edges, sp.T, cmap="viridis", shading="flat")
    plt.colorbar(im, ax=ax, label="mean speed |v| (m/s)", shrink=0.8)
    m = ok & (n > 0)
    q = 2
    sel = np.zeros_like(m)
    sel[::q, ::q] = True
    sel &= m
    ax.quiver(X[sel], Z[sel], vx[sel], vz[sel], color="w", scale=25, width=0.003)
    ax.contour(xc, xc, n.T, levels=[0.5 * nbulk], colors="r", linewidths=0.8)
    t = np.linspace(0, 2 * np.pi, 200)
    ax.plot(R * np.cos(t), R * np.sin(t), "k", lw=1)
    xx = np.linspace(-0.6 * R, 0.6 * R, 10)
    ax.plot([0, xcm / math.hypot(xcm, zcm) * R], [0, zcm / math.hypot(xcm, zcm) * R], "m-", lw=1.5,
            label="centre -> centre of mass: %.1f deg from vertical" % com_angle)
    ax.plot([xcm], [zcm], "mo")
    ax.set_aspect("equal")
    ax.set_xlim(-R * 1.05, R * 1.05)
    ax.set_ylim(-R * 1.05, R * 1.05)
    ax.set_xlabel("x (m)")
    ax.set_ylabel("z (m)")
    ax.set_title("time-averaged grain velocity, %d snapshots; Fr = %.2f\n(red: n = n_bulk/2, the bed's edge)"
                 % (ns, fr), fontsize=10)
    ax.legend(loc="upper right", fontsize=8)
    fig.tight_layout()
    fig.savefig(a.png)
    print("wrote", a.png, a.summary)


if __name__ == "__main__":
    main()
