#!/bin/bash
# Cundall number N * steps / s of pair_style ellipsoid on one core, N = 512 ... 32768
# (issue 6, acceptance 6). Usage: bench/ellipsoid_cundall.sh LMP [extra lmp args, e.g. -k on -sf kk -pk kokkos newton off]
LMP=${1:?usage: $0 LMP [args]}
shift
cd "$(dirname "$0")"
printf "%8s %10s %12s %14s %12s\n" N steps loop_s cundall contacts/step
for n in 8 12 16 20 24 32; do
  out=$($LMP -in in.ellipsoid_cundall -var nside $n -log none -nocite "$@" 2>&1)
  loop=$(echo "$out" | grep "^Loop time" | tail -1 | awk '{print $4}')
  steps=$(echo "$out" | grep "^Loop time" | tail -1 | awk '{print $9}')
  contacts=$(echo "$out" | awk '/^ +[0-9]+ +[0-9.e+-]+ +[0-9.e+-]+ +[0-9.e+-]+ *$/ {c=$4} END {print c}')
  awk -v N=$((n*n*n)) -v s=$steps -v t=$loop -v c=$contacts \
    'BEGIN {printf "%8d %10d %12.3f %14.4g %12.1f\n", N, s, t, N*s/t, c/s}'
done
