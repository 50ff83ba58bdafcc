#!/bin/bash
# ctest example.ball_mill_short: in.ball_mill for 2 revolutions (about 12 s
# on one core) in a scratch folder; checks
#   - 34 grains kept (lost atoms are an error), no kernel warning;
#   - the second revolution's mean torque of the charge on the drum equals
#     the torque arm M g x_cm within 3 % (full run, revolutions 2-5: 0.06-1.3 %);
#   - the power draw is positive and within 50-100 mW (full run: 75-78 mW).
# Usage: test_short.sh LMP
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
cd "$scratch"
cp "$here/drum.stl" .
sed 's/^dump /# dump /' "$here/in.ball_mill" > in.short
"$1" -in in.short -screen none -log log.short -var pot "$here/../../potentials" -var nrev 2
/usr/bin/python3 - <<'PY'
import sys
log = open("log.short").read()
rows = [l.split() for l in open("mill_rev.txt") if not l.startswith("#")]
torque, arm, power = (float(x) for x in rows[-1][1:4])
print(f"revolution 2: torque {torque:.5g} N m, M g x_cm {arm:.5g} N m, power {power:.4g} W")
ok = True
if "WARNING" in log:
    print("FAIL: a warning in the log"); ok = False
if abs(torque / arm - 1) > 0.03:
    print("FAIL: torque and torque arm differ by more than 3 %"); ok = False
if not 0.05 < power < 0.10:
    print("FAIL: power draw outside 50-100 mW"); ok = False
sys.exit(0 if ok else 1)
PY
