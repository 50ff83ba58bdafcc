#!/bin/bash
# run_example.sh LMP EXAMPLE_DIR INPUT REFERENCE_LOG [RTOL] [extra lmp args...]
# Runs an example in a scratch copy of its folder and compares the thermo
# output with the reference log (tools/compare_log.py). Used by ctest.
# POLYDEM_EXAMPLE_NP=n runs it on n MPI ranks (as its reference log was made).
set -euo pipefail
lmp=$1 dir=$2 input=$3 ref=$4 rtol=${5:-1e-6}
shift 5 || shift $#
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
cp -r "$dir"/. "$scratch"/
cd "$scratch"
launch=()
if [ "${POLYDEM_EXAMPLE_NP:-1}" -gt 1 ]; then
  launch=(mpirun --allow-run-as-root --oversubscribe -np "$POLYDEM_EXAMPLE_NP")
fi
"${launch[@]}" "$lmp" -in "$input" -log log.new -screen none -var pot "$(cd "$dir"/../../potentials && pwd)" "$@"
/usr/bin/python3 "$(dirname "$0")/../../tools/compare_log.py" log.new "$dir/$ref" --rtol "$rtol"
