#!/bin/bash
# A/B speed comparison on the settled silo bed (in.silo_bed): makes the bed
# once (bed.restart in DIR, with binary A, about 15 minutes on one core),
# then times 300 steps of it with A and B alternately, `rounds` times each.
# Prints CPU microseconds per grain-step of every run and the ratio B/A of
# the medians.
#   bash bench/silo_bed/run_ab.sh lmpA lmpB [rounds] [DIR]
# DIR (default: a folder under /tmp) holds silo.stl, lid.stl and bed.restart
# between calls.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
A=$(realpath "$1") B=$(realpath "$2") rounds=${3:-3} dir=${4:-/tmp/polydem_silo_bed}
mkdir -p "$dir" && cd "$dir"
[ -f silo.stl ] || python3 "$here/../../examples/silo/make_silo.py" silo.stl lid.stl
[ -f bed.restart ] || "$A" -in "$here/in.silo_bed" -var mode make -var pot "$here/../../potentials" \
  -var mesh . -log log.make -screen none
us() {    # log -> CPU microseconds per grain-step of its (only) run
  awk '/^Loop time of/ {t = $4; n = $9; N = $12} /% CPU use/ {c = $1 + 0}
       END {printf "%.3f", 1e6 * t * c / 100 / (n * N)}' "$1"
}
declare -A res
for r in $(seq "$rounds"); do
  for which in A B; do
    "${!which}" -in "$here/in.silo_bed" -var mode time -var pot "$here/../../potentials" -var mesh . \
      -log "log.$which" -screen none
    res[$which]+="$(us "log.$which") "
  done
done
median() { tr ' ' '\n' | grep -v '^$' | sort -g | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}'; }
a=$(echo "${res[A]}" | median) b=$(echo "${res[B]}" | median)
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2); $(date -u)"
printf "silo bed  A: %s us   B: %s us   (CPU us/grain-step per run)  median B/A = %.3f\n" \
  "${res[A]}" "${res[B]}" "$(echo "$b / $a" | bc -l)"
