#!/bin/bash
# ctest example.dodeca_packing_short: one packing of the full case (63
# dodecahedra, d = 3.0 cm, seed 1, mu 0.8, dt 2.5e-5 s; about 15 s on one
# core) in a scratch folder, checked against the 3.0 cm ensemble of
# results/size_scan.txt (README):
#   - all 63 particles inserted and kept, no warning, settled before tmax;
#   - no vertex more than 2 mm below the floor or outside r = 5.2 cm;
#   - bulk packing fraction phi_b and fill height H_half within 3 sample
#     standard deviations of the ensemble means (tolerances below).
# Usage: test_short.sh LMP
set -euo pipefail
# shellcheck source=SCRIPTDIR/../scratch.sh
. "$(dirname "$0")/../scratch.sh"    # here: this folder; scratch: removed on exit
line=$("$here/run_case.sh" "$1" "$scratch" 0.030 1)
echo "$line"
/usr/bin/python3 - "$line" <<'PY'
import sys
kv = dict(w.split("=", 1) for w in sys.argv[1].split() if "=" in w)
f = {k: float(v) for k, v in kv.items()}
# 3.0 cm ensemble (results/size_scan.txt): mean and 3 sample sd
PHI_B, PHI_TOL = 0.4588, 3 * 0.0221
H_HALF, H_TOL = 0.1671, 3 * 0.0066
checks = [
    ("63 particles", f["n"] == 63),
    ("no warning", f["warnings"] == 0),
    ("settled before tmax = 4 s", 0 < f["t_settle"] < 4.0),
    ("lowest vertex > -2 mm", f["zmin"] > -0.002),
    ("largest vertex radius < 5.2 cm", f["rmax"] < 0.052),
    ("phi_b = %.4f within %.4f +- %.4f" % (f["phi_b"], PHI_B, PHI_TOL), abs(f["phi_b"] - PHI_B) <= PHI_TOL),
    ("H_half = %.4f m within %.4f +- %.4f" % (f["H_half"], H_HALF, H_TOL), abs(f["H_half"] - H_HALF) <= H_TOL),
]
bad = [name for name, ok in checks if not ok]
for name, ok in checks:
    print(("ok   " if ok else "FAIL ") + name)
sys.exit(1 if bad else 0)
PY
