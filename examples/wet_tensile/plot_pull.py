"""Wet tensile test: the tensile stress against the strain of each run
(pull_SEED.txt and log.pull_SEED: uniaxial; iso_SEED.txt: isotropic), its
peak (the tensile strength) against Rumpf's relation with the counted
contacts per sphere, phi Z F0 / (pi d^2), and with Rumpf's own coordination
Z = pi / eps, (1 - eps)/eps F0 / d^2. Prints the table of the README and
draws pull.png.
    /usr/bin/python3 plot_pull.py [SEED ...]      (default: 4321 1234)
"""
import re
import sys

import numpy as np


def fields(log, tag):
    """the name/value pairs of the line starting with tag in a LAMMPS log"""
    for line in open(log):
        if line.startswith(tag + " "):
            w = line.split()[1:]
            return {w[k]: float(w[k + 1]) for k in range(0, len(w) - 1, 2)}
    raise SystemExit(f"{log}: no line {tag}")


def run(seed):
    d = np.loadtxt(f"pull_{seed}.txt")
    log = f"log.pull_{seed}"
    b, r = fields(log, "BRIDGE_STRESS"), fields(log, "RELAXED")
    k = int(np.argmax(d[:, 1]))
    q = dict(seed=seed, strain=d[:, 0], sigma=d[:, 1], peak=d[k, 1], at=d[k, 0], rest=b,
             relaxed=r, iso=None)
    try:
        i = np.loadtxt(f"iso_{seed}.txt")
        q["iso"] = (i[:, 0], i[:, 1], i[:, 1].max(), i[int(np.argmax(i[:, 1])), 0])
    except OSError:
        pass
    return q


def main():
    seeds = sys.argv[1:] or ["4321", "1234"]
    runs = [run(s) for s in seeds]
    print("| packing | at rest: phi, Z | bridge stress | phi Z F0/(pi d^2) | relaxed: phi, Z, "
          "phi Z F0/(pi d^2) | uniaxial strength (strain) | isotropic strength (strain) "
          "| strengths / phi Z F0/(pi d^2) | strengths / (1-eps)/eps F0/d^2 |")
    print("|---|---|---|---|---|---|---|---|---|")
    for q in runs:
        b, r = q["rest"], q["relaxed"]
        iso = q["iso"]
        ip = iso[2] if iso else float("nan")
        its = f"{iso[2]:.1f} Pa ({iso[3]:.2%})" if iso else "-"
        print(f"| {q['seed']} | {b['phi']:.4f}, {b['Z']:.2f} | {b['sigma_b']:.2f} Pa "
              f"| {b['rumpf_Z']:.2f} Pa ({b['sigma_b'] / b['rumpf_Z'] - 1:+.2%}) "
              f"| {r['phi']:.4f}, {r['Z']:.2f}, {r['rumpf_Z']:.1f} Pa "
              f"| {q['peak']:.1f} Pa ({q['at']:.2%}) | {its} "
              f"| {q['peak'] / r['rumpf_Z']:.2f}, {ip / r['rumpf_Z']:.2f} "
              f"| {q['peak'] / r['rumpf_eps']:.2f}, {ip / r['rumpf_eps']:.2f} |")
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    for q, c in zip(runs, ["C0", "C1", "C2", "C3"]):
        ax.plot(100 * q["strain"], q["sigma"], color=c, label=f"packing {q['seed']}, uniaxial")
        if q["iso"]:
            ax.plot(100 * q["iso"][0], q["iso"][1], color=c, ls="-.", lw=1,
                    label=f"packing {q['seed']}, isotropic")
        r = q["relaxed"]
        ax.axhline(r["rumpf_Z"], color=c, ls="--", lw=0.8)
        ax.plot(100 * q["at"], q["peak"], "o", color=c)
    r = runs[0]["relaxed"]
    ax.axhline(r["rumpf_eps"], color="k", ls=":", lw=0.8)
    ax.text(0.1, r["rumpf_eps"] * 0.95, r"Rumpf, $Z = \pi/\varepsilon$: $(1-\varepsilon)/\varepsilon\,F_0/d^2$",
            va="top", fontsize=8)
    ax.text(0.1, r["rumpf_Z"] * 1.03, r"Rumpf with the counted $Z$: $\phi Z F_0/(\pi d^2)$",
            va="bottom", fontsize=8)
    ax.set_xlabel("tensile strain along z [%]")
    ax.set_ylabel(r"tension $-\sigma_{zz}$ (uniaxial), $-p$ (isotropic) [Pa]")
    ax.set_ylim(bottom=min(0.0, min(q["sigma"].min() for q in runs)), top=1.15 * r["rumpf_eps"])
    ax.set_title("Wet packings of equal spheres pulled apart", fontsize=10)
    ax.legend(loc="center right", fontsize=8)
    fig.tight_layout()
    fig.savefig("pull.png", dpi=110)


if __name__ == "__main__":
    main()
