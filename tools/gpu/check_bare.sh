#!/bin/bash
# check_bare.sh DIR   (called by bundle.sh --prebuilt; also by hand)
#
# Checks a prebuilt run (bundle.sh --prebuilt) as a bare x86-64 Linux would
# see it: an empty environment (env -i: PATH=/usr/bin:/bin, without the CUDA
# toolkit; no LD_LIBRARY_PATH) in a fresh folder. For each build in DIR:
#   - every shared library an executable loads resolves, and every one that
#     is not glibc's resolves inside DIR/lib (a node need not have GMP, MPFR,
#     libgomp or this libstdc++);
#   - `lmp -h` runs;
#   - CUDA build: `lmp -k on g 1` stops with the CUDA runtime's message where
#     there is no GPU (or, on a GPU node, runs);
#   - the OpenMP build runs a few steps with -k on t 2 -sf kk.
set -uo pipefail
dir=$(cd "$1" && pwd)
fresh=$(mktemp -d)
trap 'rm -rf "$fresh"' EXIT
bare() { env -i PATH=/usr/bin:/bin HOME="$fresh" bash -c "cd '$fresh' && $1"; }
fail=0
say() { echo "check_bare: $*"; }
cat > "$fresh/in.tiny" <<IN
units lj
atom_style polyhedron
comm_modify vel yes
atom_modify map array
region box block 0 3 0 3 0 3
create_box 1 box
polyhedron_shape d $dir/polydem/potentials/dodecahedron.shape
create_atoms 1 single 1 1 1
create_atoms 1 single 1.45 1 1
polyhedron_set type 1 shape d scale 0.4 density 1.0
velocity all set 0.1 0 0
pair_style polyhedron
pair_coeff * * 1e4 0.3 0.5 0.5
fix 1 all nve/polyhedron
timestep 1e-4
run 10
IN
for bin in "$dir/bin" "$dir/bin-cpu"; do
  [ -d "$bin" ] || continue
  b=$(basename "$bin")
  for exe in "$bin"/*; do
    out=$(bare "ldd '$exe'")
    if echo "$out" | grep -q 'not found'; then
      say "FAIL $b/$(basename "$exe"): $(echo "$out" | grep 'not found' | paste -sd ' ')"
      fail=1
    fi
    outside=$(echo "$out" | awk '$2 == "=>" && $3 ~ /^\// {print $1, $3}' |
      grep -v -E '^(libc|libm|libdl|libpthread|librt)\.so' | while read -r n p; do
        case $(realpath "$p") in "$dir"/lib/*) ;; *) echo "$n $p" ;; esac
      done)
    if [ -n "$outside" ]; then
      say "FAIL $b/$(basename "$exe") loads from outside $dir/lib: $(echo "$outside" | paste -sd ';')"
      fail=1
    fi
  done
  if bare "'$bin/lmp' -h > lmp_h.txt 2>&1"; then
    say "ok   $b/lmp -h ($(grep -c . "$fresh/lmp_h.txt") lines; $(grep -o 'KOKKOS package API: [A-Za-z ]*' "$fresh/lmp_h.txt" | head -n1))"
  else
    say "FAIL $b/lmp -h: $(tail -n2 "$fresh/lmp_h.txt" | paste -sd ' ')"
    fail=1
  fi
  if [ "$b" = bin ]; then
    bare "'$bin/lmp' -k on g 1 -sf kk -pk kokkos newton off -in in.tiny -log none > g1.txt 2>&1"
    rc=$?
    if [ $rc -ne 0 ] && grep -qi 'cuda' "$fresh/g1.txt"; then
      say "ok   bin/lmp -k on g 1 stops without a GPU: $(grep -i -m1 'cuda' "$fresh/g1.txt" | cut -c1-160)"
    elif [ $rc -eq 0 ] && grep -q '^Loop time' "$fresh/g1.txt"; then
      say "ok   bin/lmp -k on g 1 ran on a GPU"
    else
      say "FAIL bin/lmp -k on g 1 (exit $rc): $(tail -n3 "$fresh/g1.txt" | paste -sd ' ')"
      fail=1
    fi
  else
    if bare "OMP_PROC_BIND=false '$bin/lmp' -k on t 2 -sf kk -pk kokkos newton off -in in.tiny -log none > t2.txt 2>&1" &&
      grep -q '^Loop time' "$fresh/t2.txt"; then
      say "ok   bin-cpu/lmp -k on t 2 -sf kk runs"
    else
      say "FAIL bin-cpu/lmp -k on t 2: $(tail -n3 "$fresh/t2.txt" | paste -sd ' ')"
      fail=1
    fi
  fi
done
[ $fail = 0 ] && say "passed" || say "FAILED"
exit $fail
