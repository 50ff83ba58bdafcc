#!/bin/bash
# run_case.sh LMP OUTDIR D SEED [MU] [DT|auto] [extra lmp -var pairs...]
# One packing: runs in.packing (1 MPI rank) with its output in OUTDIR, then
# analyze.py; prints one line: d seed mu dt t_settle wall_s + analyze.py's key=value.
# DT auto (default): 2.5e-5 s x min(1, d / 0.030 m), below half the printed
# stability limit of a flat face contact at every size (in.packing).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
lmp=$1 outdir=$2 d=$3 seed=$4 mu=${5:-0.8} dt=${6:-auto}
shift 4; shift $(( $# < 2 ? $# : 2 ))
mkdir -p "$outdir"
if [ "$dt" = auto ]; then dt=$(awk "BEGIN{d=$d/0.030; printf \"%.3g\", 2.5e-5*(d<1?d:1)}"); fi
tag=$(printf 'd%s_s%s_mu%s_dt%s' "$d" "$seed" "$mu" "$dt")
t0=$(date +%s.%N)
"$lmp" -in "$here/in.packing" -screen none -log "$outdir/log.$tag" \
  -var pot "$here/../../potentials" -var mesh "$here" -var out "$outdir/$tag" \
  -var d "$d" -var seed "$seed" -var mu "$mu" -var dt "$dt" "$@"
t1=$(date +%s.%N)
ts=$(sed -n 's/^SETTLED step [0-9]* time \([0-9.e+-]*\).*/\1/p' "$outdir/log.$tag")
nw=$(grep -c '^WARNING' "$outdir/log.$tag" || true)
echo "d=$d seed=$seed mu=$mu dt=$dt t_settle=$ts wall_s=$(awk "BEGIN{printf \"%.1f\", $t1 - $t0}") warnings=$nw" \
  "$(/usr/bin/python3 "$here/analyze.py" "$outdir/$tag.vtk" --d "$d" --profile "$outdir/$tag.prof")"
