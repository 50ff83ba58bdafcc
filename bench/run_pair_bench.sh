#!/bin/bash
# pair polyhedron benchmarks (issue 4, benchmark 1 and 3): dense periodic
# dodecahedra (in.dodeca_dense, solid fraction 0.49) at N = 1e3, 1e4, 1e5,
# plain and -sf kk (Kokkos Serial), one core; then N = 1e5 on 1 and 2 MPI
# ranks. Per run: microseconds per particle-step from LAMMPS's loop time, both
# wall and CPU (wall x "% CPU use", less sensitive to a shared machine), the
# peak resident memory per particle (/usr/bin/time), and the load average.
#   bash bench/run_pair_bench.sh [lmp]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
lmp=${1:-$here/../build/lmp}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
cd "$scratch"

report() {    # name N log rss_kb
  awk -v name="$1" -v N="$2" -v rss="$4" -v load="$(cut -d' ' -f1 /proc/loadavg)" '
    /^Loop time of/ {t = $4; n = $9}
    /% CPU use/ {cpu = $1 + 0}
    /^ *Step/ {getline; getline; c4 = $6}
    END {printf "%-22s N=%-7d steps=%-4d wall %7.2f us  cpu %7.2f us per particle-step  " \
                "(CPU %5.1f%%)  peak RSS %6.0f B/particle  Z=%s  load %s\n",
                name, N, n, 1e6 * t / (n * N), 1e6 * t * cpu / 100 / (n * N), cpu,
                1024 * rss / N, c4, load}' "$3"
}

run() {    # name N nx ny nz steps [launcher/args...]
  local name=$1 N=$2 nx=$3 ny=$4 nz=$5 steps=$6
  shift 6
  /usr/bin/time -o rss.txt -f "%M" "$@" -in "$here/in.dodeca_dense" -var pot "$here/../potentials" \
    -var nx $nx -var ny $ny -var nz $nz -var steps $steps -log log.$name -screen none
  report "$name" $N log.$name "$(tail -1 rss.txt)"
}

KK=(-k on -sf kk -pk kokkos newton off)
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2)"
run plain_1e3 1000 10 10 10 200 "$lmp"
run kk_1e3 1000 10 10 10 200 "$lmp" "${KK[@]}"
run plain_1e4 10000 20 20 25 20 "$lmp"
run kk_1e4 10000 20 20 25 20 "$lmp" "${KK[@]}"
run plain_1e5 100000 40 50 50 5 "$lmp"
run kk_1e5 100000 40 50 50 5 "$lmp" "${KK[@]}"
# 2 ranks (RSS: of mpirun's largest child only, not reported)
run plain_1e5_2ranks 100000 40 50 50 5 mpirun --oversubscribe -np 2 "$lmp"
