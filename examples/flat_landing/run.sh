#!/bin/bash
# Rebound of a cube landing flat on a wall against the time step (README.md).
#   bash run.sh [path/to/lmp]
set -euo pipefail
lmp=$(realpath "${1:-../../build/lmp}")
cd "$(dirname "$0")"
for dt in 1e-5 5e-6 4.5e-6 4e-6 3.6e-6 3e-6 2e-6 1e-6 5e-7 2e-7 1e-7; do
  "$lmp" -in in.flat -var pot ../../potentials -var dt $dt -log log.$dt -screen none
  grep '^RESULT' log.$dt
done
grep -h "stable for" log.1e-7
