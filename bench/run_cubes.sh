#!/bin/bash
# Side by side (issue 4, benchmark 2), in one script run: Debian's own LAMMPS
# (package lammps, /usr/bin/lmp: BODY package, pair body/rounded/polyhedron)
# running its examples/body/in.cubes (54 rounded cubes, 10,000 steps), and
# POLYDEM's lmp running in.cubes_polyhedron (the same cubes, positions,
# velocities, time step and steps with pair polyhedron). One core each, one
# after the other. Prints microseconds per particle-step and the ratio.
#   bash bench/run_cubes.sh [polydem lmp] [debian lmp]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
ours=${1:-$here/../build/lmp}
debian=${2:-/usr/bin/lmp}
examples=/usr/share/lammps/examples/body    # from Debian's lammps package
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
cp "$examples/in.cubes" "$examples/data.cubes" "$scratch/"
cp "$here/in.cubes_polyhedron" "$here/data.cubes_polyhedron" "$scratch/"

us_per_particle_step() {    # log file -> microseconds per particle-step
  awk '/^Loop time of/ {t = $4; n = $9; na = $12} END {printf "%.3f", 1e6 * t / (n * na)}' "$1"
}

echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
(cd "$scratch" && "$debian" -in in.cubes -log log.body -screen none)
(cd "$scratch" && "$ours" -in in.cubes_polyhedron -var pot "$here/../potentials" \
   -log log.poly -screen none)
echo "load average after:  $(cut -d' ' -f1-3 /proc/loadavg)"
b=$(us_per_particle_step "$scratch/log.body")
p=$(us_per_particle_step "$scratch/log.poly")
echo "body/rounded/polyhedron (Debian lammps, in.cubes): $b us per particle-step"
echo "  $(grep '^Loop time' "$scratch/log.body")"
echo "pair polyhedron (POLYDEM, in.cubes_polyhedron):    $p us per particle-step"
echo "  $(grep '^Loop time' "$scratch/log.poly")"
echo "initial kinetic energy (same velocities): body $(awk '/^ *Step/ {getline; print $2; exit}' "$scratch/log.body"), polyhedron $(awk '/^ *Step/ {getline; print $2; exit}' "$scratch/log.poly")"
echo "contacts at the end (polyhedron): $(awk '/^ *Step/ {f=1; next} /^Loop/ {f=0} f {c=$5} END {print c}' "$scratch/log.poly")"
awk -v b="$b" -v p="$p" 'BEGIN {printf "speed-up per particle-step: %.1fx\n", b / p}'
