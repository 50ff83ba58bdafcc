#!/usr/bin/python3
"""Plot and check the homogeneous cooling runs of in.hcs (log.hcs_xi*_N*).

E_tr(t)/E_tr(0) against tau = alpha Gamma0 t, alpha = (1 - e_n^2)/(2 D), D = 5,
Gamma0 = measured collision rate per particle in the elastic phase (see README),
compared with Haff's law 1/(1+tau)^2 (seed Eq. 27) and with the seed's effective
form 1/(1+tau*)^2, tau* = sqrt(3/2) tau (seed section 4.2, Fig. 9 caption).
Prints, per run, the largest relative deviation from each form up to tau = 5 (or
the largest tau reached) and the mean T_tr/T_rot over the last quarter of the run.
Usage: plot_hcs.py [log files...]  (default: all log.hcs_xi*); writes hcs.png
"""
import glob
import math
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt


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
            if cooling and len(w) == 10 and w[0].isdigit():
                rows.append([float(x) for x in w])
            elif cooling and w[:2] == ["Loop", "time"]:
                cooling = False
    return info, rows


def main():
    files = sys.argv[1:] or sorted(glob.glob("log.hcs_xi*"))
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.2))
    tmax = 0.0
    for path in files:
        info, rows = read(path)
        if not rows:
            continue
        xi = info.get("xi", float("nan"))
        tau = [r[2] for r in rows]
        ratio = [r[3] for r in rows]
        trot = [r[5] for r in rows]
        tmax = max(tmax, tau[-1])
        dev = max(abs(r * (1 + t) ** 2 - 1) for t, r in zip(tau, ratio) if t <= 5)
        s = math.sqrt(1.5)
        dev_s = max(abs(r * (1 + s * t) ** 2 - 1) for t, r in zip(tau, ratio) if t <= 5)
        # after the first collisions of the dissipative phase (tau >= 0.2): the
        # instantaneous E_tr(0) of N = 512 carries a few % of equipartition noise
        late = [(t, r) for t, r in zip(tau, ratio) if 0.2 <= t <= 5]
        dev2 = max(abs(r * (1 + t) ** 2 - 1) for t, r in late)
        dev2_s = max(abs(r * (1 + s * t) ** 2 - 1) for t, r in late)
        # least-squares slope of (E/E0)^(-1/2) - 1 against tau: alpha*/alpha
        slope = sum(t * (r ** -0.5 - 1) for t, r in late) / sum(t * t for t, r in late)
        last = [x for t, x in zip(tau, trot) if t >= 0.75 * tau[-1]]
        print(f"{path}: xi {xi:g} N {info.get('N', 0):.0f} Gamma0 {info.get('Gamma0', 0):.4g}/s "
              f"tau reached {tau[-1]:.3g}; max |E/E0 / Haff - 1| {dev:.3g} (tau), "
              f"{dev_s:.3g} (tau* = sqrt(3/2) tau); for tau >= 0.2: {dev2:.3g}, {dev2_s:.3g}; "
              f"fitted alpha*/alpha {slope:.4f} (sqrt(3/2) = 1.2247); T_tr/T_rot over the last quarter "
              f"{sum(last) / len(last):.3f}")
        ax1.loglog([1 + t for t in tau], ratio, ".", ms=3, label=f"xi = {xi:g}, N = {info.get('N', 0):.0f}")
        ax2.plot(tau, trot, "-", label=f"xi = {xi:g}, N = {info.get('N', 0):.0f}")
    x = [1 + 10 ** (k / 50.0) * 1e-3 for k in range(0, 200)]
    x = [v for v in x if v - 1 <= max(tmax, 1e-3)]
    ax1.loglog(x, [1 / v ** 2 for v in x], "k-", label="Haff 1/(1+tau)^2")
    ax1.loglog(x, [1 / (1 + math.sqrt(1.5) * (v - 1)) ** 2 for v in x], "k--",
               label="1/(1+sqrt(3/2) tau)^2")
    ax1.set_xlabel("1 + tau,  tau = alpha Gamma0 t")
    ax1.set_ylabel("E_tr(t) / E_tr(0)")
    ax1.legend(fontsize=8)
    ax2.axhline(1.0, color="k", lw=0.5)
    ax2.set_xlabel("tau")
    ax2.set_ylabel("T_tr / T_rot")
    ax2.legend(fontsize=8)
    fig.suptitle("Homogeneous cooling of frictionless prolate ellipsoids, e_n = 0.95, phi = 0.058")
    fig.tight_layout()
    fig.savefig("hcs.png", dpi=110)


if __name__ == "__main__":
    main()
