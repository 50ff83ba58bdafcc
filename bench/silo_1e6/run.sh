#!/bin/bash
# The seed's silo (section 4.1) fed to 1,000,000 mineral grains, the paper's
# size: examples/silo/in.silo with the grains scaled to s = 1.5 (4.1 x 2.8 x
# 2.2 cm), batches of 50,000, the time step scaled with the grain size (the
# flat-contact stability limit is proportional to it) and the box up to the
# silo's top. For a GPU machine (-k on g N -sf kk) or a large CPU allocation;
# cost estimate from the CPU figures in README.md.
#   bash bench/silo_1e6/run.sh LMP OUTDIR [launcher and lmp arguments...]
# e.g. bash bench/silo_1e6/run.sh build/lmp /scratch/silo mpirun -np 64
#      bash bench/silo_1e6/run.sh build/lmp /scratch/silo -- -k on g 1 -sf kk
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
ex="$here/../../examples/silo"
lmp=$1 out=$2
shift 2
launch=() extra=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do launch+=("$1"); shift; done
[ "${1:-}" = "--" ] && shift
extra=("$@")
mkdir -p "$out"
cd "$out"
[ -f silo.stl ] || /usr/bin/python3 "$ex/make_silo.py" silo.stl lid.stl
"${launch[@]}" "$lmp" "${extra[@]}" -in "$ex/in.silo" -log log.silo_1e6 \
  -var pot "$ex/../../potentials" -var mesh . -var out silo_1e6 \
  -var s 1.5 -var n 1000000 -var nb 50000 -var tb 0.35 -var phip 0.25 -var dt 5.6e-5 \
  -var tdamp 7.15 -var gdamp 0.158 -var tmax 9.0 -var tavg 0.05 -var ztop 10.6
