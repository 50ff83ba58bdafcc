#!/usr/bin/env python3
"""Figures of a settled silo fill (after analyze_silo.py).

    plot_silo.py final.vtk ANALYSIS_DIR [--tag TAG]

Writes silo.png (front view of the grains in the slice |y| < 0.15 m beside
the packing-fraction map phi(r, z)) and pressure.png (wall pressure against
depth with the Janssen fit; the ratios tau_w/p_w and K = p_w/sigma_v) into
this folder; with --tag, silo_TAG.png and pressure_TAG.png."""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, here)
sys.path.insert(0, os.path.join(here, "..", "..", "tools"))
import make_silo as ms  # noqa: E402
from analyze_silo import janssen  # noqa: E402
from render_vtk import draw_front, read_vtk  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("vtk")
    ap.add_argument("adir")
    ap.add_argument("--tag", default="")
    a = ap.parse_args()
    res = {k: float(v) for k, v in (w.split("=") for w in open(os.path.join(a.adir, "summary.txt")).read().split())}
    Hs = res["H_s"]
    zw = np.linspace(0, Hs + 0.6, 600)
    rw = np.array([ms.radius(z) for z in zw])

    pts, polys, cell = read_vtk(a.vtk)
    suffix = "_" + a.tag if a.tag else ""
    fig = plt.figure(figsize=(12, max(6.4, 1.05 * (Hs + 0.6) + 0.6)), dpi=110)
    ax = fig.add_axes([0.02, 0.06, 0.46, 0.88])
    n = draw_front(ax, pts, polys, cell, keep=lambda c: abs(c[1]) < 0.15, zrange=(0, Hs))
    ax.plot(rw, zw, "k-", lw=0.8)
    ax.plot(-rw, zw, "k-", lw=0.8)
    ax.plot([-ms.R0, ms.R0], [0, 0], "k-", lw=1.5)
    ax.set_xlim(-1.2, 1.2)
    ax.set_ylim(-0.05, Hs + 0.6)
    ax.set_title("%d of %d grains: the slice |y| < 0.15 m, seen from -y" % (n, int(res["n"])), fontsize=9)
    ax.axis("off")

    d = np.load(os.path.join(a.adir, "phi_rz.npz"))
    phi, dr = d["phi"], float(d["dr"])
    ax2 = fig.add_axes([0.52, 0.08, 0.40, 0.84])
    re = np.arange(phi.shape[0] + 1) * dr
    ze = np.arange(phi.shape[1] + 1) * dr
    m = ax2.pcolormesh(re, ze, phi.T, cmap="magma", vmin=0.0, vmax=0.75, shading="flat")
    ax2.plot(rw, zw, "w-", lw=0.8)
    ax2.axhline(Hs, color="c", ls="--", lw=0.8)
    ax2.text(0.05, Hs + 0.05, "H_s = %.2f m" % Hs, color="c", fontsize=8)
    ax2.set_xlim(0, ms.R + ms.DEPTH + 0.02)
    ax2.set_ylim(0, Hs + 0.6)
    ax2.set_aspect("equal")
    ax2.set_xlabel("r (m)")
    ax2.set_ylabel("z (m)")
    ax2.set_title("solid fraction phi(r, z), 5 cm cells (azimuthal mean); phi_b = %.3f" % res["phi_b"], fontsize=9)
    fig.colorbar(m, ax=ax2, fraction=0.05)
    fig.savefig(os.path.join(here, "silo%s.png" % suffix))

    rows = np.loadtxt(os.path.join(a.adir, "pressure.txt"))
    cyl = rows[:, 0] > ms.HCONE
    fig, (b1, b2) = plt.subplots(1, 2, figsize=(11, 4.4), dpi=110)
    hh = np.linspace(0, rows[cyl, 1].max() * 1.05, 200)
    b1.plot(rows[cyl, 1], rows[cyl, 2] / 1e3, "o", ms=4, label="cylinder, one pitch per band")
    b1.plot(rows[~cyl, 1], rows[~cyl, 2] / 1e3, "s", ms=3, mfc="none", label="hopper cone, 0.1 m bands")
    b1.plot(hh, janssen(hh, res["K"], res["lam"], res["rho_b"]) / 1e3, "k-",
            label="Janssen, mu_w = tau/p = %.2f: K = %.2f +- %.2f, lambda = %.2f m" % (res["mu_w_fit"], res["K"], res["K_sd"], res["lam"]))
    b1.plot(hh, res["K"] * res["rho_b"] * 9.81 * hh / 1e3, "k:", lw=0.8, label="K rho_b g h (no wall friction)")
    b1.axvline(Hs - ms.HCONE, color="0.6", ls="--", lw=0.8)
    b1.text(Hs - ms.HCONE, 0.2, " cone/cylinder", fontsize=7, color="0.4")
    b1.set_xlabel("depth below the free surface h = H_s - z (m)")
    b1.set_ylabel("normal wall pressure p_w (kPa)")
    b1.legend(fontsize=7)
    b2.plot(rows[cyl, 1], rows[cyl, 3] / np.maximum(rows[cyl, 2], 1e-9), "o", ms=4, label="tau_w / p_w (mobilised wall friction)")
    b2.axhline(res["mu_w_fit"], color="C0", ls="-", lw=0.8, label="its mean %.2f (used in the fit)" % res["mu_w_fit"])
    b2.axhline(0.8, color="k", ls=":", lw=0.8, label="wall friction coefficient 0.8")
    if rows.shape[1] > 5:
        b2.plot(rows[cyl, 1], rows[cyl, 5], "s", ms=4, color="C3", label="K = p_w / sigma_v (force balance)")
        b2.axhline(res["K"], color="C3", ls="--", lw=0.8, label="K of the Janssen fit %.2f" % res["K"])
    b2.set_ylim(0, 1.5)
    b2.set_xlabel("depth h (m)")
    b2.set_ylabel("ratio, cylinder bands")
    b2.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(here, "pressure%s.png" % suffix))


if __name__ == "__main__":
    main()
