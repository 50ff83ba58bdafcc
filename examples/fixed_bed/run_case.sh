#!/bin/bash
# run_case.sh LMP OUTDIR SHAPE SEED [NP] [extra lmp -var pairs...]
# One bed: runs in.bed (NP MPI ranks, default 1) with its output in OUTDIR,
# then analyze_bed.py; prints one line: shape seed wall_s warnings + analyze_bed.py's key=value.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
lmp=$1 outdir=$2 shape=$3 seed=$4 np=${5:-1}
shift 4; shift $(( $# < 1 ? $# : 1 ))
mkdir -p "$outdir"
extra=$(printf '%s' "$*" | tr -s ' ' | sed 's/-var //g; s/ /_/g')
tag="${shape}_s${seed}${extra:+_$extra}"
launch=()
[ "$np" -gt 1 ] && launch=(mpirun --allow-run-as-root --oversubscribe -np "$np")
t0=$(date +%s.%N)
"${launch[@]}" "$lmp" -in "$here/in.bed" -screen none -log "$outdir/log.$tag" \
  -var pot "$here/../../potentials" -var mesh "$here" -var out "$outdir/$tag" \
  -var shape "$shape" -var seed "$seed" "$@"
t1=$(date +%s.%N)
vp=$(sed -n 's/.*polyhedron_shape pellet (index 1): .* volume \([0-9.e+-]*\),.*/\1/p' "$outdir/log.$tag" | head -1)
ts=$(sed -n 's/^SETTLED step [0-9]* time \([0-9.e+-]*\).*/\1/p' "$outdir/log.$tag")
nw=$(grep -c '^WARNING' "$outdir/log.$tag" || true)
mu=$(awk '$1 == "pair_coeff" && $2 == "*" {m = $7} END {print m}' "$outdir/log.$tag")
echo "tag=$tag shape=$shape seed=$seed mu=$mu t_settle=$ts wall_s=$(awk "BEGIN{printf \"%.1f\", $t1 - $t0}") warnings=$nw vp=$vp" \
  "$(/usr/bin/python3 "$here/analyze_bed.py" "$outdir/$tag.vtk" --vp "$vp" \
      --profile "$outdir/$tag.rad" --axial "$outdir/$tag.ax")"
