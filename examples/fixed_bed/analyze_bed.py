#!/usr/bin/env python3
"""Bulk and radial porosity of a settled fixed bed (dump polyhedron/vtk).

    analyze_bed.py final.vtk --vp VP [--R 0.0125] [--nseg 120] [--profile rad.txt] [--axial ax.txt]

Definitions (README):
  phi(z)   solid area fraction of the horizontal section at height z (exact
           sections of the convex pellets, over the 120-gon of the tube's mesh),
           every 0.25 mm (examples/dodeca_packing/analyze.py).
  H_top    highest vertex above the floor (z = 0).
  zone     the bulk zone: 2 d_c <= z <= H_top - 2 d_c (d_c = 7.78 mm, the
           pellet's circumscribed diameter): away from the floor's ordered
           layers and the loose top.
  eps_b    bulk porosity: 1 - mean phi(z) over the zone (the tube's whole
           cross-section, wall region included, as the correlations).
  eps(r)   radial porosity: the zone sampled on a grid (h = 0.1 mm across,
           0.25 mm along z); a point is solid if it lies in a pellet's convex
           hull; counted in rings of width dr = 0.125 mm.
  eps_wall mean porosity of the ring within d_pe / 2 of the wall (d_pe: the
           diameter of the sphere of the pellet's volume); eps_core: inside it.
Prints one line of key=value pairs."""
import argparse
import math
import sys

import numpy as np

sys.path.insert(0, __file__.rsplit("/", 1)[0] + "/../dodeca_packing")
from analyze import add_container_args, analyze  # noqa: E402
sys.path.insert(0, __file__.rsplit("/", 1)[0] + "/../../tools")
from packing_grid import hulls, occupancy  # noqa: E402

DC = 0.0055 * math.sqrt(2.0)


def radial(H, R, zlo, zhi, h=1.0e-4, hz=2.5e-4, dr=1.25e-4):
    """porosity in rings of width dr over zlo <= z <= zhi, by grid sampling"""
    xs = np.arange(-R, R + h, h)
    zs = np.arange(zlo, zhi, hz) + 0.5 * hz
    X, Y = np.meshgrid(xs, xs, indexing="ij")
    nring = int(R / dr) + 1
    ring = np.minimum((np.hypot(X, Y) / dr).astype(int), nring)
    inside = np.hypot(X, Y) < R
    solid = occupancy(H, xs, xs, zs)
    cnt = np.bincount(ring[inside], minlength=nring + 1)[:nring] * len(zs)
    sol = np.bincount(ring[inside], weights=solid[inside].sum(axis=-1), minlength=nring + 1)[:nring]
    r = (np.arange(nring) + 0.5) * dr
    ok = cnt > 0
    return r[ok], 1.0 - sol[ok] / cnt[ok], solid[inside].mean()


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("vtk")
    ap.add_argument("--vp", type=float, required=True, help="pellet volume (m^3) of the template")
    add_container_args(ap, 0.0125)
    ap.add_argument("--profile", default=None, help="write r, eps(r)")
    ap.add_argument("--axial", default=None, help="write z, phi(z)")
    a = ap.parse_args()
    res, zs, phi = analyze(a.vtk, 2 * DC, a.R, a.nseg)   # its bulk zone is not used here
    zlo, zhi = 2 * DC, res["H_top"] - 2 * DC
    zone = (zs >= zlo) & (zs <= zhi)
    eps_b = 1.0 - phi[zone].mean()
    r, eps_r, phi_grid = radial(hulls(a.vtk), a.R * math.cos(math.pi / a.nseg), zlo, zhi)
    dpe = (6.0 * a.vp / math.pi) ** (1.0 / 3.0)
    wall = r > a.R - 0.5 * dpe

    def ringmean(sel):                  # area-weighted (ring area ~ r dr)
        return float(np.sum(eps_r[sel] * r[sel]) / np.sum(r[sel]))
    out = dict(n=res["n"], H_top=res["H_top"], zlo=zlo, zhi=zhi, eps_b=eps_b,
               eps_b_grid=1.0 - phi_grid, eps_wall=ringmean(wall),
               eps_core=ringmean(~wall),
               dpe=dpe, D_over_dpe=2 * a.R / dpe, V=res["V"], V_expected=res["n"] * a.vp,
               zmin=res["zmin"], rmax=res["rmax"])
    print(" ".join("%s=%.6g" % kv for kv in out.items()))
    if a.profile:
        np.savetxt(a.profile, np.column_stack([r, eps_r]), fmt="%.6g", header="r(m) eps(r)")
    if a.axial:
        np.savetxt(a.axial, np.column_stack([zs, phi]), fmt="%.6g", header="z(m) phi(z)")


if __name__ == "__main__":
    main()
