#!/usr/bin/env python3
"""Normal and tangential force on the cuboid vs kappa = dx / L_c for the six
walls, against the analytic flat wall: F_n = W'(V) A, V = A delta, A = L_c x
(overlap length), W' = K V^(1/3) (C2 core below V0 = 1e-4 L_c^3), K = 2E/R;
F_t = mu F_n once sliding. Prints the largest deviations, writes force_kappa.png."""
import math
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

L, delta, E, mu, U, dt = 0.025, 1.0e-4, 1.0e6, 0.8, 0.5, 1.0e-5
R = (3 * L**3 / (4 * math.pi)) ** (1 / 3)
K, V0 = 2 * E / R, 1.0e-4 * L**3

def wprime(V):
    if V < V0:
        return K / V0 ** (2 / 3) * V * (5 / 3 - 2 / 3 * V / V0)
    return K * V ** (1 / 3)

def analytic(x):
    A = L * max(0.0, min(x + L / 2, 0.1) - max(x - L / 2, 0.0))
    return wprime(A * delta) * A

meshes = ["wall_lam0.5", "wall_lam1", "wall_lam2", "wall_lam4", "wall_lam8", "wall_irregular"]
Ffull = analytic(0.05)
fig, ax = plt.subplots(2, 1, figsize=(7, 7), sharex=True)
curves = {}
for m in meshes:
    kap, fn, ft = [], [], []
    for line in open("force.%s.stl.txt" % m):
        if line.startswith("#"): continue
        s, fx, fz, nc, ntri = map(float, line.split())
        kap.append(U * dt * s / L)
        fn.append(-fz)
        ft.append(fx)
    x = [-L / 2 + k * L for k in kap]
    en = max(abs(a - analytic(xx)) for a, xx in zip(fn, x)) / Ffull
    # fully on the wall and sliding (1 <= kappa <= 4): F_t = mu F_n
    et = max(abs(b - mu * a) for a, b, k in zip(fn, ft, kap) if 1 <= k <= 4) / (mu * Ffull)
    curves[m] = (fn, ft)
    print("%-15s max |F_n - analytic| = %.2e of F_full; sliding plateau: max |F_t - mu F_n| = %.2e of mu F_full" % (m, en, et))
    ax[0].plot(kap, fn, label=m.replace("wall_", ""))
    ax[1].plot(kap, ft, label=m.replace("wall_", ""))
# spread between the six walls at every sample (entry, stick, edges, exit)
ref = curves[meshes[0]]
sn = max(abs(c[0][i] - ref[0][i]) for c in curves.values() for i in range(len(ref[0]))) / Ffull
st = max(abs(c[1][i] - ref[1][i]) for c in curves.values() for i in range(len(ref[1]))) / (mu * Ffull)
print("spread between the six walls over the whole sweep: F_n %.2e of F_full, F_t %.2e of mu F_full (F_full = %.2f N)" % (sn, st, Ffull))
ka = [i / 500 * 5 for i in range(501)]
ax[0].plot(ka, [analytic(-L / 2 + k * L) for k in ka], "k:", label="analytic")
ax[1].plot(ka, [mu * analytic(-L / 2 + k * L) for k in ka], "k:", label="mu x analytic")
ax[0].set_ylabel("normal force on the cuboid (N)")
ax[1].set_ylabel("tangential force (N)")
ax[1].set_xlabel("kappa = dx / L_c")
ax[0].legend(fontsize=8)
ax[0].set_title("cuboid across flat STL walls, lambda = L_c/L_m 0.5 ... 8")
fig.tight_layout()
fig.savefig("force_kappa.png", dpi=110)
