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
# shellcheck source=../bed_ab.sh
. "$here/../bed_ab.sh"
bed_ab "fixed bed" "$rounds" "$here/in.fixed_bed_settled" "${common[@]}"
