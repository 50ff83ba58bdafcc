#!/usr/bin/env python3
"""Fill height and packing fraction of a settled packing (dump polyhedron/vtk).

    analyze.py final.vtk [--d 0.03] [--R 0.05] [--nseg 120] [--profile prof.txt]

Definitions (README):
  H_top   highest vertex above the floor (z = 0).
  phi(z)  solid area fraction of the horizontal section at height z: the exact
          cross-sections of the convex particles (their edges cut by the plane)
          over the container's section (the 120-gon of the mesh), sampled every
          dz = 0.25 mm.
  phi_b   bulk packing fraction: mean of phi(z) over d/2 <= z <= H_top - 1.5 d
          (away from the floor's ordered first layer and the loose top).
  H_half  highest z where phi(z) >= phi_b / 2.
  phi_H   N V_p / (A H_half): the packing fraction an observer of the fill line
          H_half would report.
Prints one line of key=value pairs."""
import argparse
import math
import sys

import numpy as np

sys.path.insert(0, __file__.rsplit("/", 1)[0] + "/../../tools")
from render_vtk import read_vtk  # noqa: E402


def particles(path):
    """per particle (id): vertex array and edge list (index pairs)"""
    pts, polys, cell = read_vtk(path)
    ids = cell["id"]
    out = {}
    for f, pid in zip(polys, ids):
        v, e = out.setdefault(int(pid), (set(), set()))
        v.update(f)
        for a, b in zip(f, f[1:] + f[:1]):
            e.add((min(a, b), max(a, b)))
    res = []
    for pid in sorted(out):
        v, e = out[pid]
        vi = sorted(v)
        loc = {g: k for k, g in enumerate(vi)}
        res.append((pts[vi], np.array([(loc[a], loc[b]) for a, b in e])))
    return res


def section_area(P, E, z):
    """area of the section of the convex hull of P (edges E) by the plane z"""
    za, zb = P[E[:, 0], 2], P[E[:, 1], 2]
    cut = (za - z) * (zb - z) < 0
    if cut.sum() < 3:
        return 0.0
    a, b = P[E[cut, 0]], P[E[cut, 1]]
    t = (z - a[:, 2]) / (b[:, 2] - a[:, 2])
    q = a[:, :2] + t[:, None] * (b[:, :2] - a[:, :2])
    c = q.mean(axis=0)
    q = q[np.argsort(np.arctan2(q[:, 1] - c[1], q[:, 0] - c[0]))]
    x, y = q[:, 0], q[:, 1]
    return 0.5 * abs(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))


def hull_volume(P, E, zlo, zhi, dz):
    zs = np.arange(zlo, zhi, dz) + 0.5 * dz
    return sum(section_area(P, E, z) for z in zs) * dz


def analyze(path, d, R, nseg, dz=2.5e-4):
    parts = particles(path)
    A = 0.5 * nseg * R * R * math.sin(2 * math.pi / nseg)
    htop = max(P[:, 2].max() for P, _ in parts)
    zs = np.arange(0.0, htop + dz, dz) + 0.5 * dz
    area = np.zeros_like(zs)
    vol = 0.0
    for P, E in parts:
        lo, hi = P[:, 2].min(), P[:, 2].max()
        k0, k1 = int(lo / dz), int(hi / dz) + 1
        for k in range(max(k0, 0), min(k1 + 1, len(zs))):
            area[k] += section_area(P, E, zs[k])
    phi = area / A
    vol = area.sum() * dz
    bulk = (zs >= 0.5 * d) & (zs <= htop - 1.5 * d)
    phib = phi[bulk].mean() if bulk.any() else float("nan")
    above = np.nonzero(phi >= 0.5 * phib)[0]
    hhalf = zs[above[-1]] + 0.5 * dz if len(above) else float("nan")
    zmin = min(P[:, 2].min() for P, _ in parts)
    rmax = max(np.hypot(P[:, 0], P[:, 1]).max() for P, _ in parts)
    return dict(n=len(parts), H_top=htop, H_half=hhalf, phi_b=phib, phi_H=vol / (A * hhalf),
                phi_top=vol / (A * htop), V=vol, zmin=zmin, rmax=rmax), zs, phi


def add_container_args(ap, R):
    """the container on the command line (this script's and fixed_bed/analyze_bed.py's),
    as analyze takes it: its radius --R (default R) and --nseg, the segments of its mesh"""
    ap.add_argument("--R", type=float, default=R)
    ap.add_argument("--nseg", type=int, default=120)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("vtk")
    ap.add_argument("--d", type=float, required=True, help="circumscribed diameter (m)")
    add_container_args(ap, 0.05)
    ap.add_argument("--profile", default=None)
    a = ap.parse_args()
    r, zs, phi = analyze(a.vtk, a.d, a.R, a.nseg)
    print(" ".join("%s=%.6g" % kv for kv in r.items()))
    if a.profile:
        np.savetxt(a.profile, np.column_stack([zs, phi]), fmt="%.6g", header="z(m) phi(z)")


if __name__ == "__main__":
    main()
