#!/bin/bash
# Runs the three elongations of the seed (xi = 1.15, 2, 3) one after the other
# on one core; N = nside^3 (default 8: N = 512). Usage: run_hcs.sh LMP [nside]
LMP=${1:-../../build/lmp}
NSIDE=${2:-8}
for xi in 2.0 3.0 1.15; do
  $LMP -in in.hcs -var xi $xi -var nside $NSIDE -log log.hcs_xi${xi}_N$((NSIDE**3)) -screen none -nocite
done
