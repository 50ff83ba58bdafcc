#!/usr/bin/env python3
"""Tally the contacts of a settled mixed bed by the kinds of the two grains.

    count.py mixed.shapes mixed.contacts [--markdown]

mixed.shapes: dump custom (id, 1-based template index, z); mixed.contacts:
dump local (id1, id2, overlap measure). Prints, per kind pair, the number of
contacts, the law that acts (overlap volume or the algebraic contact of two
ellipsoids) and the mean overlap measure (volume over the smaller grain's, or
delta over the smallest semi-axis); then per kind the mean number of grain
contacts per grain."""
import argparse
import itertools

KINDS = ["dodecahedron", "cube", "sphere", "ellipsoid"]    # template order of in.mixed
ELLIPSOIDS = {2, 3}
SPHERES = {2}


def read_dump(path):
    rows, cols = [], None
    with open(path) as f:
        lines = f.read().splitlines()
    i = 0
    while i < len(lines):
        if lines[i].startswith("ITEM: NUMBER OF"):
            n = int(lines[i + 1])
            j = i + 2
            while not lines[j].startswith("ITEM: ATOMS") and not lines[j].startswith("ITEM: ENTRIES"):
                j += 1
            cols = lines[j].split()[2:]
            rows = [lines[j + 1 + k].split() for k in range(n)]
            i = j + 1 + n
        else:
            i += 1
    return cols, rows


def law(a, b):
    if a in ELLIPSOIDS and b in ELLIPSOIDS and not (a in SPHERES and b in SPHERES):
        return "algebraic (k_n)"
    return "overlap volume"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("shapes")
    ap.add_argument("contacts")
    ap.add_argument("--markdown", action="store_true")
    a = ap.parse_args()
    _, srows = read_dump(a.shapes)
    kind = {int(r[0]): int(float(r[1])) - 1 for r in srows}
    _, crows = read_dump(a.contacts)
    count, meas = {}, {}
    per_grain = {i: 0 for i in kind}
    for r in crows:
        i, j, m = int(float(r[0])), int(float(r[1])), float(r[2])
        key = tuple(sorted((kind[i], kind[j])))
        count[key] = count.get(key, 0) + 1
        meas[key] = meas.get(key, 0.0) + m
        per_grain[i] += 1
        per_grain[j] += 1
    sep = " | " if a.markdown else "  "
    if a.markdown:
        print("| kinds | contacts | law | mean overlap |")
        print("|---|---|---|---|")
    for key in itertools.combinations_with_replacement(range(4), 2):
        n = count.get(key, 0)
        mean = meas.get(key, 0.0) / n if n else 0.0
        row = [f"{KINDS[key[0]]}-{KINDS[key[1]]}", str(n), law(*key), f"{mean:.2g}"]
        print(("| " + sep.join(row) + " |") if a.markdown else sep.join(row))
    print(f"{len(crows)} contacts between {len(kind)} grains")
    for k in range(4):
        g = [per_grain[i] for i in kind if kind[i] == k]
        if g:
            print(f"{KINDS[k]}: {len(g)} grains, {sum(g) / len(g):.2f} grain contacts per grain")


if __name__ == "__main__":
    main()
