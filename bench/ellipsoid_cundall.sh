#!/bin/bash
# Cundall number N * steps / s of pair_style ellipsoid on one core, N = 512 ... 32768
# (issue 6, acceptance 6). Usage: bench/ellipsoid_cundall.sh LMP [extra lmp args, e.g. -k on -sf kk -pk kokkos newton off]
LMP=${1:?usage: $0 LMP [args]}
shift
cd "$(dirname "$0")"
# wall-clock Cundall number, LAMMPS's "% CPU use" of the timed run (below 100 % when
# the core was shared), and the Cundall number per CPU second (wall / CPU fraction)
printf "%8s %8s %10s %8s %12s %14s %12s\n" N steps loop_s cpu% cundall cundall/cpu contacts/step
for n in 8 12 16 20 24 32; do
  out=$($LMP -in in.ellipsoid_cundall -var nside $n -log none -nocite "$@" 2>&1)
  loop=$(echo "$out" | grep "^Loop time" | tail -1 | awk '{print $4}')
  steps=$(echo "$out" | grep "^Loop time" | tail -1 | awk '{print $9}')
  cpu=$(echo "$out" | grep "% CPU use" | tail -1 | awk '{print $1}' | tr -d '%')
  contacts=$(echo "$out" | awk '/^ +[0-9]+ +[0-9.e+-]+ +[0-9.e+-]+ +[0-9.e+-]+ *$/ {c=$4} END {print c}')
  awk -v N=$((n*n*n)) -v s=$steps -v t=$loop -v c=$contacts -v p=$cpu \
    'BEGIN {printf "%8d %8d %10.3f %8.1f %12.4g %14.4g %12.1f\n", N, s, t, p, N*s/t, N*s/t/(p/100), c/s}'
done
