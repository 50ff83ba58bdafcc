#!/usr/bin/env python3
"""Compare the thermo output of a LAMMPS log with a reference log.

    compare_log.py new.log reference.log [--rtol 1e-10] [--atol 1e-300]

Every thermo table (the lines between a header starting with "Step" and the
"Loop time" line) must have the same columns and rows; each value must agree
within rtol (relative) or atol (absolute). Exit 0 if they agree, 1 if not,
2 on a malformed log. Used by the example regression tests.
"""
import argparse
import sys


def thermo_tables(path):
    tables, cur, header = [], None, None
    with open(path) as f:
        for line in f:
            w = line.split()
            if w and w[0] == "Step":
                header, cur = w, []
                continue
            if cur is not None:
                if line.startswith("Loop time"):
                    tables.append((header, cur))
                    cur = None
                    continue
                try:
                    cur.append([float(x) for x in w])
                except ValueError:
                    continue  # warnings interleaved with thermo lines
    return tables


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("new")
    ap.add_argument("ref")
    ap.add_argument("--rtol", type=float, default=1e-10)
    ap.add_argument("--atol", type=float, default=1e-300)
    a = ap.parse_args()
    new, ref = thermo_tables(a.new), thermo_tables(a.ref)
    if not ref:
        print(f"compare_log: no thermo table in {a.ref}")
        return 2
    if len(new) != len(ref):
        print(f"compare_log: {len(new)} thermo tables in {a.new}, {len(ref)} in {a.ref}")
        return 1
    worst = 0.0
    for t, ((hn, rn), (hr, rr)) in enumerate(zip(new, ref)):
        if hn != hr:
            print(f"compare_log: table {t}: columns {hn} != {hr}")
            return 1
        if len(rn) != len(rr):
            print(f"compare_log: table {t}: {len(rn)} rows != {len(rr)}")
            return 1
        for i, (rowa, rowb) in enumerate(zip(rn, rr)):
            for c, (x, y) in enumerate(zip(rowa, rowb)):
                d = abs(x - y)
                rel = d / max(abs(x), abs(y)) if d > 0 else 0.0
                worst = max(worst, rel)
                if d > a.atol and d > a.rtol * max(abs(x), abs(y)):
                    print(f"compare_log: table {t} row {i} column {hr[c]}: {x!r} vs {y!r} "
                          f"(rel {rel:.3g} > {a.rtol})")
                    return 1
    print(f"compare_log: {len(ref)} table(s) agree, worst relative difference {worst:.3g}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
