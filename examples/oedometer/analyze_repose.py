#!/usr/bin/env python3
"""Angle of repose of the oedometer's grains (in.repose) and Jaky's
K0 = 1 - sin(phi) from it, against the K0 the oedometer measured.
    /usr/bin/python3 analyze_repose.py [HEAP ...]     (default repose_heap.txt)
    /usr/bin/python3 analyze_repose.py --plot OUT.png HEAP ...
The heap's surface as in ../wet_heap/analyze.py: the highest grain top
(z + bounding radius) in radial rings 4 mm wide, above the top of the fixed
spheres (z = 8.4 mm), and the slope of a line through it between 15 % and
85 % of the heap's height. With several heaps (other seeds of the same
grains), their mean angle and its spread; with --plot, their surfaces."""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../wet_heap"))
from analyze import angle, load, surface  # noqa: E402

args = sys.argv[1:]
plot = None
if args[:1] == ["--plot"]:
    plot, args = args[1], args[2:]
paths = args or ["repose_heap.txt"]
phis, curves = [], []
for p in paths:
    d = load(p)
    r, h, rr, top = surface(d, width=0.004, zbase=0.0084)
    phi, slope, icpt, sel, H = angle(r, h)
    phis.append(phi)
    curves.append((p, r, h, slope, icpt, sel, phi))
    print(f"{p}: heap of {len(d['x'])} grains: height {H * 1e3:.1f} mm, angle of repose {phi:.1f} deg; "
          f"Jaky K0 = 1 - sin(phi) = {1 - math.sin(math.radians(phi)):.3f}")
if len(phis) > 1:
    m = sum(phis) / len(phis)
    k0 = [1 - math.sin(math.radians(p)) for p in phis]
    print(f"{len(phis)} heaps: angle of repose {m:.1f} deg (from {min(phis):.1f} to {max(phis):.1f}); "
          f"Jaky K0 = {1 - math.sin(math.radians(m)):.3f} (from {min(k0):.3f} to {max(k0):.3f})")
if plot:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt  # noqa: E402

    fig, ax = plt.subplots(figsize=(7, 3.6))
    for k, (p, r, h, slope, icpt, sel, phi) in enumerate(curves):
        c = f"C{k}"
        ax.plot(1e3 * r, 1e3 * h, "o", ms=3, color=c, label=f"{os.path.basename(p)}: {phi:.1f} deg")
        ax.plot(1e3 * r[sel], 1e3 * (slope * r[sel] + icpt), "-", color=c, lw=1)
    ax.set_xlabel("distance from the heap's axis (mm)")
    ax.set_ylabel("surface height (mm)")
    ax.set_title("heaps of in.repose: surface and the line fitted to it")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(plot, dpi=110)
