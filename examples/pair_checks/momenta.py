#!/usr/bin/env python3
"""momenta.py log.gas1000 [plot.png]: drift of the total linear momentum
(relative to sum m|v| at step 0) and of the total angular momentum about the
centre of mass (relative to sum m|v| times the cluster size R at step 0)
in the thermo output of in.gas1000; plots both against the step."""
import sys
import numpy as np

rows, head, inside = [], None, False
for line in open(sys.argv[1]):
    p = line.split()
    if p[:2] == ["Step", "Atoms"]:
        head, inside = p, True
        continue
    if inside and len(p) == len(head):
        try:
            rows.append([float(x) for x in p])
        except ValueError:
            inside = False
d = np.array(rows)
c = {k: i for i, k in enumerate(head)}
P = d[:, [c["v_px"], c["v_py"], c["v_pz"]]]
L = d[:, [c["v_Lx"], c["v_Ly"], c["v_Lz"]]]
s0, R0 = d[0, c["c_scale"]], d[0, c["v_R"]]
dP = np.abs(P - P[0]).max(axis=1) / s0
dL = np.abs(L - L[0]).max(axis=1) / (s0 * R0)
print(f"{int(d[-1, 0])} steps, atoms {int(d[0, c['Atoms']])} -> {int(d[-1, c['Atoms']])}, "
      f"contacts at the end {int(d[-1, c['c_cs[1]']])}: max linear-momentum drift {dP.max():.3g}, "
      f"max angular-momentum drift {dL.max():.3g} (relative)")
if len(sys.argv) > 2:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6, 3.5))
    ax.semilogy(d[1:, 0], dP[1:] + 1e-18, "o-", label="linear momentum")
    ax.semilogy(d[1:, 0], dL[1:] + 1e-18, "s-", label="angular momentum")
    ax.set_xlabel("step")
    ax.set_ylabel("relative drift")
    ax.set_title("1,000-particle mixed-shape gas, damping + friction")
    ax.legend()
    fig.tight_layout()
    fig.savefig(sys.argv[2], dpi=110)
