#!/bin/bash
LMP=$(realpath "${1:-$(dirname "$0")/../../../build/lmp}")
cd "$(dirname "$0")"
for x in 1.0 2.0 3.0; do for K in 1.0e9 1.0e10; do
  /usr/bin/time -f "wall %e s" $LMP -in in.pairs_kn -var tag xi$x -var xi $x -var kn $K -var dtfrac 100 \
     -log log.xi$x.kn$K.tc100 -screen none 2> time.xi$x.kn$K.tc100 || exit 1
done; done
echo KNDONE
