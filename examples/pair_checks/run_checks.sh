#!/bin/bash
# Runs the full-size checks of pair_style polyhedron from this folder
# and prints the figures; see README.md. Takes several minutes.
#   bash run_checks.sh [path/to/lmp]
set -euo pipefail
lmp=${1:-../../build/lmp}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
py=/usr/bin/python3

echo "== acceptance 4: 1,000-particle gas, 10,000 steps"
$lmp -in in.gas1000 -log log.gas1000 -screen none
$py momenta.py log.gas1000 gas1000.png

echo "== elastic tetrahedra gas: total energy"
$lmp -in in.tetra_elastic -log log.tetra_elastic -screen none
awk '/^ *Step/ {f=1; next} /^Loop/ {f=0} f && NF==7 {print $1, $5}' log.tetra_elastic

echo "== acceptance 5: 2,000 dense particles, -sf kk vs plain"
$lmp -in in.dense2000 -var out plain -log log.dense2000.plain -screen none
$lmp -in in.dense2000 -var out plainon -var newton on -log log.dense2000.plainon -screen none
$lmp -k on -sf kk -pk kokkos newton off -in in.dense2000 -var out kk -log log.dense2000.kk -screen none
for s in 0 100; do
  $py compare.py forces.kk.$s forces.plain.$s
  $py compare.py forces.kk.$s forces.plainon.$s
done

echo "== acceptance 5: settling, 100,000 steps (writes settle.data at step 30,000)"
$lmp -in in.settle -log log.settle -screen none
grep -A12 '^ *Step' log.settle | awk 'NF==7'

echo "== acceptance 5: 1, 2, 4 ranks, 100 steps from settle.data"
for n in 1 2 4; do
  mpirun --oversubscribe -np $n $lmp -in in.settle_ranks -var out $n -log log.ranks.$n -screen none
done
for n in 2 4; do $py compare.py ranks.$n.100 ranks.1.100; done
