#!/usr/bin/python3
"""Plot and check the homogeneous cooling runs of in.hcs (log.hcs_xi*_N*).

E_tr(t)/E_tr(0) against tau = alpha Gamma0 t, alpha = (1 - e_n^2)/(2 D), D = 5, with Gamma0
from the seed's Eq. 28 (eq28.py: Song-Mason g_c, S_c <D>_c from kinetic theory,
T(0) = (2/3) E_tr(0)/N), compared with Haff's law 1/(1+tau)^2 (seed Eq. 27).

E_tr(0): at the start of cooling the elastic gas is in equipartition over its 5 degrees of
freedom, so the expected translational energy is (3/5) of the conserved elastic energy
E_kin + E_rot + pe at t0 (exact, no sampling noise); the instantaneous E_tr(t0) differs from it
by the finite-N fluctuation of the translation/rotation split (about 1 % for N = 4096), which
decays within a few collision times and would otherwise offset the whole curve. For logs of
in.hcs, E_tr(t) is the average over each output interval (100 samples), compared with Haff's
law averaged over the same samples (plotted at the interval's mid-time). The total kinetic energy (E_tr + E_rot)/(E_tr + E_rot)(0) is
analysed the same way (no split noise: it tests the cooling law itself).
Logs of the same xi and N (different seeds) are averaged into one ensemble curve.
Prints, per run or ensemble: Gamma0 of Eq. 28 against the measured collision rate, the largest relative
deviations from Haff's law for tau <= 5, the fitted alpha*/alpha, and T_tr/T_rot.
Usage: plot_hcs.py [log files...]  (default: all log.hcs_xi*); writes hcs.png
"""
import glob
import math
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

import eq28

EN = 0.95
ALPHA = (1 - EN ** 2) / 10.0
NSAMP = 100    # samples per output interval (in.hcs: fix eavg ave/time 100 100 10000)
_SCDC = {}


def sc_dc(xi):
    if xi not in _SCDC:
        _SCDC[xi] = eq28.sc_dc(xi)[1]
    return _SCDC[xi]


def read(path):
    """info: the 'HCS xi ...' line; first: the cooling run's first thermo line (t0);
    rows: the cooling run's thermo lines with interval averages."""
    info, rows, first, cooling = {}, [], None, False
    with open(path) as f:
        for line in f:
            w = line.split()
            if line.startswith("HCS xi"):
                for k in range(1, len(w) - 1, 2):
                    try:
                        info[w[k]] = float(w[k + 1])
                    except ValueError:
                        pass
            if w[:3] == ["Step", "Time", "v_tau"]:
                cooling = True
                continue
            if cooling and len(w) == 12 and w[0].isdigit():
                r = [float(x) for x in w]
                if first is None:
                    first = r    # t0: no interval average yet
                else:
                    rows.append(r)
            elif cooling and w[:2] == ["Loop", "time"]:
                cooling = False
    return info, first, rows


def analyse(info, first, rows):
    """Gamma0 (Eq. 28), tau at the mid-time of each averaging interval, E_tr/E_tr(0),
    E_kin/E_kin(0), T_tr/T_rot (interval averages), T_tr/T_rot at t0."""
    xi, n_atoms, b, m = info["xi"], info["N"], info["b"], info["m"]
    box = info["L"]
    eta = n_atoms * 4.0 / 3.0 * math.pi * xi * b ** 3 / box ** 3
    ekin0 = first[6] + first[7] + first[8]    # ke + E_rot + pe at t0: conserved elastic energy
    etr0 = 0.6 * ekin0
    g28 = eq28.gamma0(xi, b, m, n_atoms / box ** 3, 2.0 / 3.0 * etr0 / n_atoms, eta, sc_dc(xi))
    span = rows[1][1] - rows[0][1] if len(rows) > 1 else 0.0
    tau = [ALPHA * g28 * (r[1] - 0.5 * span - info["t0"]) for r in rows]
    # the interval averages are means of NSAMP samples ending at the output step
    # (fix ave/time 100 100 10000): Haff's law is averaged over the same samples, so
    # that the curvature of 1/(1+tau)^2 within an interval (0.3 % at tau = 0) is not
    # counted as a deviation; ratios are returned relative to that average
    haff = [sum((1 + ALPHA * g28 * (r[1] - span * (NSAMP - 1 - k) / NSAMP - info["t0"])) ** -2
                for k in range(NSAMP)) / NSAMP for r in rows]
    etr = [r[10] / etr0 / h * (1 + t) ** -2 for r, h, t in zip(rows, haff, tau)]
    ekin = [(r[10] + r[11]) / ekin0 / h * (1 + t) ** -2 for r, h, t in zip(rows, haff, tau)]
    trot = [2.0 / 3.0 * r[10] / r[11] for r in rows]
    return g28, tau, etr, ekin, trot, 2.0 / 3.0 * first[6] / first[7]


def deviation(tau, ratio, lo=0.0, hi=5.0):
    sel = [(t, r) for t, r in zip(tau, ratio) if lo <= t <= hi]
    dev = max(abs(r * (1 + t) ** 2 - 1) for t, r in sel)
    # least-squares slope of (E/E0)^(-1/2) - 1 against tau: alpha*/alpha
    slope = sum(t * (r ** -0.5 - 1) for t, r in sel) / sum(t * t for t, r in sel)
    return dev, slope


def ensembles(files):
    """Runs grouped by (xi, N): independent seeds of the same state. Per group, the
    interval-averaged curves are averaged over the runs at equal interval index (tau differs
    between seeds only through T(0), by ~0.1 %, and is averaged too)."""
    groups = {}
    for path in files:
        info, first, rows = read(path)
        if len(rows) < 2:
            continue
        groups.setdefault((info["xi"], info["N"]), []).append((path, info, first, rows))
    out = []
    for key in sorted(groups):
        runs = groups[key]
        res = [analyse(info, first, rows) for _, info, first, rows in runs]
        n = min(len(r[1]) for r in res)
        k = len(res)
        mean = lambda j: [sum(r[j][i] for r in res) / k for i in range(n)]
        g28 = sum(r[0] for r in res) / k
        trot0 = sum(r[5] for r in res) / k
        info = dict(runs[0][1])
        info["Gamma0"] = sum(r[1]["Gamma0"] for r in runs) / k
        out.append((", ".join(r[0] for r in runs), k, info,
                    (g28, mean(1), mean(2), mean(3), mean(4), trot0)))
    return out


def main():
    files = sys.argv[1:] or sorted(glob.glob("log.hcs_xi*"))
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.2))
    tmax = 0.0
    for path, nruns, info, res in ensembles(files):
        xi = info["xi"]
        g28, tau, etr, ekin, trot, trot0 = res
        if nruns > 1:
            path = f"ensemble of {nruns} seeds ({path})"
        tmax = max(tmax, tau[-1])
        dev_tr, slope_tr = deviation(tau, etr)
        dev_kin, slope_kin = deviation(tau, ekin)
        upto = [x for t, x in zip(tau, trot) if t <= 5]
        last = upto[3 * len(upto) // 4:]
        print(f"{path}: xi {xi:g} N {info['N']:.0f}; Gamma0 Eq. 28 {g28:.4g}/s, measured "
              f"{info['Gamma0']:.4g}/s (ratio {info['Gamma0'] / g28:.4f}); tau reached "
              f"{tau[-1]:.3g}; tau <= 5: max |E_tr/E_tr(0) / Haff - 1| {dev_tr:.4f} (alpha*/alpha "
              f"{slope_tr:.4f}), max |E_kin/E_kin(0) / Haff - 1| {dev_kin:.4f} (alpha*/alpha "
              f"{slope_kin:.4f}); T_tr/T_rot at t0 {trot0:.3f}, last quarter {sum(last) / len(last):.3f}")
        lab = f"xi = {xi:g}, N = {info['N']:.0f}" + (f", {nruns} seeds" if nruns > 1 else "")
        ax1.loglog([1 + t for t in tau], etr, ".", ms=3, label=lab + " E_tr")
        ax2.plot(tau, trot, "-", lw=0.8, label=lab)
    x = [1 + 10 ** (k / 50.0) * 1e-3 for k in range(0, 200)]
    x = [v for v in x if v - 1 <= max(tmax, 1e-3)]
    ax1.loglog(x, [1 / v ** 2 for v in x], "k-", label="Haff 1/(1+tau)^2")
    ax1.set_xlabel("1 + tau,  tau = alpha Gamma0(Eq. 28) t,  alpha = (1 - e_n^2)/10")
    ax1.set_ylabel("E_tr(t) / E_tr(0)")
    ax1.legend(fontsize=8)
    ax2.axhline(1.0, color="k", lw=0.5)
    ax2.set_xlabel("tau")
    ax2.set_ylabel("T_tr / T_rot")
    ax2.legend(fontsize=8)
    fig.suptitle("Homogeneous cooling of frictionless prolate ellipsoids, e_n = 0.95, phi = 0.058, "
                 "damping contact")
    fig.tight_layout()
    fig.savefig("hcs.png", dpi=110)


if __name__ == "__main__":
    main()
