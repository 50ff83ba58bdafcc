#!/usr/bin/env python3
"""Solid occupancy of a packing of convex particles on a regular grid, for
porosity and packing-fraction maps (examples/fixed_bed, examples/silo).

    from packing_grid import hulls, occupancy
    H = hulls("final.vtk")                  # per particle: vertices, hull planes
    solid = occupancy(H, xs, ys, zs)        # bool array (len(xs), len(ys), len(zs))

A grid point is solid if it lies in a particle's convex hull (n.x + c <= 0
for every face plane); each particle tests only the points of its bounding
box."""
import sys

import numpy as np
from scipy.spatial import ConvexHull

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from render_vtk import read_dump, read_vtk  # noqa: E402


def hulls(path):
    """[(vertices, hull equations)] per particle of a dump polyhedron/vtk file, by atom ID"""
    pts, polys, cell = read_vtk(path)
    verts = {}
    for f, pid in zip(polys, cell["id"]):
        verts.setdefault(int(pid), set()).update(f)
    out = []
    for pid in sorted(verts):
        P = pts[sorted(verts[pid])]
        out.append((P, ConvexHull(P).equations))
    return out


def occupancy(H, xs, ys, zs):
    """bool array: grid point (xs[i], ys[j], zs[k]) inside a particle"""
    solid = np.zeros((len(xs), len(ys), len(zs)), dtype=bool)
    for P, eq in H:
        lo, hi = P.min(axis=0), P.max(axis=0)
        i0, i1 = np.searchsorted(xs, lo[0]), np.searchsorted(xs, hi[0])
        j0, j1 = np.searchsorted(ys, lo[1]), np.searchsorted(ys, hi[1])
        k0, k1 = np.searchsorted(zs, lo[2]), np.searchsorted(zs, hi[2])
        if i1 <= i0 or j1 <= j0 or k1 <= k0:
            continue
        g = np.stack(np.meshgrid(xs[i0:i1], ys[j0:j1], zs[k0:k1], indexing="ij"), axis=-1)
        solid[i0:i1, j0:j1, k0:k1] |= np.all(g @ eq[:, :3].T + eq[:, 3] <= 0.0, axis=-1)
    return solid


def bulk_of_profile(zs, phi, margin, per_value):
    """The bulk of a settled bed's layer profile (zs, phi): the plateau is
    the median of the layers above margin that exceed half the profile's
    maximum, the surface the highest layer above half the plateau; the bulk
    is the mean of the layers from margin above the floor to margin below the
    surface, its error counting one independent value per per_value layers.
    Returns (mean, error, surface height, number of layers)."""
    plateau = np.median(phi[(zs > margin) & (phi > 0.5 * phi.max())])
    top = zs[np.flatnonzero(phi > 0.5 * plateau).max()]
    sel = (zs > margin) & (zs < top - margin)
    return phi[sel].mean(), phi[sel].std() / np.sqrt(max(1, sel.sum() // per_value)), top, sel.sum()


def bed_main(default_dump, profile, zpad, bulk, describe):
    """The command line of the examples' analyze.py: reads a dump (id x y z
    qw qi qj qk), writes profile(x, q, zmax) as phi_z.txt (--profile) up to
    zpad above the highest centre, prints describe(x, mean, err, top, n) of
    bulk(zs, phi)."""
    import argparse
    ap = argparse.ArgumentParser()
    ap.add_argument("dump", nargs="?", default=default_dump)
    ap.add_argument("--profile", default="phi_z.txt")
    a = ap.parse_args()
    x, q = read_dump(a.dump)
    zs, phi = profile(x, q, x[:, 2].max() + zpad)
    np.savetxt(a.profile, np.column_stack([zs, phi]), header="z [m]  solid fraction", fmt="%.6g")
    print(describe(x, *bulk(zs, phi)))


def bed_figure(path, verts, colors, box, pad, zmax, view, title, zs, phi, bulk, margin,
               xmax, xlabel, ptitle, band=None, figsize=(11, 5.2), lw=0.15):
    """The examples' picture of a settled bed: left, its faces (verts,
    colors) in a periodic box of side box (drawn with pad around it, up to
    zmax; view = (elev, azim)); right, the layer profile (zs, phi) with the
    bulk value (bulk = (mean, err, top)), the bulk layers (margin from floor
    and surface) and an optional reference band (lo, hi, label)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection
    mean, err, top = bulk
    fig = plt.figure(figsize=figsize)
    a = fig.add_subplot(1, 2, 1, projection="3d")
    a.add_collection3d(Poly3DCollection(verts, facecolors=colors, edgecolors=(0, 0, 0, 0.25),
                                        linewidths=lw))
    a.set_xlim(-pad, box + pad)
    a.set_ylim(-pad, box + pad)
    a.set_zlim(0, zmax)
    a.set_box_aspect((1, 1, zmax / (box + 2 * pad)))
    a.view_init(elev=view[0], azim=view[1])
    for name, axis in (("x", a.set_xlabel), ("y", a.set_ylabel), ("z", a.set_zlabel)):
        axis(f"{name} [m]")
    a.set_title(title)
    b = fig.add_subplot(1, 2, 2)
    if band is not None:
        b.axvspan(band[0], band[1], color="tab:orange", alpha=0.35, label=band[2])
    b.plot(phi, 1e3 * zs, "-", color="tab:blue")
    b.axvline(mean, color="k", ls="--", lw=1, label=f"bulk {mean:.3f} ± {err:.3f}")
    b.axhspan(1e3 * margin, 1e3 * (top - margin), color="0.9", label="bulk layers")
    b.set_xlabel(xlabel)
    b.set_ylabel("height z [mm]")
    b.set_xlim(0, xmax)
    b.legend(loc="upper right")
    b.set_title(ptitle)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
