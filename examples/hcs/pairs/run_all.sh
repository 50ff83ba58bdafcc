#!/bin/bash
# sequential: generation, then the LAMMPS runs of each xi (one process at a time)
LMP=$(realpath "${1:-$(dirname "$0")/../../../build/lmp}")
cd "$(dirname "$0")"
export OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1
for x in 1.0 3.0 2.0; do
  /usr/bin/python3 gen.py $x 3000 2024 xi$x > gen.xi$x.out 2>&1 || exit 1
  if [ $x = 1.0 ]; then post50=3; else post50=80; fi
  for F in 50 100 200 800 1600; do
    post=$post50; [ $F = 1600 ] && post=3
    /usr/bin/time -f "wall %e s" $LMP -in in.pairs -var tag xi$x -var xi $x -var dtfrac $F -var post $post \
        -log log.xi$x.tc$F -screen none 2> time.xi$x.tc$F || exit 1
  done
  /usr/bin/python3 analyse.py xi$x 50 100 200 800 1600 > result.xi$x.txt 2>&1
done
echo ALLDONE
