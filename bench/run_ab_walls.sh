#!/bin/bash
# A/B speed comparison of two lmp binaries on the wall benchmark's meshes, run
# alternately (see run_ab.sh): wall_mesh/in.floor (225 dodecahedra, merge and
# cache defaults) on the flat 10k floor and the curved 10k and 150k bowls.
# Prints CPU microseconds per particle-step of each run and the ratio B/A of
# the medians.
#   bash bench/run_ab_walls.sh lmpA lmpB [rounds]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
A=$(realpath "$1") B=$(realpath "$2") rounds=${3:-5}
cd "$here/wall_mesh"
[ -f floor10k.stl ] || python3 make_floor.py floor10k.stl 71
[ -f bowl10k.stl ] || python3 make_bowl.py bowl10k.stl 71 0.3 5.0
[ -f bowl150k.stl ] || python3 make_bowl.py bowl150k.stl 274 0.3 5.0
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
us() {    # log -> CPU microseconds per particle-step
  awk '/^Loop time of/ {t = $4; n = $9; N = $12} /% CPU use/ {c = $1 + 0}
       END {printf "%.3f", 1e6 * t * c / 100 / (n * N)}' "$1"
}
declare -A res
for r in $(seq "$rounds"); do
  for which in A B; do
    lmp=${!which}
    for c in "floor10k 0.0095" "bowl10k 0.0140" "bowl150k 0.0140"; do
      set -- $c
      "$lmp" -in in.floor -var mesh "$1.stl" -var merge 1e-9 -var cache 128 -var lift "$2" \
        -var pot "$here/../potentials" -log "$scratch/log.$1" -screen none
      res[$1_$which]+="$(us "$scratch/log.$1") "
    done
  done
done
median() { tr ' ' '\n' | grep -v '^$' | sort -g | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}'; }
for m in floor10k bowl10k bowl150k; do
  a=$(echo ${res[${m}_A]} | median)
  b=$(echo ${res[${m}_B]} | median)
  echo "$m A: ${res[${m}_A]} B: ${res[${m}_B]} median B/A $(awk -v a="$a" -v b="$b" 'BEGIN {printf "%.3f", b / a}')"
done
