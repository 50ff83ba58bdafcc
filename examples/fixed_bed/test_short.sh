#!/bin/bash
# ctest example.fixed_bed_short: a short bed of the full case's input (100
# pellets of the 24-gon, seed 1; about 70 s on one core) in a scratch folder,
# checked against the 5-seed ensemble of short beds in results/short_n100.txt
# (README):
#   - 100 pellets inserted and kept, no warning, settled by the criterion;
#   - no vertex more than 0.5 mm below the floor or into the wall;
#   - the analysis' volume equals the pellets' volume within 1e-3;
#   - bulk porosity eps_b and highest vertex H_top within 3 sample standard
#     deviations of the ensemble means (tolerances below).
# Usage: test_short.sh LMP
set -euo pipefail
# shellcheck source=SCRIPTDIR/../scratch.sh
. "$(dirname "$0")/../scratch.sh"    # here: this folder; scratch: removed on exit
line=$("$here/run_case.sh" "$1" "$scratch" catalyst_cylinder 1 1 -var n 100 -var tsettle 0.6)
echo "$line"
/usr/bin/python3 - "$line" <<'PY'
import sys
kv = dict(w.split("=", 1) for w in sys.argv[1].split() if "=" in w)
f = {k: float(v) for k, v in kv.items() if k not in ("tag", "shape")}
# results/short_n100.txt, 5 seeds: mean and 3 sample sd
EPS_B, EPS_TOL = 0.5178, 3 * 0.0135
H_TOP, H_TOL = 0.05924, 3 * 0.00101
checks = [
    ("100 pellets", f["n"] == 100),
    ("no warning", f["warnings"] == 0),
    ("settled by the criterion (t = %.3f s < 0.9 s)" % f["t_settle"], 0 < f["t_settle"] < 0.9 - 1e-6),
    ("lowest vertex > -0.5 mm", f["zmin"] > -0.0005),
    ("largest vertex radius < 12.9 mm", f["rmax"] < 0.0129),
    ("volume of the sections = N V_p within 1e-3", abs(f["V"] / f["V_expected"] - 1) < 1e-3),
    ("eps_b = %.4f within %.4f +- %.4f" % (f["eps_b"], EPS_B, EPS_TOL), abs(f["eps_b"] - EPS_B) <= EPS_TOL),
    ("H_top = %.4f m within %.4f +- %.4f" % (f["H_top"], H_TOP, H_TOL), abs(f["H_top"] - H_TOP) <= H_TOL),
]
for name, ok in checks:
    print(("ok   " if ok else "FAIL ") + name)
sys.exit(0 if all(ok for _, ok in checks) else 1)
PY
