#!/bin/bash
# fix wall/mesh scale benchmark (issue 5 acceptance 4): the same 0.3 m x 0.3 m
# floor as 10,082 and as 150,152 triangles (flat: make_floor.py; gently curved,
# radius 5 m, no two facets coplanar: make_bowl.py), 225 dodecahedra resting
# and sliding on it, with coplanar merging (default) and without (merge no),
# and on the curved floor with near lists (cache 128, default) and without (cache 0);
# then a silo (make_silo.py, in.silo) at 9,840 and 149,700 triangles.
# Prints wall and CPU time per particle-step of the second run (1000 steps,
# all in contact), where the fix is > 99 % of the time.
#   bash run.sh [path/to/lmp] [repeats]
set -euo pipefail
lmp=$(realpath "${1:-../../build/lmp}")
reps=${2:-2}
cd "$(dirname "$0")"
[ -f floor10k.stl ] || python3 make_floor.py floor10k.stl 71
[ -f floor150k.stl ] || python3 make_floor.py floor150k.stl 274
[ -f bowl10k.stl ] || python3 make_bowl.py bowl10k.stl 71 0.3 5.0
[ -f bowl150k.stl ] || python3 make_bowl.py bowl150k.stl 274 0.3 5.0
[ -f silo10k.stl ] || python3 make_silo.py silo10k.stl 80 40 22
[ -f silo150k.stl ] || python3 make_silo.py silo150k.stl 300 150 100
# summary LABEL FIX LOG: one line from a run's log: the triangles read and used
# (after coplanar merging), wall and CPU time per particle-step, and the share
# of the time in Modify (FIX: "fix" or "fixes", the words before it)
summary() {
  awk -v m="$1" -v fix="$2" '/^Loop time/ {loop = $4; steps = $9; atoms = $12}
       /CPU use/ {cpu = $1 + 0}
       /^Modify/ {mod = $NF}
       /triangles read/ {tri = $7}
       /coplanar regions/ {after = $10}
       END {printf "%-32s %7d triangles (%d used): %.2f us/particle-step wall, %.2f us CPU (%.0f%% CPU), %s %.1f%%\n",
            m, tri, after ? after : tri, 1e6 * loop / (steps * atoms), 1e6 * loop * cpu / 100 / (steps * atoms), cpu, fix, mod}' "$3"
}
for r in $(seq "$reps"); do
  for c in "floor10k 1e-9 128" "floor150k 1e-9 128" "floor10k no 128" "floor150k no 128" \
           "bowl10k 1e-9 0" "bowl150k 1e-9 0" "bowl10k 1e-9 128" "bowl150k 1e-9 128"; do
    set -- $c
    m=$1; merge=$2; cache=$3
    lift=0.0095
    [[ $m == bowl* ]] && lift=0.0140    # rim of the bowl 4.5 mm above its centre
    "$lmp" -in in.floor -var mesh $m.stl -var merge $merge -var cache $cache -var lift $lift \
      -var pot ../../potentials -log log.$m.$merge.c$cache -screen none
    summary "$m merge $merge cache $cache" fix "log.$m.$merge.c$cache"
  done
done
# the seed's case: a silo (cylinder on a cone) holding about 700 particles that
# touch each other; merging (tolerance 1e-6 for the float32 STL vertices)
# reduces both meshes to planar strips (in.silo)
for r in $(seq "$reps"); do
  for m in silo10k silo150k; do
    "$lmp" -in in.silo -var mesh $m.stl -var pot ../../potentials -log log.$m -screen none
    summary "$m merge 1e-6 cache 128" fixes "log.$m"
  done
done
