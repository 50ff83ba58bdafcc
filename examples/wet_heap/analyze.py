#!/usr/bin/env python3
"""Angle of repose of the wet heap example from the final positions
(heap_<Bo>.txt of in.heap), and the picture wet_heap.png.
    /usr/bin/python3 analyze.py [Bo ...]
    /usr/bin/python3 analyze.py --rolling [mu_r ...]   (dry heaps, rolling_heap.png)
    /usr/bin/python3 analyze.py --poured [mu_r ...]    (in.pour's heaps, poured_heap.png)
The heap's surface: the highest sphere top (z + r) in radial rings 1 mm wide
about the heap's axis (its grains' mean x, y), measured from the top of the
rough floor (the fixed spheres' tops, z = 2.1 mm); the angle of repose is
that of a straight line through the surface between 15 % and 85 % of the
heap's height (atan of minus its slope). Prints a table and writes
wet_heap.png."""
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

ZBASE = 0.0021    # top of the fixed spheres of the floor


def load(path):
    rows = []
    with open(path) as f:
        items = None
        for line in f:
            if line.startswith("ITEM: ATOMS"):
                items = line.split()[2:]
                continue
            if items and line.strip():
                rows.append([float(x) for x in line.split()])
    a = np.array(rows)
    return {k: a[:, i] for i, k in enumerate(items)}


def surface(d, width=0.001, zbase=ZBASE):
    """the heap's surface h(r) in rings of 'width' above the floor's top zbase"""
    cx, cy = d["x"].mean(), d["y"].mean()
    rr = np.hypot(d["x"] - cx, d["y"] - cy)
    top = d["z"] + d["radius"] - zbase
    nb = int(rr.max() / width) + 1
    r = (np.arange(nb) + 0.5) * width
    h = np.array([top[(rr >= k * width) & (rr < (k + 1) * width)].max()
                  if np.any((rr >= k * width) & (rr < (k + 1) * width)) else np.nan for k in range(nb)])
    return r, h, rr, top


def angle(r, h):
    H = np.nanmax(h)
    sel = np.isfinite(h) & (h > 0.15 * H) & (h < 0.85 * H)
    slope, icpt = np.polyfit(r[sel], h[sel], 1)
    return math.degrees(math.atan(-slope)), slope, icpt, sel, H


def rolling(murs):
    """dry heaps against the rolling friction mu_r (rolling_<mu_r>.txt; 0.1 is heap_0.txt)"""
    print("| mu_r | heap height (mm) | radius of the foot (mm) | angle of repose (deg) |")
    print("|---|---|---|---|")
    res = []
    for m in murs:
        d = load("heap_0.txt" if float(m) == 0.1 else f"rolling_{m}.txt")
        r, h, rr, top = surface(d)
        th, slope, icpt, sel, H = angle(r, h)
        print(f"| {m} | {H * 1e3:.1f} | {np.nanmax(r[np.isfinite(h)]) * 1e3:.1f} | {th:.1f} |")
        res.append((float(m), th))
    res = np.array(res)
    fig, ax = plt.subplots(figsize=(5, 3.6), dpi=110)
    ax.plot(res[:, 0], res[:, 1], "o-")
    ax.set_xlabel("rolling friction $\\mu_r$ (EPSD)")
    ax.set_ylabel("angle of repose (deg)")
    ax.set_title("dry slumped columns (Bo = 0) against rolling friction", fontsize=9)
    fig.tight_layout()
    fig.savefig("rolling_heap.png")
    print("wrote rolling_heap.png")


def series(runs, dots, title, xlabel, ylabel, title2, png, base=None):
    """profiles (left) and the angle against the run's parameter (right) of
    runs = [(value, label text, positions)], written to png: the angle of
    repose of the line fit (angle()), or with base (the radius of a fixed
    base) the heap's mean slope atan(H / base), without fit lines"""
    fig, ax = plt.subplots(1, 2, figsize=(11, 4.2), dpi=110)
    res = []
    for k, (value, text, d) in enumerate(runs):
        r, h, rr, top = surface(d)
        th, slope, icpt, sel, H = angle(r, h)
        if base:
            th = math.degrees(math.atan(H / base))
        res.append((value, th))
        yield value, d, H, np.nanmax(r[np.isfinite(h)]), th
        c = f"C{k}"
        if dots:
            ax[0].plot(rr * 1e3, top * 1e3, ".", ms=2, color=c, alpha=0.35)
        ax[0].plot(r * 1e3, h * 1e3, "-", color=c, label=f"{text}: {th:.1f}°")
        if not base:
            x = r[sel]
            ax[0].plot(x * 1e3, (slope * x + icpt) * 1e3, "--", color=c, lw=0.8)
    ax[0].set_xlabel("distance from the heap's axis (mm)")
    ax[0].set_ylabel(ylabel)
    ax[0].set_title(title, fontsize=9)
    ax[0].legend(fontsize=8)
    res = np.array(res)
    ax[1].plot(res[:, 0], res[:, 1], "o-")
    ax[1].set_xlabel(xlabel)
    ax[1].set_ylabel("mean slope atan(H / R) (deg)" if base else "angle of repose (deg)")
    ax[1].set_title(title2, fontsize=9)
    fig.tight_layout()
    fig.savefig(png)
    print(f"wrote {png}")


def poured(murs, base=0.025):
    """conical heaps poured onto the fixed base of radius 'base' (in.pour:
    poured_<mu_r>.txt) against the rolling friction mu_r; only grains on the
    base (r < base, z > 0) count. The angle of repose: the line fit of
    angle() through the cone's flank"""
    print("| mu_r | grains on the base | heap height H (mm) | angle of repose (deg) | "
          "mean slope atan(H/R) (deg) |")
    print("|---|---|---|---|---|")
    runs = []
    for m in murs:
        d = load(f"poured_{m}.txt")
        keep = (np.hypot(d["x"], d["y"]) < base) & (d["z"] > 0.0)
        runs.append((float(m), f"$\\mu_r$ = {m}", {key: v[keep] for key, v in d.items()}))
    for m, d, H, foot, th in series(runs, True, f"heaps poured on a base of radius R = "
                                    f"{base * 1e3:g} mm (dots: sphere tops; dashed: fit)",
                                    "rolling friction $\\mu_r$ (EPSD)",
                                    "height above the rough base (mm)",
                                    "dry poured heaps against rolling resistance",
                                    "poured_heap.png"):
        print(f"| {m:g} | {len(d['x'])} | {H * 1e3:.1f} | {th:.1f} | "
              f"{math.degrees(math.atan(H / base)):.1f} |")


def main():
    if len(sys.argv) > 1 and sys.argv[1] == "--poured":
        poured(sys.argv[2:] if len(sys.argv) > 2 else ["0", "0.05", "0.1", "0.2", "0.4"])
        return
    if len(sys.argv) > 1 and sys.argv[1] == "--rolling":
        rolling(sys.argv[2:] if len(sys.argv) > 2 else ["0", "0.05", "0.1", "0.2", "0.4"])
        return
    bos = sys.argv[1:] if len(sys.argv) > 1 else ["0", "1", "3", "10"]
    print("| Bo | heap height (mm) | radius of the foot (mm) | angle of repose (deg) |")
    print("|---|---|---|---|")
    runs = [(float(bo), f"Bo = {bo}", load(f"heap_{bo}.txt")) for bo in bos]
    for bo, d, H, foot, th in series(runs, True,
                                     "heap profiles (dots: sphere tops; line: surface; dashed: fit)",
                                     "Bond number Bo = 2π r γ / (m g)",
                                     "height above the rough floor (mm)", "wet heaps stand steeper",
                                     "wet_heap.png"):
        print(f"| {bo:g} | {H * 1e3:.1f} | {foot * 1e3:.1f} | {th:.1f} |")


if __name__ == "__main__":
    main()
