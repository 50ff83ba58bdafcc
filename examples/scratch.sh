# shellcheck shell=bash
# Sourced by the examples' test_short.sh (ctest example.*_short), which run in
# a scratch folder: sets `here`, the folder of the test script ($0), and
# `scratch`, a new temporary folder that is removed when the script exits.
# shellcheck disable=SC2034  # here: for the script that sources this file
here=$(cd "$(dirname "$0")" && pwd)
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
