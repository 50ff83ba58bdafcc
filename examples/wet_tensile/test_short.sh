#!/bin/bash
# ctest example.wet_tensile_short: in.pack with 125 spheres, then in.pull to
# a strain of 1.5 % (about a minute and a half). Checks: the stress the
# bridges add at rest is Rumpf's phi Z F0 / (pi d^2) with the counted
# contacts within 1 % (the branch vectors are d less the overlaps, a few
# 1e-4 of d); the relaxed packing is at zero mean stress within 2 % of it;
# the tensile strength is 0.3-0.7 of it (the full case: 0.46-0.47).
# Usage: test_short.sh LMP
set -euo pipefail
# shellcheck source=SCRIPTDIR/../scratch.sh
. "$(dirname "$0")/../scratch.sh"    # here: this folder; scratch: removed on exit
cd "$scratch"
"$1" -in "$here/in.pack" -var n 5 -var out packed.restart -screen none -log log.pack
"$1" -in "$here/in.pull" -var strain 0.015 -screen none -log log.pull
if grep -q "WARNING" log.pack log.pull; then echo "FAIL: a warning"; grep WARNING log.pack log.pull; exit 1; fi
/usr/bin/python3 - <<'PY'
import numpy as np
def fields(tag):
    for line in open("log.pull"):
        if line.startswith(tag + " "):
            w = line.split()[1:]
            return {w[k]: float(w[k + 1]) for k in range(0, len(w) - 1, 2)}
b, r = fields("BRIDGE_STRESS"), fields("RELAXED")
peak = np.loadtxt("pull.txt")[:, 1].max()
print(f"bridge stress {b['sigma_b']:.4g} Pa, phi Z F0/(pi d^2) {b['rumpf_Z']:.4g} Pa "
      f"(phi {b['phi']:.4f}, Z {b['Z']:.3f}); relaxed p {r['p']:.3g} Pa; tensile strength "
      f"{peak:.4g} Pa = {peak / r['rumpf_Z']:.3f} of the relaxed packing's phi Z F0/(pi d^2)")
assert abs(b["sigma_b"] / b["rumpf_Z"] - 1) < 0.01, "FAIL: bridge stress"
assert abs(r["p"]) < 0.02 * r["rumpf_Z"], "FAIL: not relaxed"
assert 0.3 < peak / r["rumpf_Z"] < 0.7, "FAIL: tensile strength"
PY
