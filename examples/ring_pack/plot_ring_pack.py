#!/usr/bin/env python3
"""The settled Raschig rings (ring_pack.png): left, the bed in perspective
(every sector of every ring drawn, shaded by its normal); right, the solid
fraction per 1 mm layer (analyze.py), the bulk value and the band of the
packing tables' ceramic rings (void fraction 0.73-0.74).

    /usr/bin/python3 plot_ring_pack.py [pack.180000.vtk] [pack.180000.txt]
"""
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path[:0] = [os.path.join(here, "..", "..", "tools"), here]
from analyze import L, S, SOLID, bulk, profile, read_dump  # noqa: E402
from packing_grid import bed_figure  # noqa: E402
from render_vtk import faces_colors, read_vtk  # noqa: E402

vtk = sys.argv[1] if len(sys.argv) > 1 else "pack.180000.vtk"
x, q = read_dump(sys.argv[2] if len(sys.argv) > 2 else "pack.180000.txt")
verts, colors = faces_colors(*read_vtk(vtk), color_by="id")    # a colour per ring
zs, phi = profile(x, q, x[:, 2].max() + S)
mean, err, top, nl = bulk(zs, phi)
bed_figure("ring_pack.png", verts, colors, L, 0.006, 1.1 * top + S, (16, -62),
           f"{len(x)} Raschig rings settled (8 x 8 mm, wall 1 mm)", zs, phi, (mean, err, top),
           2 * S, 0.5, "solid fraction of the layer (1 - void fraction)",
           "solid fraction per 1 mm layer", band=(1 - 0.74, 1 - 0.73, "ceramic rings, tables: 0.26-0.27"),
           figsize=(11, 6.2), lw=0.1)
print(f"wrote ring_pack.png; bulk solid fraction {mean:.4f} +- {err:.4f}, "
      f"envelope fraction {mean / SOLID:.4f}")
