#!/bin/bash
# README's first command: installs what is needed, builds lmp, runs the main
# example (examples/hopper) and draws its pictures.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install-deps.sh
BUILD=${POLYDEM_BUILD_DIR:-build}
cmake -S . -B "$BUILD"
cmake --build "$BUILD" -j"$(nproc)" --target lmp
LMP=$(cd "$BUILD" && pwd)/lmp
cd examples/hopper
# 400 grains poured into an STL funnel, then discharged onto a floor: on two
# MPI ranks (1.5-4 minutes here); the reference log is log.hopper
mpirun --allow-run-as-root --oversubscribe -np 2 "$LMP" -in in.hopper -log log.run
/usr/bin/python3 plot_hopper.py log.run
echo
echo "quickstart: log       $(pwd)/log.run (reference: log.hopper)"
echo "quickstart: snapshots $(pwd)/hopper.*.vtk (ParaView reads them)"
echo "quickstart: pictures  $(pwd)/hopper.png $(pwd)/hopper_discharge.png"
