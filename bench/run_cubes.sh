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

us_per_particle_step() {    # log file -> wall and CPU (wall x % CPU use) microseconds per particle-step
  awk '/^Loop time of/ {t = $4; n = $9; na = $12} /% CPU use/ {c = $1 + 0}
       END {printf "%.3f %.3f", 1e6 * t / (n * na), 1e6 * t * c / 100 / (n * na)}' "$1"
}

echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
(cd "$scratch" && "$debian" -in in.cubes -log log.body -screen none)
(cd "$scratch" && "$ours" -in in.cubes_polyhedron -var pot "$here/../potentials" \
   -log log.poly -screen none)
echo "load average after:  $(cut -d' ' -f1-3 /proc/loadavg)"
read -r bw bc <<< "$(us_per_particle_step "$scratch/log.body")"
read -r pw pc <<< "$(us_per_particle_step "$scratch/log.poly")"
echo "body/rounded/polyhedron (Debian lammps, in.cubes): wall $bw, CPU $bc us per particle-step"
echo "  $(grep '^Loop time' "$scratch/log.body"); $(grep '% CPU use' "$scratch/log.body")"
echo "pair polyhedron (POLYDEM, in.cubes_polyhedron):    wall $pw, CPU $pc us per particle-step"
echo "  $(grep '^Loop time' "$scratch/log.poly"); $(grep '% CPU use' "$scratch/log.poly")"
# same velocities: kinetic energy per atom at step 0 (in.cubes normalises by atoms)
ke_body=$(awk '/^ *Step/ {getline; print $2; exit}' "$scratch/log.body")
ke_poly=$(awk '/^ *Step/ {getline; printf "%.7g", $2 / 54; exit}' "$scratch/log.poly")
echo "kinetic energy per atom at step 0: body $ke_body, polyhedron $ke_poly"
echo "contacts at the end (polyhedron): $(awk '/^ *Step/ {f=1; next} /^Loop/ {f=0} f {c=$5} END {print c}' "$scratch/log.poly")"
awk -v bw="$bw" -v pw="$pw" -v bc="$bc" -v pc="$pc" \
  'BEGIN {printf "speed-up per particle-step: %.1fx (wall), %.1fx (CPU)\n", bw / pw, bc / pc}'
