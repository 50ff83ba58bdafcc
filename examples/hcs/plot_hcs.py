#!/usr/bin/python3
"""Plot and check the homogeneous cooling runs of in.hcs (log.hcs_xi*_N*).

E_tr(t)/E_tr(0) against tau = alpha Gamma0 t, alpha = (1 - e_n^2)/(2 D), D = 5, with
Gamma0 from the seed's Eq. 28 (eq28.py: Song-Mason g_c, S_c <D>_c from kinetic theory,
T(0) = (2/3) E_tr(0)/N), compared with Haff's law 1/(1+tau)^2 (seed Eq. 27). E_tr(0) is the
mean translational energy over the second half of the elastic measurement window when the
log has it ("E_tr(mean)"), else the instantaneous value at the start of cooling.
Prints, per run: Gamma0 of Eq. 28 against the measured collision rate, the largest relative
deviation from Haff's law for tau <= 5, the fitted alpha*/alpha, and T_tr/T_rot.
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
_SCDC = {}


def sc_dc(xi):
    if xi not in _SCDC:
        _SCDC[xi] = eq28.sc_dc(xi)[1]
    return _SCDC[xi]


def read(path):
    info, rows, cooling = {}, [], False
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
            if cooling and len(w) in (10, 12) and w[0].isdigit():
                rows.append([float(x) for x in w])
            elif cooling and w[:2] == ["Loop", "time"]:
                cooling = False
    return info, rows


def analyse(info, rows):
    xi, n_atoms, b, m = info["xi"], info["N"], info["b"], info["m"]
    box = info.get("L", round(n_atoms ** (1 / 3)) / 8.0)
    eta = n_atoms * 4.0 / 3.0 * math.pi * xi * b ** 3 / box ** 3
    e0 = info.get("E_tr(mean)", info["E_tr(0)"])
    t0 = 2.0 / 3.0 * e0 / n_atoms
    g28 = eq28.gamma0(xi, b, m, n_atoms / box ** 3, t0, eta, sc_dc(xi))
    tau = [ALPHA * g28 * (r[1] - info["t0"]) for r in rows]
    ratio = [r[6] / e0 for r in rows]
    return g28, tau, ratio


def main():
    files = sys.argv[1:] or sorted(glob.glob("log.hcs_xi*"))
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.2))
    tmax = 0.0
    for path in files:
        info, rows = read(path)
        if not rows:
            continue
        xi = info["xi"]
        g28, tau, ratio = analyse(info, rows)
        trot = [r[5] for r in rows]
        tmax = max(tmax, tau[-1])
        upto5 = [(t, r) for t, r in zip(tau, ratio) if t <= 5]
        dev = max(abs(r * (1 + t) ** 2 - 1) for t, r in upto5)
        late = [(t, r) for t, r in upto5 if t >= 0.2]
        dev2 = max(abs(r * (1 + t) ** 2 - 1) for t, r in late)
        # least-squares slope of (E/E0)^(-1/2) - 1 against tau: alpha*/alpha
        slope = sum(t * (r ** -0.5 - 1) for t, r in late) / sum(t * t for t, r in late)
        last = [x for t, x in zip(tau, trot) if t >= 0.75 * min(tau[-1], 5)]
        print(f"{path}: xi {xi:g} N {info['N']:.0f}; Gamma0 Eq. 28 {g28:.4g}/s, measured "
              f"{info['Gamma0']:.4g}/s (ratio {info['Gamma0'] / g28:.4f}); tau reached "
              f"{tau[-1]:.3g}; max |E_tr/E_tr(0) / Haff - 1| for tau <= 5: {dev:.3g} "
              f"(tau >= 0.2: {dev2:.3g}); fitted alpha*/alpha {slope:.4f}; T_tr/T_rot "
              f"{sum(last) / len(last):.3f} (last quarter up to tau 5)")
        ax1.loglog([1 + t for t in tau], ratio, ".", ms=3,
                   label=f"xi = {xi:g}, N = {info['N']:.0f}")
        ax2.plot(tau, trot, "-", lw=0.8, label=f"xi = {xi:g}, N = {info['N']:.0f}")
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
