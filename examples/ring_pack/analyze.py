#!/usr/bin/env python3
"""Solid fraction of the settled Raschig rings (examples/ring_pack).

    /usr/bin/python3 analyze.py [pack.180000.txt] [--profile phi_z.txt]

Reads the final dump (id x y z qw qx qy qz). Each ring's solid volume is
spread over height by Monte Carlo in its own frame: 20,000 points uniform in
the ring (annulus 0.375 < r < 0.5, |z| < 0.5, times the scale; the 12-gons
of ring.stl have the circles' areas, so the volumes are equal), turned by
the ring's orientation (the ring's axis is its body z: principal moments
I1 = I2 < I3) and binned in 1 mm layers. The solid fraction of a layer is
the volume in it over the box's area times 1 mm (periodic in x and y, so no
images are needed). The bulk value is taken between 2 ring sizes above the
floor and 2 below the bed's surface (where the profile falls to half its
plateau). Prints it with the void fraction 1 - phi and the envelope
(cylinder) fraction phi / 0.4375.
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from render_vtk import read_dump, rotation  # noqa: E402,F401
from packing_grid import bed_main, bulk_of_profile  # noqa: E402

L = 0.048         # periodic box side [m]
S = 0.008         # ring outer diameter = length [m]
RI = 0.375        # inner radius / S (wall 1/8 of the diameter)
SOLID = 1.0 - (2 * RI) ** 2    # solid share of the ring's envelope: 0.4375
VRING = np.pi / 4 * SOLID * S ** 3


def ring_points(n, rng):
    """n points uniform in the unit ring's solid, body frame"""
    r = np.sqrt(rng.uniform(RI ** 2, 0.25, n))
    a = rng.uniform(0, 2 * np.pi, n)
    return np.column_stack([r * np.cos(a), r * np.sin(a), rng.uniform(-0.5, 0.5, n)])


def profile(x, q, zmax, per_ring=20000, seed=1):
    rng = np.random.default_rng(seed)
    edges = np.arange(0.0, zmax + 0.001, 0.001)
    vol = np.zeros(len(edges) - 1)
    for k in range(len(x)):
        z = x[k, 2] + S * (ring_points(per_ring, rng) @ rotation(q[k])[2])
        vol += np.histogram(z, bins=edges)[0] * (VRING / per_ring)
    return 0.5 * (edges[1:] + edges[:-1]), vol / (L * L * 0.001)


def bulk(zs, phi):
    # layers closer than a ring size are correlated: one independent value per 8
    return bulk_of_profile(zs, phi, 2 * S, 8)


def describe(x, mean, err, top, n):
    return (f"{len(x)} rings; bed surface (half plateau) {1e3 * top:.1f} mm; bulk solid fraction "
            f"{mean:.4f} +- {err:.4f} over {n} layers of 1 mm: void fraction {1 - mean:.4f}, "
            f"envelope fraction {mean / SOLID:.4f}; mean over the bed "
            f"{len(x) * VRING / (L * L * top):.4f}")


if __name__ == "__main__":
    bed_main("pack.180000.txt", profile, S, bulk, describe)
