#!/bin/bash
# Thread scaling of the /kk styles against MPI scaling of the plain ones
# (issue 19): the dense periodic dodecahedra (in.dodeca_dense, N = 1e4, 100
# steps) and the seed's silo (wall_mesh/in.silo, 726 dodecahedra in a
# 9,840-triangle silo, 6,000 steps untimed + 1,000 timed), each as
#   kk1   lmp -k on t 1 -sf kk        kk2   lmp -k on t 2 -sf kk
#   mpi1  mpirun -np 1 lmp (plain)    mpi2  mpirun -np 2 lmp (plain)
# (the /kk runs with -pk kokkos newton on, the Kokkos default on CPUs). The four are run in turn, round
# after round, so that the machine's drift (+-25 %) hits them alike. Prints the
# wall-clock loop time of the timed run of each, per particle-step, and the
# speed-ups t1/t2 of the medians.
#   bash bench/run_threads.sh [path/to/lmp] [rounds]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
lmp=$(realpath "${1:-$here/../build/lmp}")
rounds=${2:-3}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
(cd "$here/wall_mesh" && { [ -f silo10k.stl ] || python3 make_silo.py silo10k.stl 80 40 22; })
cp "$here/wall_mesh/silo10k.stl" "$scratch/"
cd "$scratch"
export OMP_PROC_BIND=false
mpi=(mpirun --allow-run-as-root --oversubscribe --bind-to none)

us() {    # log -> wall microseconds per particle-step of the last run
  awk '/^Loop time of/ {t = $4; n = $9; N = $12} END {printf "%.3f", 1e6 * t / (n * N)}' "$1"
}
run() {    # case config
  local c=$1 k=$2 args=() launch=()
  case $k in
    kk1) args=(-k on t 1 -sf kk -pk kokkos newton on) ;;
    kk2) args=(-k on t 2 -sf kk -pk kokkos newton on) ;;
    mpi1) launch=("${mpi[@]}" -np 1) ;;
    mpi2) launch=("${mpi[@]}" -np 2) ;;
  esac
  if [ "$c" = dense ]; then
    "${launch[@]}" "$lmp" "${args[@]}" -in "$here/in.dodeca_dense" -var pot "$here/../potentials" \
      -var nx 20 -var ny 20 -var nz 25 -var steps 100 -log log.$c.$k -screen none
  else
    "${launch[@]}" "$lmp" "${args[@]}" -in "$here/wall_mesh/in.silo" -var mesh silo10k.stl \
      -var pot "$here/../potentials" -log log.$c.$k -screen none
  fi
  res[${c}_$k]+="$(us log.$c.$k) "
}

declare -A res
for r in $(seq "$rounds"); do
  for c in dense silo; do
    for k in kk1 kk2 mpi1 mpi2; do run $c $k; done
  done
done
median() { tr ' ' '\n' | grep -v '^$' | sort -g | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}'; }
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2); $(date -u)"
echo "lmp: $lmp, $rounds rounds; wall us/particle-step per run"
for c in dense silo; do
  for k in kk1 kk2 mpi1 mpi2; do printf "%-6s %-5s %s\n" "$c" "$k" "${res[${c}_$k]}"; done
  m() { echo "${res[${c}_$1]}" | median; }
  printf "%-6s speed-up 2 threads (kk1/kk2) %.3f   2 ranks (mpi1/mpi2) %.3f   kk2 vs mpi2 time %.3f\n" "$c" \
    "$(echo "$(m kk1) / $(m kk2)" | bc -l)" "$(echo "$(m mpi1) / $(m mpi2)" | bc -l)" \
    "$(echo "$(m kk2) / $(m mpi2)" | bc -l)"
  # per round ratios (the drift cancels within a round)
  read -r -a a1 <<< "${res[${c}_kk1]}"; read -r -a a2 <<< "${res[${c}_kk2]}"
  read -r -a b1 <<< "${res[${c}_mpi1]}"; read -r -a b2 <<< "${res[${c}_mpi2]}"
  for i in "${!a1[@]}"; do
    printf "%-6s round %d: kk1/kk2 %.3f mpi1/mpi2 %.3f\n" "$c" $((i + 1)) \
      "$(echo "${a1[$i]} / ${a2[$i]}" | bc -l)" "$(echo "${b1[$i]} / ${b2[$i]}" | bc -l)"
  done
done
