#!/bin/bash
# fix wall/mesh scale benchmark (issue 5 acceptance 4): the same 0.3 m x 0.3 m
# floor as 10,082 and as 150,152 triangles, 225 dodecahedra resting and
# sliding on it. Prints wall and CPU time per particle-step of the second run
# (1000 steps, all in contact), where the fix is > 99 % of the time.
#   bash run.sh [path/to/lmp] [repeats]
set -euo pipefail
lmp=${1:-../../build/lmp}
reps=${2:-2}
cd "$(dirname "$0")"
[ -f floor10k.stl ] || python3 make_floor.py floor10k.stl 71
[ -f floor150k.stl ] || python3 make_floor.py floor150k.stl 274
for r in $(seq "$reps"); do
  for m in floor10k floor150k; do
    "$lmp" -in in.floor -var mesh $m.stl -var pot ../../potentials -log log.$m -screen none
    awk -v m=$m '/^Loop time/ {loop = $4; steps = $9; atoms = $12}
                 /CPU use/ {cpu = $1 + 0}
                 /^Modify/ {mod = $6}
                 /^fix wall\/mesh/ {tri = $6}
                 END {printf "%-10s %7d triangles: %.2f us/particle-step wall, %.2f us CPU (%.0f%% CPU), fix %.1f%%\n",
                      m, tri, 1e6 * loop / (steps * atoms), 1e6 * loop * cpu / 100 / (steps * atoms), cpu, mod}' log.$m
  done
done
