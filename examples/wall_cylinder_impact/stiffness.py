#!/usr/bin/env python3
"""Deviation of V_z from seed Eq. 28 as the contact stiffens: log.impact (Table 1,
E = 1.15e9 Pa, dt = 5e-7 s) and log.impact_ExF (E x F, dt / sqrt(F)), written by
  lmp -in in.impact -var pot ../../potentials -var E 1.15e10 -var dt 1.58114e-7 \\
      -log log.impact_Ex10 -screen none            (and F = 100, 1000)
Eqs. 27-28 are the rigid limit (contact point C fixed); the model's contact has a
finite size, which shrinks as E grows. Prints the table of README.md and the
fitted exponent of |dV_z| against E."""
import math

from eq2728 import V, analytic, results

runs = [(1, results("log.impact"))] + [(f, results("log.impact_Ex%d" % f)) for f in (10, 100, 1000)]
print("theta   Eq.28    " + "".join("  dVz/|Vz| E x%-5d" % f for f, _ in runs) + "  dVz/V E x1  E x1000")
slopes = []
for th in sorted(runs[0][1]):
    wa, va = analytic(math.radians(th))
    d = [r[th][1] - va for _, r in runs]
    print("%5.0f  %+.5f" % (th, va) + "".join("  %+15.2f%%" % (100 * x / abs(va)) for x in d) +
          "  %+8.2f%%  %+6.2f%%" % (100 * d[0] / V, 100 * d[-1] / V))
    if abs(d[0]) > 1e-4:
        slopes.append(math.log(abs(d[-1]) / abs(d[0])) / math.log(1000.0))
print("|dV_z| ~ E^p, p from E x1 to x1000 where |dV_z| > 1e-4 m/s: %.3f to %.3f" % (min(slopes), max(slopes)))
