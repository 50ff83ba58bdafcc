#!/bin/bash
# bundle.sh [OUT.tar.gz]   (default: polydem-gpu-kit.tar.gz in the current folder)
#
# Writes the GPU run kit (issue 19): one archive with everything a GPU node
# needs to build and validate POLYDEM there (CUDA nvcc, CMake, a C++ compiler,
# python3; no network, no MPI, no CGAL/GMP/MPFR/Boost/GoogleTest):
#
#   polydem-gpu-kit/
#     run.sh      the kit's one command (tools/gpu/run.sh)
#     polydem/    this repository at HEAD (git archive) + the meshes the checks use
#                 (tools/gpu/data: floor10k.stl, examples/silo's silo.stl, lid.stl)
#     lammps/     the LAMMPS source POLYDEM builds against (29 Sep 2021, Debian's
#                 source package): top-level src/ files, KOKKOS, ASPHERE,
#                 GRANULAR, STUBS (MPI stubs), fmt, cmake/
#     kokkos/     Kokkos 3.4.01 (Debian's trilinos source) with our CUDA 13 patch
#     deps/       CGAL, Boost (the headers our shape code includes), GMP and MPFR
#                 (headers and x86-64 shared libraries, glibc >= 2.14)
#     MANIFEST    versions and sources
#
# Run where the packages are reachable (the build machine): it uses the caches of
# the normal build (LAMMPS source, Kokkos source) and fetches what is missing.
#
# bundle.sh --prebuilt DIR [--cuda-only | --cpu-only] [--jobs N]
#
# Builds here instead (CUDA nvcc needs no GPU) and writes into DIR a ready
# run (tools/gpu/prebuild.sh): the executables (lmp with KOKKOS + POLYDEM +
# MPI stubs, the kernel check) for CUDA and for Kokkos OpenMP, the shared
# libraries a bare x86-64 Linux may lack, the inputs, meshes and shapes, the
# plain styles' reference logs (computed here) and run.sh; then checks it in
# a bare environment (check_bare.sh). On a GPU node:
# `bash DIR/run.sh OUT --limit 300`; without a GPU: `bash DIR/run.sh OUT --cpu`.
# The build folders stay in the cache (POLYDEM_CACHE_DIR/gpu-prebuilt), so a
# second bundle recompiles only what changed. DIR must not exist or be empty.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo=$(cd "$here/../.." && pwd)
prebuilt="" pmodes=(cuda cpu) pjobs=$(nproc) out=""
while [ $# -gt 0 ]; do
  case $1 in
    --prebuilt) prebuilt=$(realpath -m "$2"); shift ;;
    --cuda-only) pmodes=(cuda) ;;
    --cpu-only) pmodes=(cpu) ;;
    --jobs) pjobs=$2; shift ;;
    -*) echo "bundle.sh: unknown option $1" >&2; exit 2 ;;
    *) out=$(realpath -m "$1") ;;
  esac
  shift
done
[ -z "$prebuilt" ] && [ -z "$out" ] && out=$(realpath -m polydem-gpu-kit.tar.gz)
if [ -n "$prebuilt" ] && [ -e "$prebuilt" ] && [ -n "$(ls -A "$prebuilt")" ]; then
  echo "bundle.sh: $prebuilt exists and is not empty" >&2
  exit 2
fi
cache=${POLYDEM_CACHE_DIR:-$HOME/.cache/polydem}
log() { echo "bundle: $*" >&2; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
kit="$work/polydem-gpu-kit"
mkdir -p "$kit"

# --- POLYDEM -------------------------------------------------------------------
log "POLYDEM $(git -C "$repo" rev-parse --short HEAD)"
mkdir -p "$kit/polydem"
git -C "$repo" archive HEAD | tar -x -C "$kit/polydem"
cp "$here/run.sh" "$kit/run.sh"
# the meshes of the benchmarks, made here (the node may lack numpy)
mkdir -p "$kit/polydem/tools/gpu/data"
(cd "$repo/bench/wall_mesh" &&
  { [ -f floor10k.stl ] || python3 make_floor.py floor10k.stl 71; } &&
  cp floor10k.stl "$kit/polydem/tools/gpu/data/")
(cd "$kit/polydem/tools/gpu/data" && python3 "$repo/examples/silo/make_silo.py" silo.stl lid.stl > /dev/null)

# --- LAMMPS ----------------------------------------------------------------------
lmp_ver=20220106.git7586adbb6a+ds1-2
lmp_cache="$cache/lammps-$lmp_ver"
if [ ! -f "$lmp_cache/.extracted" ]; then
  log "fetching the LAMMPS source (Debian lammps $lmp_ver)"
  tarball=$(bash "$repo/cmake/scripts/fetch-debian-source.sh" lammps "$lmp_ver" "$lmp_cache/download" | head -n1)
  mkdir -p "$lmp_cache/src"
  tar -xf "$tarball" -C "$lmp_cache/src"
  touch "$lmp_cache/.extracted"
fi
lsrc=$(find "$lmp_cache/src" -mindepth 1 -maxdepth 1 -type d | head -n1)
log "LAMMPS from $lsrc"
mkdir -p "$kit/lammps/src"
cp -r "$lsrc/cmake" "$kit/lammps/"
cp "$lsrc/LICENSE" "$lsrc/README" "$kit/lammps/"
find "$lsrc/src" -maxdepth 1 -type f -exec cp {} "$kit/lammps/src/" \;
for p in KOKKOS ASPHERE GRANULAR STUBS fmt; do cp -r "$lsrc/src/$p" "$kit/lammps/src/"; done

# --- Kokkos ------------------------------------------------------------------------
ksrc=$(bash "$repo/cmake/scripts/kokkos-source.sh" "$cache" | tail -n1)    # fetched and patched if missing
mkdir -p "$kit/kokkos"
(cd "$ksrc" && tar -c --exclude=./doc --exclude=./benchmarks \
  --exclude='./*/unit_test' --exclude='./*/unit_tests' --exclude='./*/perf_test' . ) |
  tar -x -C "$kit/kokkos"

# --- CGAL, Boost, GMP, MPFR ---------------------------------------------------------
# exactly the headers the shape code includes (the compiler's dependency
# list), plus Boost's configuration headers (they differ by compiler)
log "CGAL/Boost/GMP/MPFR headers and libraries"
mkdir -p "$kit/deps/include" "$kit/deps/lib"
g++ -std=c++17 -M -I"$repo/src/POLYDEM" "$repo"/src/POLYDEM/polydem_shape_*.cpp |
  tr ' \\' '\n\n' | grep -E '^/usr/include/(CGAL|boost)/' | sort -u > "$work/headers"
(cd /usr/include && sed 's|^/usr/include/||' "$work/headers" | tar -c -T - boost/config boost/predef \
  boost/config.hpp boost/version.hpp mpfr.h) | tar -x -C "$kit/deps/include"
cp /usr/include/x86_64-linux-gnu/gmp.h "$kit/deps/include/"
for l in libgmp.so.10 libmpfr.so.6; do
  real=$(readlink -f "/usr/lib/x86_64-linux-gnu/$l")
  cp "$real" "$kit/deps/lib/"
  ln -sf "$(basename "$real")" "$kit/deps/lib/$l"
  ln -sf "$l" "$kit/deps/lib/${l%%.so.*}.so"
done

{
  echo "POLYDEM GPU run kit, made $(date -u +%Y-%m-%dT%H:%M:%SZ) on $(uname -m)"
  echo "polydem  $(git -C "$repo" rev-parse HEAD)$(git -C "$repo" diff --quiet HEAD || echo ' (+ uncommitted changes not in the kit)')"
  echo "lammps   Debian source package lammps $lmp_ver (29 Sep 2021, Update 2)"
  echo "kokkos   3.4.01 from Debian's trilinos 13.2.0-4 source + cmake/scripts/kokkos-cuda13.patch"
  echo "cgal     $(dpkg-query -W -f='${Version}' libcgal-dev 2> /dev/null) (headers used by polydem_shape_*.cpp)"
  echo "boost    $(dpkg-query -W -f='${Version}' libboost-dev 2> /dev/null) (headers used by CGAL)"
  echo "gmp      $(dpkg-query -W -f='${Version}' libgmp10 2> /dev/null) (libgmp.so.10)"
  echo "mpfr     $(dpkg-query -W -f='${Version}' libmpfr6 2> /dev/null) (libmpfr.so.6)"
} > "$kit/MANIFEST"

if [ -n "$prebuilt" ]; then
  t0=$(date +%s)
  bash "$here/prebuild.sh" "$kit" "$cache/gpu-prebuilt" "$prebuilt" "$pjobs" "${pmodes[@]}"
  size=$(du -sm "$prebuilt" | cut -f1)
  log "prebuilt run ${pmodes[*]} in $prebuilt: $size MiB, $(($(date +%s) - t0)) s"
  [ "$size" -le 60 ] || { log "larger than 60 MiB"; exit 1; }
  echo "$prebuilt"
  exit 0
fi

log "writing $out"
tar -C "$work" -czf "$out" polydem-gpu-kit
size=$(stat -c %s "$out")
log "$(basename "$out"): $((size / 1024 / 1024)) MiB ($size bytes)"
if [ "$size" -gt $((60 * 1024 * 1024)) ]; then
  log "larger than 60 MiB"
  exit 1
fi
echo "$out"
