#!/bin/bash
# ctest example.silo_short: the full case's input (in.silo) and its 150,336-
# triangle mesh with 600 grains (one batch; about a minute on one core),
# in a scratch folder:
#   - 600 grains inserted and kept, no warning (the box is closed and lost
#     atoms are an error, so none may leave the silo);
#   - no vertex more than 2 cm outside the silo's wall or below the lid;
#   - settled: the walls and the lid carry the grains' weight within 5 %
#     (thermo f_silo[3] + f_lid[3] at the end against N m g).
# Usage: test_short.sh LMP
set -euo pipefail
# shellcheck source=SCRIPTDIR/../scratch.sh
. "$(dirname "$0")/../scratch.sh"    # here: this folder; scratch: removed on exit
cd "$scratch"
/usr/bin/python3 "$here/make_silo.py" silo.stl lid.stl
"$1" -in "$here/in.silo" -screen none -log log.short -var pot "$here/../../potentials" -var mesh . \
  -var s 4.0 -var dt 1.5e-4 -var phip 0.25 -var ztop 6.0 \
  -var n 600 -var nb 600 -var tb 0.45 -var tmax 1.0 -var tavg 0.03 -var out short
grep -E '^(BATCH|FED|SETTLED)' log.short
/usr/bin/python3 - "$here" <<'PY'
import sys
import numpy as np
sys.path.insert(0, sys.argv[1])
sys.path.insert(0, sys.argv[1] + "/../../tools")
import make_silo as ms
from packing_grid import hulls
log = open("log.short").read().splitlines()
nwarn = sum(1 for ln in log if ln.startswith("WARNING"))
head = [i for i, ln in enumerate(log) if ln.split()[:2] == ["Step", "Time"]][-1]
cols = log[head].split()
last = None
for ln in log[head + 1:]:
    w = ln.split()
    if len(w) == len(cols) and w[0].isdigit():
        last = dict(zip(cols, map(float, w)))
m = 1500 * 3.5800724335920435e-06 * 4.0 ** 3
H = hulls("short.vtk")
worst = max(float(np.max(np.hypot(P[:, 0], P[:, 1]) - [ms.radius(max(z, 0.0)) for z in P[:, 2]])) for P, _ in H)
zmin = min(P[:, 2].min() for P, _ in H)
carried = -(last["f_silo[3]"] + last["f_lid[3]"]) / (last["Atoms"] * m * 9.81)
checks = [("600 grains kept (%d)" % last["Atoms"], last["Atoms"] == 600 and len(H) == 600),
          ("no warning (%d)" % nwarn, nwarn == 0),
          ("no vertex > 2 cm outside the wall (worst %+.4f m)" % worst, worst < 0.02),
          ("no vertex > 2 cm below the lid (lowest %.4f m)" % zmin, zmin > -0.02),
          ("walls + lid carry the weight within 5 %% (%.4f)" % carried, abs(carried - 1.0) < 0.05)]
for name, ok in checks:
    print(("ok   " if ok else "FAIL ") + name)
sys.exit(0 if all(ok for _, ok in checks) else 1)
PY
