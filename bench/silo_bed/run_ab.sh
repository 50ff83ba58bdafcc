#!/bin/bash
# A/B speed comparison on the settled silo bed (in.silo_bed): makes the bed
# once (bed.restart in DIR, with binary A, 3 minutes on one core with 6d0352b),
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
# shellcheck source=../bed_ab.sh
. "$here/../bed_ab.sh"
bed_ab "silo bed" "$rounds" "$here/in.silo_bed" -var pot "$here/../../potentials" -var mesh .
