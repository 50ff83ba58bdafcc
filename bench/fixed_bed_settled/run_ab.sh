#!/bin/bash
# A/B speed comparison on the settled short fixed bed (in.fixed_bed_settled):
# makes the bed once (bed.data in DIR, with binary A, about a minute), then
# times 4,000 steps of it with A and B alternately, `rounds` times each.
# Prints CPU microseconds per grain-step of every run and the ratio B/A of
# the medians. Binaries of other versions read the same data file, so the
# baseline of issue 31 (a build of 7be29f3) runs the same work.
#   bash bench/fixed_bed_settled/run_ab.sh lmpA lmpB [rounds] [DIR]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
A=$(realpath "$1") B=$(realpath "$2") rounds=${3:-3} dir=${4:-/tmp/polydem_fixed_bed_settled}
mkdir -p "$dir" && cd "$dir"
common=(-var ex "$here/../../examples/fixed_bed" -var pot "$here/../../potentials")
[ -f bed.data ] || "$A" -in "$here/in.fixed_bed_settled" -var mode make "${common[@]}" \
  -var mesh "$here/../../examples/fixed_bed" -var out final -var shape catalyst_cylinder \
  -var seed 1 -var n 100 -var tsettle 0.6 -log log.make -screen none
us() {    # log -> CPU microseconds per grain-step of its (only) run
  awk '/^Loop time of/ {t = $4; n = $9; N = $12} /% CPU use/ {c = $1 + 0}
       END {printf "%.3f", 1e6 * t * c / 100 / (n * N)}' "$1"
}
declare -A res
for r in $(seq "$rounds"); do
  for which in A B; do
    "${!which}" -in "$here/in.fixed_bed_settled" -var mode time "${common[@]}" \
      -log "log.$which" -screen none
    res[$which]+="$(us "log.$which") "
  done
done
median() { tr ' ' '\n' | grep -v '^$' | sort -g | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}'; }
a=$(echo "${res[A]}" | median) b=$(echo "${res[B]}" | median)
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2); $(date -u)"
printf "fixed bed  A: %s us   B: %s us   (CPU us/grain-step per run)  median B/A = %.3f\n" \
  "${res[A]}" "${res[B]}" "$(echo "$b / $a" | bc -l)"
