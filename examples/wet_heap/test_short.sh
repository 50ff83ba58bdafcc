#!/bin/bash
# ctest example.wet_heap_short: in.heap with a shorter column (273 spheres,
# 34 mm) for Bo = 0 and Bo = 3 side by side (about two minutes); the wet heap
# must stand at least 1.5 times as steep as the dry one (the full case: 10
# and 36 degrees), none lost (LAMMPS stops on a lost atom), and no warning
# but the lifted tube's (a new fix that finds the spheres pressing on it).
# Usage: test_short.sh LMP
set -euo pipefail
# shellcheck source=SCRIPTDIR/../scratch.sh
. "$(dirname "$0")/../scratch.sh"    # here: this folder; scratch: removed on exit
cd "$scratch"
cp "$here/in.heap" "$here/analyze.py" "$here/floor.stl" "$here/tube.stl" .
for bo in 0 3; do
  "$1" -in in.heap -screen none -log log.$bo -var bo $bo -var top 0.036 -var lift 90000 \
       -var rest 30000 &
done
wait
ok=0
for bo in 0 3; do
  grep -q "^Total wall time" log.$bo || { echo "FAIL: Bo = $bo did not finish"; ok=1; }
  # the lifted tube is a new fix: the spheres pressing on it start without history (warned)
  if grep "WARNING" log.$bo | grep -qv "overlap the mesh at the start of the run"; then
    echo "FAIL: a warning in the log of Bo = $bo"; ok=1
  fi
done
/usr/bin/python3 - <<'PY' || ok=1
from analyze import angle, load, surface
th = {}
for bo in ("0", "3"):
    r, h, rr, top = surface(load(f"heap_{bo}.txt"))
    th[bo] = angle(r, h)[0]
print(f"angle of repose: dry {th['0']:.1f} deg, Bo = 3 {th['3']:.1f} deg")
assert th["3"] > 1.5 * th["0"], "FAIL: the wet heap is not steeper"
PY
exit $ok
