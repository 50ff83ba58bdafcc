#!/usr/bin/env python3
"""Packing map, containment and wall pressure (Janssen fit) of a settled silo fill.

    analyze_silo.py final.vtk final.p_wall.txt silo.stl --vg VG --out DIR [--rho 1500]

Definitions (README):
  phi(r, z)  solid fraction on a grid (h = 1.5 cm; a point is solid if it lies
             in a grain's convex hull), in rings of 5 cm x 5 cm, counting only
             points inside the silo (r < radius(z) of make_silo.py).
  phi(z)     the same over the whole section at height z.
  H_s        free surface: the highest z where phi(z) >= phi_b / 2.
  phi_b      bulk solid fraction: mean phi(z) over 0.25 m <= z <= H_s - 0.3 m
             (cone and cylinder; away from the lid and the loose top).
  p_w(z)     normal wall pressure, area-weighted mean of the per-triangle
             pressures (fix wall/mesh pertriangle, time-averaged) over bands of
             one corrugation pitch (0.25 m, crest to crest) of the cylinder;
             tau_w(z) the mean upward force per area the grains put on it.
  Janssen    p_w(h) = K rho_b g lam (1 - exp(-h / lam)), h = H_s - z the depth,
             rho_b = phi_b rho, lam = D / (4 mu_w K), D = 2 x 1.075 m (the
             corrugation's mean radius), on the cylinder's bands with their
             centre below H_s - 0.25 m: K fitted with mu_w = the mobilised
             ratio tau_w / p_w measured on the same bands (K, lam); also K and
             lam both free (K_free, lam_free: degenerate when the fill is
             shorter than lam) and the hydrostatic K (p_w = K rho_b g h).
  sigma_v(z) the section's mean vertical stress from the force balance of the
             grains above z: their weight (grid) less the vertical force the
             wall above z takes, over the section's area; K_direct = p_w /
             sigma_v per band, and its ratio of sums over the fit bands deeper
             than 0.5 m (Janssen's K measured without a fit).
Writes DIR/summary.txt (key=value), DIR/phi_rz.npz, DIR/pressure.txt."""
import argparse
import os
import sys

import numpy as np
from scipy.optimize import curve_fit

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, here)
sys.path.insert(0, os.path.join(here, "..", "..", "tools"))
import make_silo as ms  # noqa: E402
from packing_grid import hulls, occupancy  # noqa: E402
from render_vtk import read_stl  # noqa: E402


def last_block(path, nrows):
    """the last time block of a fix ave/time mode vector file: (nrows, ncols)"""
    with open(path) as f:
        lines = [ln for ln in f if not ln.startswith("#")]
    rows = lines[-nrows:]
    return np.array([[float(x) for x in ln.split()[1:]] for ln in rows])


def janssen(h, K, lam, rho_b):
    return K * rho_b * 9.81 * lam * (1.0 - np.exp(-h / lam))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("vtk")
    ap.add_argument("pwall")
    ap.add_argument("stl")
    ap.add_argument("--out", required=True)
    ap.add_argument("--rho", type=float, default=1500.0)
    ap.add_argument("--vg", type=float, required=True, help="grain volume (m^3)")
    ap.add_argument("--h", type=float, default=0.015)
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    res = {}

    H = hulls(a.vtk)
    allp = np.vstack([P for P, _ in H])
    res["n"] = len(H)
    res["zmin_vertex"] = allp[:, 2].min()
    # radial distance of each vertex beyond the wall (> 0: into it), then per grain
    wall_r = np.array([ms.radius(z) for z in np.clip(allp[:, 2], 0.0, ms.HTOT)])
    beyond = np.hypot(allp[:, 0], allp[:, 1]) - wall_r
    res["max_vertex_outside_wall"] = float(beyond.max())
    ends = np.cumsum([len(P) for P, _ in H])[:-1]
    res["grains_2cm_outside"] = int(sum(bool(b.max() > 0.02 or z.min() < -0.02)
                                        for b, z in zip(np.split(beyond, ends), np.split(allp[:, 2], ends))))

    h = a.h
    ztop = allp[:, 2].max() + h
    xs = np.arange(-ms.R - ms.DEPTH, ms.R + ms.DEPTH + h, h)
    zs = np.arange(0.0, ztop, h) + 0.5 * h
    solid = occupancy(H, xs, xs, zs)
    X, Y = np.meshgrid(xs, xs, indexing="ij")
    r2 = np.hypot(X, Y)
    rad = np.array([ms.radius(z) for z in zs])
    inside = r2[:, :, None] < rad[None, None, :]
    phi_z = (solid & inside).sum(axis=(0, 1)) / inside.sum(axis=(0, 1))
    low = zs >= 0.25
    # free surface from a first bulk estimate, then the zone
    phib0 = np.mean(phi_z[low & (phi_z > 0.2)])
    Hs = zs[np.nonzero(phi_z >= 0.5 * phib0)[0][-1]] + 0.5 * h
    zone = low & (zs <= Hs - 0.3)
    phib = float(np.mean(phi_z[zone])) if zone.any() else float(phib0)
    Hs = zs[np.nonzero(phi_z >= 0.5 * phib)[0][-1]] + 0.5 * h
    res.update(H_s=Hs, phi_b=phib, hc=ms.HCONE, volume=float(solid.sum() * h ** 3))
    # phi(r, z) map in 5 cm cells
    dr = 0.05
    rb = (r2 / dr).astype(int)
    nr, nz = int((ms.R + ms.DEPTH) / dr) + 1, int(ztop / dr) + 1
    kz = (zs / dr).astype(int)
    cnt = np.zeros((nr, nz))
    sol = np.zeros((nr, nz))
    for k in range(len(zs)):
        m = inside[:, :, k]
        cnt[:, kz[k]] += np.bincount(rb[m], minlength=nr)[:nr]
        sol[:, kz[k]] += np.bincount(rb[m], weights=solid[:, :, k][m], minlength=nr)[:nr]
    with np.errstate(invalid="ignore"):
        phi_rz = np.where(cnt > 0, sol / np.maximum(cnt, 1), np.nan)
    np.savez_compressed(os.path.join(a.out, "phi_rz.npz"), phi=phi_rz, dr=dr, dz=dr, zs=zs, phi_z=phi_z)

    # wall pressure
    tri = read_stl(a.stl)
    cen = tri.mean(axis=1)
    area = 0.5 * np.linalg.norm(np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0]), axis=1)
    F = last_block(a.pwall, len(tri))
    p, fz = F[:, 3], F[:, 2]
    res["wall_Fz_total"] = float(fz.sum())
    res["weight"] = len(H) * a.vg * a.rho * 9.81
    res["wall_share_of_weight"] = -res["wall_Fz_total"] / res["weight"]     # the rest is on the lid
    cz = cen[:, 2]
    incyl = cz > ms.HCONE
    k0 = ((cz - ms.HCONE) / ms.PITCH).astype(int)
    nb = int((Hs - ms.HCONE) / ms.PITCH) + 1

    def band(m, zc):                    # area-weighted p_w and tau_w of the triangles m
        A = area[m].sum()
        return (zc, Hs - zc, (p[m] * area[m]).sum() / A, -fz[m].sum() / A)

    rows = [band(incyl & (k0 == k), ms.HCONE + (k + 0.5) * ms.PITCH) for k in range(nb)]
    kc = (cz / 0.1).astype(int)
    rows += [band(~incyl & (kc == k), k * 0.1 + 0.05) for k in range(int(ms.HCONE / 0.1) + 1)
             if np.any(~incyl & (kc == k))]
    rows = np.array(sorted(rows))
    # mean vertical stress of the section from the force balance of the grains above z:
    # their weight (from the grid) less what the wall above z carries
    w_layer = a.rho * 9.81 * (solid & inside).sum(axis=(0, 1)) * h ** 3
    sec = inside.sum(axis=(0, 1)) * h ** 2

    def sigma_v(z):
        k = min(int(z / h), len(zs) - 1)
        return (w_layer[zs > z].sum() + fz[cz > z].sum()) / sec[k]
    sv = np.array([sigma_v(z) for z in rows[:, 0]])
    with np.errstate(divide="ignore", invalid="ignore"):
        rows = np.column_stack([rows, sv, np.where(sv > 0, rows[:, 2] / sv, np.nan)])
    np.savetxt(os.path.join(a.out, "pressure.txt"), rows, fmt="%.6g",
               header="z(m) depth(m) p_w(Pa) tau_w(Pa) sigma_v(Pa) K_direct=p_w/sigma_v"
               "  (cylinder: one pitch per band; cone: 0.1 m bands)")
    fit = (rows[:, 0] > ms.HCONE) & (rows[:, 1] > 0.25)
    rho_b = phib * a.rho
    D = 2.0 * (ms.R + 0.5 * ms.DEPTH)
    res.update(rho_b=rho_b, D=D, fit_bands=int(fit.sum()))
    if fit.sum() >= 3:                  # the fill reaches into the cylinder
        (K, lam), cov = curve_fit(lambda hh, K, lam: janssen(hh, K, lam, rho_b), rows[fit, 1], rows[fit, 2],
                                  p0=(0.4, 1.5), bounds=([0.01, 0.05], [5.0, 50.0]))
        sK, sl = np.sqrt(np.diag(cov))
        pred = janssen(rows[fit, 1], K, lam, rho_b)
        mu_m = float(np.sum(rows[fit, 3]) / np.sum(rows[fit, 2]))
        res.update(K_free=K, K_free_sd=sK, lam_free=lam, lam_free_sd=sl, mu_w_free=D / (4 * K * lam),
                   mu_w_mobilised=mu_m, rms_free=float(np.sqrt(np.mean((pred / rows[fit, 2] - 1) ** 2))))
        # Janssen with the wall friction the grains mobilise (tau_w / p_w measured): K alone
        f1 = lambda hh, K: janssen(hh, K, D / (4 * mu_m * K), rho_b)  # noqa: E731
        (K1,), c1 = curve_fit(f1, rows[fit, 1], rows[fit, 2], p0=(0.5,), bounds=([0.01], [5.0]))
        res.update(K=K1, K_sd=float(np.sqrt(c1[0, 0])), lam=D / (4 * mu_m * K1), mu_w_fit=mu_m,
                   fit_rms_rel=float(np.sqrt(np.mean((f1(rows[fit, 1], K1) / rows[fit, 2] - 1) ** 2))),
                   K_hydrostatic=float(np.sum(rows[fit, 2] * rows[fit, 1]) / np.sum(rho_b * 9.81 * rows[fit, 1] ** 2)))
        # Janssen's K measured without a fit: p_w over the force-balance sigma_v, bands deeper than 0.5 m
        deep = fit & (rows[:, 1] > 0.5)
        if deep.any():
            res.update(K_direct=float(np.sum(rows[deep, 2]) / np.sum(rows[deep, 4])),
                       K_direct_min=float(np.min(rows[deep, 5])), K_direct_max=float(np.max(rows[deep, 5])))
    with open(os.path.join(a.out, "summary.txt"), "w") as f:
        f.write(" ".join("%s=%.6g" % kv for kv in res.items()) + "\n")
    print(" ".join("%s=%.6g" % kv for kv in res.items()))


if __name__ == "__main__":
    main()
