#!/usr/bin/env python3
"""Picture of the settled mixed bed: the grains in the cylinder, coloured by
kind, beside the number of contacts of each kind pair (marked k_n: the
algebraic contact of two ellipsoids; the others by overlap volume).

    picture.py mixed.vtk mixed.shapes mixed.contacts out.png"""
import argparse
import itertools
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.patches import Patch  # noqa: E402

here = __file__.rsplit("/", 1)[0] if "/" in __file__ else "."
sys.path.insert(0, here + "/../../tools")
sys.path.insert(0, here)
from render_vtk import draw  # noqa: E402
from count import KINDS, law, read_dump  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("vtk")
    ap.add_argument("shapes")
    ap.add_argument("contacts")
    ap.add_argument("png")
    a = ap.parse_args()
    _, srows = read_dump(a.shapes)
    kind = {int(r[0]): int(float(r[1])) - 1 for r in srows}
    _, crows = read_dump(a.contacts)
    count = {}
    for r in crows:
        key = tuple(sorted((kind[int(float(r[0]))], kind[int(float(r[1]))])))
        count[key] = count.get(key, 0) + 1
    ngrain = [sum(1 for k in kind.values() if k == i) for i in range(4)]

    fig = plt.figure(figsize=(11, 5.2), dpi=110)
    ax = fig.add_axes([0.0, 0.0, 0.5, 0.95], projection="3d")
    draw(ax, a.vtk, elev=16, azim=-60, limits=(np.array([-0.05, -0.05, 0.0]),
                                              np.array([0.05, 0.05, 0.06])))
    t = np.linspace(0, 2 * np.pi, 121)
    for z in (0.0, 0.06):
        ax.plot(0.05 * np.cos(t), 0.05 * np.sin(t), z, color="0.45", lw=0.8)
    ax.set_axis_off()
    palette = plt.get_cmap("tab10")
    ax.legend(handles=[Patch(color=palette(i), label=f"{KINDS[i]} ({ngrain[i]})") for i in range(4)],
              loc="upper left", frameon=False, fontsize=9)
    ax.set_title(f"{len(kind)} grains of equal volume settled in a 10 cm cylinder", fontsize=10)

    bx = fig.add_axes([0.6, 0.32, 0.37, 0.58])
    keys = list(itertools.combinations_with_replacement(range(4), 2))
    short = ["dod", "cube", "sph", "ell"]
    vals = [count.get(k, 0) for k in keys]
    bars = bx.bar(range(len(keys)), vals, color=[palette(k[0]) for k in keys],
                  edgecolor=[palette(k[1]) for k in keys], linewidth=2.5)
    for b, k in zip(bars, keys):
        if law(*k).startswith("algebraic"):
            bx.text(b.get_x() + 0.5 * b.get_width(), b.get_height() + 0.5, "k_n", ha="center",
                    va="bottom", fontsize=8)
    bx.set_xticks(range(len(keys)))
    bx.set_xticklabels([f"{short[k[0]]}-{short[k[1]]}" for k in keys], rotation=60, fontsize=9)
    bx.set_ylabel("contacts in the settled bed")
    bx.set_ylim(0, 1.12 * max(vals))
    bx.set_title(f"{len(crows)} grain-grain contacts by kind pair\n(k_n: algebraic contact of two "
                 "ellipsoids; others: overlap volume)", fontsize=9)
    fig.savefig(a.png)
    print(f"picture.py: wrote {a.png}")


if __name__ == "__main__":
    main()
