#!/bin/bash
# ensemble.sh LMP RESULTS RUNDIR "D1 D2 ..." "SEED1 SEED2 ..." [MU] [DT] [extra lmp -var pairs]
# Runs run_case.sh for every size and seed, one at a time (1 MPI rank), and
# appends its line to RESULTS; a (d, seed, mu, dt) already in RESULTS is skipped.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
lmp=$1 results=$2 rundir=$3 sizes=$4 seeds=$5 mu=${6:-0.8} dt=${7:-auto}
shift 5; shift $(( $# < 2 ? $# : 2 ))
touch "$results"
for d in $sizes; do
  for s in $seeds; do
    dtd=$dt
    if [ "$dt" = auto ]; then dtd=$(awk "BEGIN{x=$d/0.030; printf \"%.3g\", 2.5e-5*(x<1?x:1)}"); fi
    if grep -q "^d=$d seed=$s mu=$mu dt=$dtd " "$results"; then continue; fi
    "$here/run_case.sh" "$lmp" "$rundir" "$d" "$s" "$mu" "$dtd" "$@" >> "$results"
    tail -1 "$results"
  done
done
