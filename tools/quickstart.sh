#!/bin/bash
# README's first command: installs what is needed, builds lmp, runs the main
# example and renders its last snapshot.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install-deps.sh
BUILD=${POLYDEM_BUILD_DIR:-build}
cmake -S . -B "$BUILD"
cmake --build "$BUILD" -j"$(nproc)" --target lmp
LMP=$(cd "$BUILD" && pwd)/lmp
cd examples/tumble
"$LMP" -in in.tumble -log log.run
last=$(ls -1 polyhedra.*.vtk | sort -t. -k2 -n | tail -n 1)
/usr/bin/python3 ../../tools/render_vtk.py "$last" tumble.png --title "POLYDEM: 300 grains, ${last}"
echo
echo "quickstart: log      $(pwd)/log.run (reference: log.tumble)"
echo "quickstart: snapshot $(pwd)/${last} (ParaView reads it)"
echo "quickstart: picture  $(pwd)/tumble.png"
