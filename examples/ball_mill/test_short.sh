#!/bin/bash
# ctest example.ball_mill_short: in.ball_mill for 2 revolutions (about 12 s
# on one core) in a scratch folder; checks
#   - 34 grains kept (lost atoms are an error), no kernel warning;
#   - the second revolution's torque balance (mill_balance.py: the mean
#     torque on the drum = M g x_cm - dL/T_rev) closes within 1e-4 (full run:
#     at most 1.3e-5);
#   - the power draw is within 50-100 mW (full run: 68-77 mW);
# then in.bond -var ore 1 (the 3-D mill with ore) for 5,000 steps (the ore
# falling into the ball charge, about 5 s): 324 balls and 336 ore grains, no
# warning (its time step is below the flat-face stability limit), none lost.
# Usage: test_short.sh LMP
set -euo pipefail
# shellcheck source=SCRIPTDIR/../scratch.sh
. "$(dirname "$0")/../scratch.sh"    # here: this folder; scratch: removed on exit
cd "$scratch"
cp "$here/drum.stl" .
sed 's/^dump /# dump /' "$here/in.ball_mill" > in.short
"$1" -in in.short -screen none -log log.short -var pot "$here/../../potentials" -var nrev 2
/usr/bin/python3 - "$here" <<'PY'
import sys
sys.path.insert(0, sys.argv[1])
from mill_balance import mill_balance
log = open("log.short").read()
torque, arm, dl, power = mill_balance("log.short", "mill_rev.txt")[-1]
bal = (torque - (arm - dl)) / torque
print(f"revolution 2: torque {torque:.6g} N m, M g x_cm {arm:.6g}, dL/T {dl:.6g}, "
      f"balance {bal:.2e}, power {power:.4g} W")
ok = True
if "WARNING" in log:
    print("FAIL: a warning in the log"); ok = False
if abs(bal) > 1e-4:
    print("FAIL: the torque balance is off by more than 1e-4"); ok = False
if not 0.05 < power < 0.10:
    print("FAIL: power draw outside 50-100 mW"); ok = False
sys.exit(0 if ok else 1)
PY
cp "$here/drum_3d.stl" .
sed 's/^dump /# dump /' "$here/in.bond" > in.bond_short
"$1" -in in.bond_short -screen none -log log.bond_short -var pot "$here/../../potentials" \
  -var ore 1 -var nrev 0.05
status=0
grep -q "Created 324 atoms" log.bond_short || { echo "FAIL: not 324 balls"; status=1; }
grep -q "Created 336 atoms" log.bond_short || { echo "FAIL: not 336 ore grains"; status=1; }
grep -q "Loop time of .* for 5000 steps with 660 atoms" log.bond_short ||
  { echo "FAIL: the run did not end with 660 grains after 5000 steps"; status=1; }
! grep "WARNING" log.bond_short || { echo "FAIL: a warning in the 3-D mill's log"; status=1; }
exit $status
