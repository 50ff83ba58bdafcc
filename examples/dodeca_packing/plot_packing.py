#!/usr/bin/env python3
"""Ensemble figures of the dodecahedron packing (README).

    plot_packing.py results/size_scan.txt [--extra results/mu_dt.txt]
                    [--png packing_height.png] [--summary summary.txt]

Reads run_case.sh lines (key=value), groups them by (d, mu, dt) and prints
mean and sample standard deviation of H_top, H_half, phi_b, phi_H, the sizes
at which the mean fill heights reach 16 cm (linear fit of the ensemble means
against d^3, the relation at constant packing fraction, over the sizes that
bracket 16 cm), and draws height and packing fraction against d."""
import argparse
import collections

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

# regular dodecahedron: volume-equivalent diameter over circumscribed
# diameter (6 V / pi)^(1/3) / d, and sphericity pi^(1/3) (6 V)^(2/3) / A
DV_OVER_D = 0.87279
SPHERICITY = 0.9105
KEYS = ("H_top", "H_half", "phi_b", "phi_H", "t_settle", "wall_s")


def read(paths):
    rows = []
    for p in paths:
        for line in open(p):
            kv = dict(w.split("=", 1) for w in line.split() if "=" in w)
            if "H_top" in kv and kv.get("t_settle"):
                rows.append(kv)
    return rows


def groups(rows):
    g = collections.OrderedDict()
    for r in sorted(rows, key=lambda r: (float(r["mu"]), float(r["dt"]), float(r["d"]))):
        g.setdefault((float(r["d"]), float(r["mu"]), float(r["dt"])), []).append(r)
    out = []
    for (d, mu, dt), rs in g.items():
        e = dict(d=d, mu=mu, dt=dt, n=len(rs))
        for k in KEYS:
            v = np.array([float(r[k]) for r in rs])
            e[k] = v.mean()
            e[k + "_sd"] = v.std(ddof=1) if len(v) > 1 else 0.0
            e[k + "_all"] = v
        out.append(e)
    return out


def phi_benyahia_oneil(d, D=0.10):
    """1 - voidage of Benyahia & O'Neill (2005) for poured beds of uniform
    particles of any shape, eps = 0.1504 + 0.2024 / psi + 1.0814 / (D/d_pe + 0.1226)^2
    (mean error 5.2 %, 1.5 < D/d_pe < 50, 0.42 < psi < 1)"""
    eps = 0.1504 + 0.2024 / SPHERICITY + 1.0814 / (D / (DV_OVER_D * d) + 0.1226) ** 2
    return 1 - eps, 0.052 * eps


def d_at(es, key, h=0.16):
    """d where the mean of key reaches h: fit mean = a d^3 + b on the two sizes
    on either side of h (their neighbours included when there are any)"""
    d = np.array([e["d"] for e in es])
    y = np.array([e[key] for e in es])
    o = np.argsort(d)
    d, y = d[o], y[o]
    i = np.searchsorted(y, h)
    if i == 0 or i == len(y):
        return float("nan"), float("nan")
    sel = slice(max(i - 2, 0), min(i + 2, len(y)))
    a, b = np.polyfit(d[sel] ** 3, y[sel], 1)
    d16 = ((h - b) / a) ** (1 / 3)
    sd = np.mean([e[key + "_sd"] for e in es]) / (3 * a * d16 ** 2)   # height spread -> size
    return d16, sd


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("scan", help="size scan (mu 0.8, dt auto): the figure and the 16 cm sizes")
    ap.add_argument("--extra", nargs="*", default=[], help="more results (mu, dt): table only")
    ap.add_argument("--png", default="packing_height.png")
    ap.add_argument("--summary", default="summary.txt")
    a = ap.parse_args()
    base = groups(read([a.scan]))
    es = base + groups(read(a.extra))
    lines = ["# d(m) mu dt n | H_top mean sd (cm) | H_half mean sd (cm) | phi_b mean sd |"
             " phi_H mean sd | t_settle (s) | wall (s)"]
    for e in es:
        lines.append("%.4f %.2f %.2e %d | %6.2f %.2f | %6.2f %.2f | %.4f %.4f | %.4f %.4f | %.2f | %.0f" % (
            e["d"], e["mu"], e["dt"], e["n"], 100 * e["H_top"], 100 * e["H_top_sd"],
            100 * e["H_half"], 100 * e["H_half_sd"], e["phi_b"], e["phi_b_sd"],
            e["phi_H"], e["phi_H_sd"], e["t_settle"], e["wall_s"]))
    for key in ("H_top", "H_half"):
        d16, sd = d_at(base, key)
        lines.append("d at which the mean %s = 16 cm (size scan): %.2f cm "
                     "(+- %.2f cm from the ensemble spread of %s)" % (key, 100 * d16, 100 * sd, key))
    # a (mu, dt) group at 3.0 cm against the scan's 3.0 cm group
    ref = [e for e in base if abs(e["d"] - 0.030) < 1e-9]
    for e in es[len(base):]:
        if ref and abs(e["d"] - 0.030) < 1e-9:
            r = ref[0]
            se = np.hypot(e["phi_b_sd"] / np.sqrt(e["n"]), r["phi_b_sd"] / np.sqrt(r["n"]))
            sh = np.hypot(e["H_half_sd"] / np.sqrt(e["n"]), r["H_half_sd"] / np.sqrt(r["n"]))
            lines.append("mu %.2f dt %.2e vs the scan at 3.0 cm: phi_b %+.4f (+- %.4f standard error), "
                         "H_half %+.2f cm (+- %.2f)" % (e["mu"], e["dt"], e["phi_b"] - r["phi_b"], se,
                                                        100 * (e["H_half"] - r["H_half"]), 100 * sh))
    if base:
        allphi = np.concatenate([e["phi_b_all"] for e in base])
        lines.append("phi_b over all sizes (mu 0.8): %.3f +- %.3f (%d packings)"
                     % (allphi.mean(), allphi.std(ddof=1), len(allphi)))
    for dd in (0.026, 0.0297, 0.032):
        pc, pe = phi_benyahia_oneil(dd)
        lines.append("Benyahia & O'Neill (2005) at d = %.2f cm (D/d_pe = %.2f): phi = %.3f +- %.3f"
                     % (100 * dd, 0.1 / (DV_OVER_D * dd), pc, pe))
    text = "\n".join(lines)
    print(text)
    open(a.summary, "w").write(text + "\n")

    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 4.2), dpi=110)
    d = np.array([e["d"] for e in base]) * 100
    for key, c, lab in (("H_top", "C0", "highest vertex"), ("H_half", "C1", "phi(z) = phi_b/2")):
        for e in base:
            ax1.plot([100 * e["d"]] * e["n"], 100 * e[key + "_all"], ".", color=c, alpha=0.35)
        ax1.errorbar(d, [100 * e[key] for e in base], yerr=[100 * e[key + "_sd"] for e in base],
                     color=c, marker="o", capsize=3, label=lab + " (mean +- sd)")
    ax1.axhline(16, color="k", ls="--", lw=1, label="seed: experiment and DEM, ~16 cm")
    ax1.axhline(20, color="0.5", ls=":", lw=1, label="container top")
    ax1.set_xlabel("circumscribed diameter d (cm)")
    ax1.set_ylabel("fill height (cm)")
    ax1.set_title("63 dodecahedra, D = 10 cm, mu = 0.8")
    ax1.legend(fontsize=8)
    for key, c, lab in (("phi_b", "C2", "bulk phi_b"), ("phi_H", "C3", "N V_p / (A H_half)")):
        ax2.errorbar(d, [e[key] for e in base], yerr=[e[key + "_sd"] for e in base],
                     color=c, marker="o", capsize=3, label=lab)
    ax2.axhspan(0.50, 0.52, color="0.85", label="Baker & Kudrolli 2010, loosest stable (bulk): 0.51")
    dd = np.linspace(d.min(), d.max(), 50) / 100 if len(d) else np.array([])
    pc, pe = phi_benyahia_oneil(dd)
    ax2.fill_between(100 * dd, pc - pe, pc + pe, color="C0", alpha=0.15,
                     label="Benyahia & O'Neill 2005, poured beds, +- 5.2 % of eps")
    ax2.plot(100 * dd, pc, color="C0", lw=1)
    ax2.set_xlabel("circumscribed diameter d (cm)")
    ax2.set_ylabel("packing fraction")
    ax2.set_ylim(0.40, 0.60)
    ax2.legend(fontsize=7, loc="lower left")
    ax2.set_title("D/d = %.1f to %.1f" % (10 / d.max(), 10 / d.min()) if len(d) else "")
    fig.tight_layout()
    fig.savefig(a.png)
    print("wrote", a.png, a.summary)


if __name__ == "__main__":
    main()
