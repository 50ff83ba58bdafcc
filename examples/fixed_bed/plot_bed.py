#!/usr/bin/env python3
"""Figures and summary of the fixed-bed runs.

    plot_bed.py results/beds.txt RUNDIR [--extra more.txt ...] [--picture TAG]

results/beds.txt: one line per bed (run_case.sh); --extra: more such files,
for the summary only (short beds, friction). RUNDIR holds each bed's
TAG.rad (r, eps(r)) and TAG.ax (z, phi(z)) and TAG.vtk. Writes summary.txt
(mean, sample sd per shape and friction against Benyahia & O'Neill 2005),
porosity.png (radial and axial profiles) and, with --picture, bed.png (front
view of the bed TAG beside its radial profile). A bed's eps_b_se (key of its
line, if there) replaces the block standard error computed from TAG.ax.
--summary-only: summary.txt alone."""
import argparse
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "..", "tools"))
from render_vtk import draw_front, read_vtk  # noqa: E402

R = 0.0125


def benyahia_cyl(D_over_dpe):
    """Benyahia & O'Neill (2005), solid cylinders: eps = 0.373 + 1.703 / (D/d_pe + 0.611)^2,
    mean error 1.6 %, 1.7 < D/d_pe < 26.3 (as quoted by the fluids package,
    voidage_Benyahia_Oneil_cylindrical)"""
    return 0.373 + 1.703 / (D_over_dpe + 0.611) ** 2


def read(path):
    rows = []
    for ln in open(path):
        if "=" in ln:
            kv = dict(w.split("=", 1) for w in ln.split() if "=" in w)
            rows.append(kv)
    return rows


def tag_of(kv):
    return kv.get("tag") or "%s_s%s" % (kv["shape"], kv["seed"])


def block_se(rundir, kv, nb=5):
    """standard error of one bed's eps_b from nb consecutive blocks of its bulk zone"""
    path = os.path.join(rundir, tag_of(kv) + ".ax")
    if not os.path.exists(path):
        return float("nan")
    z, phi = np.loadtxt(path, unpack=True)
    e = 1.0 - phi[(z >= float(kv["zlo"])) & (z <= float(kv["zhi"]))]
    bm = np.array([b.mean() for b in np.array_split(e, nb)])
    return bm.std(ddof=1) / math.sqrt(nb)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("results")
    ap.add_argument("rundir")
    ap.add_argument("--picture", default=None)
    ap.add_argument("--extra", nargs="*", default=[])
    ap.add_argument("--summary-only", action="store_true", help="write summary.txt, no figures")
    a = ap.parse_args()
    rows = read(a.results)
    groups = {}
    for kv in rows + [k for f in a.extra for k in read(f)]:
        groups.setdefault((kv["shape"], kv.get("mu", "0.8"), kv.get("n", "")), []).append(kv)
    lines = ["# group: shape mu n_pellets | beds | eps_b mean +- sd (one bed: +- its standard error from 5 blocks) | eps_wall | eps_core | H_top (m) | "
             "D/d_pe | Benyahia-O'Neill eps (+-1.6 %) | eps_b - correlation"]
    for (shape, mu, n), g in sorted(groups.items(), key=lambda t: (t[0][0], -float(t[0][2]), -float(t[0][1]))):
        e = np.array([float(k["eps_b"]) for k in g])
        ew = np.array([float(k["eps_wall"]) for k in g])
        ec = np.array([float(k["eps_core"]) for k in g])
        ht = np.array([float(k["H_top"]) for k in g])
        dd = float(g[0]["D_over_dpe"])
        c = benyahia_cyl(dd)
        sd = e.std(ddof=1) if len(e) > 1 else (float(g[0]["eps_b_se"]) if "eps_b_se" in g[0] else block_se(a.rundir, g[0]))
        lines.append("%s mu=%s n=%s | %d | %.4f +- %.4f | %.4f | %.4f | %.3f | %.3f | %.4f +- %.4f | %+.4f"
                     % (shape, mu, n, len(g), e.mean(), sd, ew.mean(), ec.mean(), ht.mean(), dd, c, 0.016 * c,
                        e.mean() - c))
    open(os.path.join(here, "summary.txt"), "w").write("\n".join(lines) + "\n")
    print("\n".join(lines))
    if a.summary_only:
        return

    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.2), dpi=110)
    colors = {"catalyst_cylinder": "C0", "catalyst_cylinder12": "C1"}
    for kv in rows:
        t = tag_of(kv)
        rad = os.path.join(a.rundir, t + ".rad")
        axf = os.path.join(a.rundir, t + ".ax")
        if not os.path.exists(rad):
            continue
        r, e = np.loadtxt(rad, unpack=True)
        dpe = float(kv["dpe"])
        lab = "%s, mu %s, seed %s" % ("24-gon" if kv["shape"] == "catalyst_cylinder" else "12-gon",
                                     kv.get("mu", "0.8"), kv["seed"])
        col = colors.get(kv["shape"], "C3") if kv.get("mu", "0.8") == "0.8" else "C2"
        ax1.plot((R - r) / dpe, e, lw=1, color=col, label=lab)
        z, phi = np.loadtxt(axf, unpack=True)
        ax2.plot(z, 1 - phi, lw=0.6, color=col, label=lab)
    dd = float(rows[0]["D_over_dpe"])
    c = benyahia_cyl(dd)
    for ax in (ax1, ax2):
        ax.axhspan(c * 0.984, c * 1.016, color="0.8", alpha=0.6, lw=0)
        ax.axhline(c, color="k", ls="--", lw=1, label="Benyahia & O'Neill 2005: %.3f +- 1.6 %%" % c)
    ax1.set_xlabel("distance from the wall / d_pe")
    ax1.set_ylabel("porosity eps(r) (bulk zone)")
    ax1.set_xlim(0, R / float(rows[0]["dpe"]))
    ax1.set_ylim(0.2, 1.0)
    ax1.legend(fontsize=7)
    ax2.set_xlabel("z (m)")
    ax2.set_ylabel("porosity of the section, 1 - phi(z)")
    ax2.set_ylim(0.2, 1.0)
    ax2.set_title("D/d_pe = %.2f" % dd, fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(here, "porosity.png"))

    if a.picture:
        pts, polys, cell = read_vtk(os.path.join(a.rundir, a.picture + ".vtk"))
        zmax = pts[:, 2].max()
        fig = plt.figure(figsize=(8, 9), dpi=110)
        axa = fig.add_axes([0.02, 0.04, 0.22, 0.92])
        n = draw_front(axa, pts, polys, cell, keep=lambda c: c[1] > -0.004)
        axa.plot([-R, -R], [0, zmax], "k-", lw=0.8)
        axa.plot([R, R], [0, zmax], "k-", lw=0.8)
        axa.plot([-R, R], [0, 0], "k-", lw=0.8)
        axa.set_xlim(-R * 1.1, R * 1.1)
        axa.set_ylim(-0.003, zmax + 0.003)
        axa.set_title("%d pellets behind y = -4 mm" % n, fontsize=8)
        axa.axis("off")
        axb = fig.add_axes([0.30, 0.55, 0.24, 0.38])
        lo = zmax - 0.06
        draw_front(axb, pts, polys, cell, keep=lambda c: c[2] > lo - 0.01 and c[1] > -0.004, zrange=(0, zmax))
        axb.set_xlim(-R * 1.05, R * 1.05)
        axb.set_ylim(lo, zmax + 0.002)
        axb.set_title("top 6 cm", fontsize=8)
        axb.axis("off")
        axc = fig.add_axes([0.62, 0.55, 0.36, 0.38])
        kv = [k for k in rows if tag_of(k) == a.picture][0]
        r, e = np.loadtxt(os.path.join(a.rundir, a.picture + ".rad"), unpack=True)
        axc.plot((R - r) / float(kv["dpe"]), e, "C0-", lw=1)
        axc.axhline(float(kv["eps_b"]), color="C0", ls=":", lw=1, label="this bed: eps_b = %.3f" % float(kv["eps_b"]))
        axc.axhline(c, color="k", ls="--", lw=1, label="correlation %.3f" % c)
        axc.set_xlabel("distance from the wall / d_pe", fontsize=8)
        axc.set_ylabel("eps(r)", fontsize=8)
        axc.legend(fontsize=7)
        axc.set_xlim(0, R / float(kv["dpe"]))
        axd = fig.add_axes([0.62, 0.08, 0.36, 0.36])
        z, phi = np.loadtxt(os.path.join(a.rundir, a.picture + ".ax"), unpack=True)
        axd.plot(1 - phi, z, "C0-", lw=0.6)
        axd.axvline(c, color="k", ls="--", lw=1)
        axd.axhspan(float(kv["zlo"]), float(kv["zhi"]), color="0.9", lw=0)
        axd.set_xlabel("1 - phi(z)", fontsize=8)
        axd.set_ylabel("z (m); shaded: bulk zone", fontsize=8)
        fig.savefig(os.path.join(here, "bed.png"))


if __name__ == "__main__":
    main()
