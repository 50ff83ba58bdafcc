#!/bin/bash
# ctest example.ring_pack_short: in.ring_pack for 400 steps (a few seconds)
# in a scratch folder; checks
#   - the ring's template from ring.stl (12-gons of the circles' areas, outer
#     diameter = length = 1, wall 1/8, scale 0.008), against the closed forms:
#     12 convex pieces; volume pi/4 (1 - 0.75^2) s^3 = 1.759291886e-07;
#     bounding radius s sqrt(rho_o^2 + 1/4) = 0.005723212456 with
#     rho_o = sqrt(pi/3)/2; principal moments per density
#     s^5 (J/2 + A/12) and s^5 J, J = 12 (rho_o^4 - rho_i^4) sin 30 (2 + cos 30)/12,
#     A = pi/4 (1 - 0.75^2): 2.038320998e-12 (twice) and 2.200063984e-12;
#   - 250 rings placed, no warning, none lost (thermo_modify lost error).
# Usage: test_short.sh LMP
set -euo pipefail
# shellcheck source=SCRIPTDIR/../scratch.sh
. "$(dirname "$0")/../scratch.sh"    # here: this folder; scratch: removed on exit
cd "$scratch"
short_run "$1" in.ring_pack 400 ring.stl floor.stl
status=0
for want in "composite of 12 parts (convex decomposition of ring.stl), volume 1.75929188[5-7]e-07 (1 of the parts' sum), 12 contact parts" \
            "bounding radius 0.00572321245[5-7]" \
            "principal moments/density 2.03832099[7-9]e-12 2.03832099[7-9]e-12 2.20006398[3-5]e-12" \
            "ins: 250 particle(s) inserted"; do
  grep -q "$want" log.short || { echo "FAIL: not in the log: $want"; status=1; }
done
! grep "WARNING" log.short || { echo "FAIL: a warning in the log"; status=1; }
exit $status
