#!/bin/bash
# ctest example.composite_pack_short: in.composite_pack for 400 steps (a few
# seconds) in a scratch folder; checks
#   - the cross's template: volume 7 of the bars' 9, three equal principal
#     moments 5.166666667 (closed form: 5.5 - 2/6), 5 contact parts;
#   - 200 crosses placed, no warning, none lost (thermo_modify lost error).
# Usage: test_short.sh LMP
set -euo pipefail
# shellcheck source=SCRIPTDIR/../scratch.sh
. "$(dirname "$0")/../scratch.sh"    # here: this folder; scratch: removed on exit
cd "$scratch"
short_run "$1" in.composite_pack 400 bar.shape floor.stl
ok=0
grep -q "composite of 3 parts, volume 7 (0.7777777778 of the parts' sum), 5 contact parts" log.short || { echo "FAIL: the cross's volume or contact parts"; ok=1; }
grep -q "principal moments/density 5.166666667 5.166666667 5.166666667" log.short || { echo "FAIL: the cross's moments"; ok=1; }
grep -q "ins: 200 particle(s) inserted" log.short || { echo "FAIL: not 200 crosses placed"; ok=1; }
if grep -q "WARNING" log.short; then echo "FAIL: a warning in the log"; ok=1; fi
grep "composite of 3 parts" log.short
exit $ok
