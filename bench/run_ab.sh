#!/bin/bash
# A/B speed comparison of two lmp binaries (e.g. before and after a change),
# run alternately so that the machine's drift (+-25 % from minute to minute)
# hits both alike: the dense periodic dodecahedra (in.dodeca_dense, N = 1e4,
# plain and -sf kk) and the wall benchmark (wall_mesh/in.floor, 225
# dodecahedra on a 10,082-triangle floor, merge and cache defaults).
# Suite "walls": wall_mesh/in.floor on the flat 10k floor and on the curved
# 10k and 150k bowls (cache 128) instead. Suite "kk": the dense case plain,
# -sf kk with newton pair off and with newton on (one thread each), and the
# /kk runs' cost relative to plain within each binary (-sf kk with newton
# pair off against plain with newton pair off, as both then compute the pairs
# across periodic images twice).
# Prints microseconds per particle-step (CPU time) of each run and the ratio
# B/A of the medians.
#   bash bench/run_ab.sh lmpA lmpB [rounds] [default|walls|kk]
set -euo pipefail
export OMP_PROC_BIND=${OMP_PROC_BIND:-false}    # Kokkos OpenMP: no binding warning
here=$(cd "$(dirname "$0")" && pwd)
A=$(realpath "$1") B=$(realpath "$2") rounds=${3:-3} suite=${4:-default}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
(cd "$here/wall_mesh" && { [ -f floor10k.stl ] || python3 make_floor.py floor10k.stl 71; })
cp "$here/wall_mesh/floor10k.stl" "$scratch/"
if [ "$suite" = walls ]; then
  (cd "$here/wall_mesh" && { [ -f bowl10k.stl ] || python3 make_bowl.py bowl10k.stl 71 0.3 5.0; } &&
    { [ -f bowl150k.stl ] || python3 make_bowl.py bowl150k.stl 274 0.3 5.0; })
  cp "$here/wall_mesh/bowl10k.stl" "$here/wall_mesh/bowl150k.stl" "$scratch/"
fi
cd "$scratch"

us() {    # log N -> CPU microseconds per particle-step
  awk '/^Loop time of/ {t = $4; n = $9; N = $12} /% CPU use/ {c = $1 + 0}
       END {printf "%.3f", 1e6 * t * c / 100 / (n * N)}' "$1"
}

declare -A res
walls() {    # lmp which: the floor and the two bowls
  for c in "floor10k 0.0095" "bowl10k 0.0140" "bowl150k 0.0140"; do
    set -- $c
    "$lmp" -in "$here/wall_mesh/in.floor" -var mesh "$1.stl" -var merge 1e-9 -var cache 128 \
      -var lift "$2" -var pot "$here/../potentials" -log "log.$1" -screen none
    res[$1_$which]+="$(us "log.$1") "
  done
}

dense() {    # lmp which name [args]: the dense dodecahedra, N = 1e4
  local name=$1
  shift
  "$lmp" "$@" -in "$here/in.dodeca_dense" -var pot "$here/../potentials" -var nx 20 -var ny 20 \
    -var nz 25 -var steps 100 -log "log.$name" -screen none
  res[${name}_$which]+="$(us "log.$name") "
}

floor() {    # lmp which name [args]: 225 dodecahedra on the 10k floor
  local name=$1
  shift
  "$lmp" "$@" -in "$here/wall_mesh/in.floor" -var mesh floor10k.stl -var merge 1e-9 \
    -var cache 128 -var lift 0.0095 -var pot "$here/../potentials" -log "log.$name" -screen none
  res[${name}_$which]+="$(us "log.$name") "
}

cases="dense densekk floor"
[ "$suite" = walls ] && cases="floor10k bowl10k bowl150k"
[ "$suite" = kk ] && cases="dense densenoff densekk densekkon floor floorkk"
for r in $(seq "$rounds"); do
  for which in A B; do
    lmp=${!which}
    if [ "$suite" = walls ]; then
      walls
      continue
    fi
    dense dense
    dense densekk -k on -sf kk -pk kokkos newton off
    if [ "$suite" = kk ]; then
      dense densenoff -var newton off
      dense densekkon -k on -sf kk -pk kokkos newton on
    fi
    floor floor
    if [ "$suite" = kk ]; then floor floorkk -k on -sf kk; fi
  done
done
median() { tr ' ' '\n' | grep -v '^$' | sort -g | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}'; }
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2); $(date -u)"
for case in $cases; do
  a=$(echo "${res[${case}_A]}" | median) b=$(echo "${res[${case}_B]}" | median)
  printf "%-8s A: %s us   B: %s us   (CPU us/particle-step per run)  median B/A = %.3f\n" \
    "$case" "${res[${case}_A]}" "${res[${case}_B]}" "$(echo "$b / $a" | bc -l)"
done
if [ "$suite" = kk ]; then
  for which in A B; do
    for pair in densekk:densenoff densekkon:dense floorkk:floor; do
      case=${pair%%:*}
      p=$(echo "${res[${pair##*:}_$which]}" | median)
      k=$(echo "${res[${case}_$which]}" | median)
      printf "%s: %-9s / %-9s = %.3f (medians)\n" "$which" "$case" "${pair##*:}" "$(echo "$k / $p" | bc -l)"
    done
  done
fi
