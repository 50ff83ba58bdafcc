#!/bin/bash
# ctest example.mixed_shapes_short: the full case of in.mixed (120 grains of
# four kinds settled in the cylinder; about 40 s on one core) in a scratch
# folder, checked for what the example shows (README):
#   - all 120 grains inserted and kept, no warning, settled before tmax;
#   - every one of the 10 kind pairs in contact somewhere in the bed (the
#     sphere-ellipsoid and ellipsoid-ellipsoid pairs by the algebraic
#     contact, the others by overlap volume);
#   - no vertex more than 2 mm below the floor or outside r = 5.2 cm;
#   - a coordination number (grain contacts per grain) between 3 and 6.
# Usage: test_short.sh LMP
set -euo pipefail
lmp=$(realpath "$1")
# shellcheck source=SCRIPTDIR/../scratch.sh
. "$(dirname "$0")/../scratch.sh"    # here: this folder; scratch: removed on exit
cd "$scratch"
"$lmp" -in "$here/in.mixed" -var pot "$here/../../potentials" -var mesh "$here/../dodeca_packing" \
    -var out "$scratch/mixed" -log "$scratch/log" > "$scratch/screen" 2>&1
grep -E "^SETTLED" "$scratch/screen"
/usr/bin/python3 - "$scratch" "$here" <<'PY'
import itertools
import sys

import numpy as np

scratch, here = sys.argv[1], sys.argv[2]
sys.path.insert(0, here)
sys.path.insert(0, here + "/../../tools")
from count import read_dump  # noqa: E402
from render_vtk import read_vtk  # noqa: E402

screen = open(scratch + "/screen").read()
settled = [l for l in screen.splitlines() if l.startswith("SETTLED")]
kv = settled[0].split() if settled else []
t_settle = float(kv[kv.index("time") + 1]) if settled else -1.0
_, srows = read_dump(scratch + "/mixed.shapes")
kind = {int(r[0]): int(float(r[1])) - 1 for r in srows}
_, crows = read_dump(scratch + "/mixed.contacts")
pairs = {tuple(sorted((kind[int(float(r[0]))], kind[int(float(r[1]))]))) for r in crows}
missing = [p for p in itertools.combinations_with_replacement(range(4), 2) if p not in pairs]
pts, _, _ = read_vtk(scratch + "/mixed.vtk")
zmin = pts[:, 2].min()
rmax = np.hypot(pts[:, 0], pts[:, 1]).max()
z = 2.0 * len(crows) / len(kind)
checks = [
    ("120 grains", len(kind) == 120),
    ("no warning", "WARNING" not in screen),
    ("settled at %.2f s before tmax = 3 s" % t_settle, 0 < t_settle < 3.0),
    ("every kind pair in contact (missing %s)" % missing, not missing),
    ("lowest vertex %.4f m > -2 mm" % zmin, zmin > -0.002),
    ("largest vertex radius %.4f m < 5.2 cm" % rmax, rmax < 0.052),
    ("coordination %.2f in [3, 6]" % z, 3.0 <= z <= 6.0),
]
for name, ok in checks:
    print(("ok   " if ok else "FAIL ") + name)
sys.exit(0 if all(ok for _, ok in checks) else 1)
PY
