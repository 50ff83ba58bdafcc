#!/usr/bin/env python3
"""/kk against plain, measured against the run's own sensitivity.

    compare_runs.py plain.log perturbed.log kk.log [--factor 100] [--floor 1e-10] [--common]

plain.log and kk.log are the same input run by the plain and the /kk styles;
perturbed.log is the plain run with every atom moved at random by ~1e-12 of
the box (the inputs' `perturb` variable). A granular run amplifies any
difference, so the plain-vs-perturbed difference d_p of each thermo value
measures how far round-off alone may carry it by then. The /kk run passes if
for every thermo value its difference d_kk <= max(factor * d_p, floor)
(relative). Rows where d_p > 1e-3 (chaos saturated: no evidence either way)
are reported and not judged; at least one judged row after the first must
remain. --common judges the rows the three logs have in common (a run cut
short against the full run's logs: the first tables, each to the shortest).
Exit 0 pass, 1 fail, 2 malformed logs. Standard library only.
"""
import argparse
import sys


def tables(path):
    out, cur = [], None
    with open(path) as f:
        for line in f:
            w = line.split()
            if w and w[0] == "Step":
                cur = {"header": w, "rows": []}
                out.append(cur)
                continue
            if cur is None:
                continue
            if w and w[0] == "Loop":
                cur = None
                continue
            try:
                cur["rows"].append([float(x) for x in w])
            except ValueError:
                cur = None
    return out


def rel(a, b):
    if a == b:
        return 0.0
    den = max(abs(a), abs(b))
    return abs(a - b) / den if den > 0 else 0.0


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("plain")
    ap.add_argument("perturbed")
    ap.add_argument("kk")
    ap.add_argument("--factor", type=float, default=100.0)
    ap.add_argument("--floor", type=float, default=1e-10)
    ap.add_argument("--common", action="store_true")
    a = ap.parse_args()
    try:
        tp, tq, tk = tables(a.plain), tables(a.perturbed), tables(a.kk)
    except OSError as e:
        print(f"compare_runs: {e}")
        return 2
    if a.common:
        nt = min(len(tp), len(tq), len(tk))
        tp, tq, tk = tp[:nt], tq[:nt], tk[:nt]
        for p, q, k in zip(tp, tq, tk):
            nr = min(len(p["rows"]), len(q["rows"]), len(k["rows"]))
            p["rows"], q["rows"], k["rows"] = p["rows"][:nr], q["rows"][:nr], k["rows"][:nr]
    if not tp or len(tp) != len(tq) or len(tp) != len(tk):
        print(f"compare_runs: thermo tables differ in number ({len(tp)}, {len(tq)}, {len(tk)})")
        return 2
    judged = failed = saturated = 0
    worst = (0.0, None)
    for it, (p, q, k) in enumerate(zip(tp, tq, tk)):
        if p["header"] != k["header"] or len(p["rows"]) != len(k["rows"]) or \
                len(p["rows"]) != len(q["rows"]):
            print(f"compare_runs: table {it}: columns or rows differ")
            return 2
        for ir, (rp, rq, rk) in enumerate(zip(p["rows"], q["rows"], k["rows"])):
            dp = max(rel(x, y) for x, y in zip(rp, rq))
            if dp > 1e-3:
                saturated += 1
                continue
            if it > 0 or ir > 0:
                judged += 1
            for j, (x, z) in enumerate(zip(rp, rk)):
                dk = rel(x, z)
                allowed = max(a.factor * rel(x, rq[j]), a.floor)
                if dk > worst[0]:
                    worst = (dk, f"table {it} step {rp[0]:.0f} {p['header'][j]}")
                if not dk <= allowed:
                    failed += 1
                    if failed <= 5:
                        print(f"  table {it} step {rp[0]:.0f} {p['header'][j]}: plain {x:.12g} "
                              f"kk {z:.12g} (rel {dk:.3g}; perturbed plain {rq[j]:.12g}, "
                              f"allowed {allowed:.3g})")
    ok = failed == 0 and judged > 0
    print(f"compare_runs: {judged} rows judged, {saturated} saturated, {failed} values outside; "
          f"largest kk-vs-plain difference {worst[0]:.3g} ({worst[1]}): "
          f"{'PASS' if ok else 'FAIL'}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
