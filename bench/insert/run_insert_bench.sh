#!/bin/bash
# Insertion benchmarks (bench/RESULTS.md): time and solid fraction of random
# sequential addition of 5 mm dodecahedra with fix insert/polyhedron, one rank.
#   bash run_insert_bench.sh [lmp]
set -euo pipefail
cd "$(dirname "$0")"
LMP=$(realpath "${1:-../../build/lmp}")
bench_case() {
  local label=$1
  shift
  local args=()
  for kv in "$@"; do args+=(-var "${kv%%=*}" "${kv#*=}"); done
  local t0 t1
  t0=$(date +%s.%N)
  out=$("$LMP" -in in.pack -log none -nocite "${args[@]}" | grep -E "RESULT")
  t1=$(date +%s.%N)
  printf "%-44s %s  %.1f s\n" "$label" "$out" "$(echo "$t1 - $t0" | bc)"
}
bench_case "20k to 0.35, periodic box" L=0.3796 bc=p allin=no phi=0.35 n=20000
bench_case "20k to 0.35, walled box (all_in yes)" L=0.3796 bc=f allin=yes phi=0.35 n=20000
bench_case "saturation, periodic 0.2 m box" L=0.2 bc=p allin=no phi=0.99 n=0 attempts=10000 misses=200
