# shellcheck shell=bash
# Sourced by the examples' test_short.sh (ctest example.*_short), which run in
# a scratch folder: sets `here`, the folder of the test script ($0), and
# `scratch`, a new temporary folder that is removed when the script exits;
# defines short_run (below).
# shellcheck disable=SC2034  # here: for the script that sources this file
here=$(cd "$(dirname "$0")" && pwd)
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

# short_run LMP INPUT STEPS FILE...: in the scratch folder, INPUT (its dump
# lines commented out) and the FILEs from here, run for STEPS steps into
# log.short
short_run() {
  local lmp=$1 input=$2 steps=$3
  shift 3
  for f in "$@"; do cp "$here/$f" .; done
  sed 's/^dump /# dump /' "$here/$input" > in.short
  "$lmp" -in in.short -screen none -log log.short -var steps "$steps"
}
