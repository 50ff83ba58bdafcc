#!/bin/bash
# The runs of README.md: xi = 2 and 3 with N = 4096
# (about 60-70 CPU minutes each here; three seeds each), xi = 1.15 with N = 512 and a long warm-up
# (rotation of a nearly spherical body equilibrates slowly), one after the
# other on one core; then the plot. Usage: run_hcs.sh [LMP]
set -e
LMP=${1:-../../build/lmp}
$LMP -in in.hcs -var xi 2.0 -var nside 16 -var cool 1950000 -log log.hcs_xi2.0_N4096 -screen none -nocite
$LMP -in in.hcs -var xi 3.0 -var nside 16 -var cool 1450000 -log log.hcs_xi3.0_N4096 -screen none -nocite
$LMP -in in.hcs -var xi 1.15 -var nside 8 -var warm 200000 -var cool 2200000 -log log.hcs_xi1.15_N512 -screen none -nocite
# more seeds of xi = 2 and 3 (averaged by plot_hcs.py into ensembles)
for seed in 7151 31337; do
  $LMP -in in.hcs -var xi 2.0 -var nside 16 -var cool 1950000 -var seed $seed -log log.hcs_xi2.0_N4096_s$seed -screen none -nocite
  $LMP -in in.hcs -var xi 3.0 -var nside 16 -var cool 1450000 -var seed $seed -log log.hcs_xi3.0_N4096_s$seed -screen none -nocite
done
/usr/bin/python3 plot_hcs.py log.hcs_xi1.15_N512 log.hcs_xi2.0_N4096* log.hcs_xi3.0_N4096*
