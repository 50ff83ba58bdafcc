#!/usr/bin/env python3
"""compare.py A B: largest difference of per-atom forces (and torques) between
two dumps of in.dense2000 (or in.settle), relative to the largest |f| (normwise)
and per atom (atoms with |f| > 1e-6 max|f|)."""
import sys
import numpy as np


def read(fn):
    lines = open(fn).read().splitlines()
    i = lines.index(next(l for l in lines if l.startswith("ITEM: ATOMS")))
    cols = lines[i].split()[2:]
    data = np.array([[float(x) for x in l.split()] for l in lines[i + 1:] if l.strip()])
    return cols, data[np.argsort(data[:, 0])]


def compare(a, b, cols, names):
    out = {}
    for name in names:
        k = [cols.index(c) for c in name]
        va, vb = a[:, k], b[:, k]
        nb = np.linalg.norm(vb, axis=1)
        d = np.linalg.norm(va - vb, axis=1)
        big = nb > 1e-6 * nb.max()
        out[name[0][:-1] or name[0]] = (d.max() / nb.max(), (d[big] / nb[big]).max())
    return out


if __name__ == "__main__":
    ca, a = read(sys.argv[1])
    cb, b = read(sys.argv[2])
    assert ca == cb and (a[:, 0] == b[:, 0]).all(), "different atoms"
    groups = [c for c in (["fx", "fy", "fz"], ["tqx", "tqy", "tqz"], ["x", "y", "z"],
                          ["vx", "vy", "vz"]) if all(x in ca for x in c)]
    for name, (nw, pa) in compare(a, b, ca, groups).items():
        print(f"{sys.argv[1]} vs {sys.argv[2]}: {len(a)} atoms, {name}: "
              f"normwise {nw:.3g}, per atom {pa:.3g}")
