#!/bin/bash
# kokkos-compile-check.sh BUILD_DIR [LAMMPS]
#
# Compiles every /kk style of POLYDEM (src/POLYDEM/*_kokkos.cpp) against a
# LAMMPS newer than Debian 12's Kokkos 3.4.01 allows (LAMMPS=2025: 4 Feb 2025,
# the default) and Kokkos 4.5.1's headers, host (Serial) backend: object
# files only, never linked or run. Kokkos 4.5.1 comes from sid's
# libtrilinos-kokkos-dev 16.1.0-5+b2 binary package, unpacked (not installed) into
# POLYDEM_CACHE_DIR by cmake/scripts/fetch-debian-deb.sh: its libraries need a newer
# glibc than Debian 12's, its headers serve. The build tree BUILD_DIR is
# LAMMPS + KOKKOS + POLYDEM configured by the top-level CMakeLists.txt; only
# the objects of the /kk styles (and generated headers) are built.
#
# Exits non-zero if any file fails, after showing its compiler output.
# Environment: POLYDEM_CACHE_DIR (default ~/.cache/polydem), POLYDEM_JOBS
# (default 2), POLYDEM_KK_CHECK_CMAKE_ARGS (extra configure arguments).
set -euo pipefail
{
if [ $# -lt 1 ]; then
  echo "usage: $0 BUILD_DIR [2025|2026]" >&2
  exit 2
fi
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
src=$(cd "$here/../.." && pwd)
build=$1
lammps=${2:-2025}
cache=${POLYDEM_CACHE_DIR:-$HOME/.cache/polydem}
jobs=${POLYDEM_JOBS:-2}
log() { echo "kokkos-compile-check: $*" >&2; }
t0=$(date +%s)

root=$(sh "$src/cmake/scripts/fetch-debian-deb.sh" sid "$cache/kokkos-4.5.1-deb" \
  libtrilinos-kokkos-dev=16.1.0-5+b2 libtrilinos-kokkos-16.1=16.1.0-5+b2 | tail -n1)
kdir=$(dirname "$(find "$root" -name KokkosConfig.cmake | head -n1)")
if [ ! -f "$kdir/KokkosConfig.cmake" ]; then
  log "no KokkosConfig.cmake in $root"
  exit 1
fi
log "Kokkos: $kdir"

mkdir -p "$build"
# shellcheck disable=SC2086
cmake -S "$src" -B "$build" -DPOLYDEM_LAMMPS="$lammps" -DPOLYDEM_KOKKOS=ON -DKokkos_DIR="$kdir" \
  -DPOLYDEM_ENABLE_TESTS=OFF -DPOLYDEM_BUILD_BENCH=OFF -DPOLYDEM_CUDA_CHECK=OFF \
  ${POLYDEM_KK_CHECK_CMAKE_ARGS:-} > "$build/polydem-kk-configure.log" 2>&1 || {
  cat "$build/polydem-kk-configure.log" >&2
  log "configuring $build failed"
  exit 1
}
log "configured $build [$(($(date +%s) - t0)) s]"

# generated headers a style might include (lmpgitversion.h is made at build time)
if make -C "$build/lammps" help 2> /dev/null | grep -q '\.\.\. gitversion$'; then
  make -C "$build/lammps" gitversion > /dev/null 2>&1 || true
fi

files=()
targets=()
for f in "$src"/src/POLYDEM/*_kokkos.cpp; do
  f=$(basename "$f")
  files+=("$f")
  targets+=("__/src/KOKKOS/${f%.cpp}.o")
done
# and LAMMPS's own files that instantiate the styles (new T(lmp) in the
# style creators: an abstract /kk class, a missed override, fails there)
core=(atom.cpp force.cpp modify.cpp)
for f in "${core[@]}"; do targets+=("__/src/${f%.cpp}.o"); done
objdir="$build/lammps/CMakeFiles/lammps.dir/__/src/KOKKOS"
coredir="$build/lammps/CMakeFiles/lammps.dir/__/src"
for f in "${files[@]}"; do rm -f "$objdir/$f.o"; done
for f in "${core[@]}"; do rm -f "$coredir/$f.o"; done
# one make for all objects (parallel, keep going): per-object targets of the
# Makefile generator
t1=$(date +%s)
make -C "$build/lammps" -k -j"$jobs" "${targets[@]}" > "$build/polydem-kk-compile.log" 2>&1 || true
failed=()
# check_objects DIR NOTE FILE...: each FILE's object in DIR, or FILE in failed
check_objects() {
  local dir=$1 note=$2 f
  shift 2
  for f in "$@"; do
    if [ -f "$dir/$f.o" ]; then
      log "ok      $f$note"
    else
      log "FAILED  $f$note"
      failed+=("$f")
    fi
  done
}
check_objects "$objdir" "" "${files[@]}"
check_objects "$coredir" " (LAMMPS's, instantiates the styles)" "${core[@]}"
if [ ${#failed[@]} -gt 0 ]; then
  grep -E 'error' "$build/polydem-kk-compile.log" | head -n 60 | sed 's/^/    /' >&2
  log "compiler output: $build/polydem-kk-compile.log"
fi
log "compiled in $(($(date +%s) - t1)) s"
if [ ${#failed[@]} -gt 0 ]; then
  log "${#failed[@]} of $((${#files[@]} + ${#core[@]})) file(s) FAILED against LAMMPS $lammps + Kokkos 4.5.1 [$(($(date +%s) - t0)) s]"
  exit 1
fi
log "all ${#files[@]} /kk file(s) and ${#core[@]} instantiating LAMMPS file(s) compile against LAMMPS $lammps + Kokkos 4.5.1 (Serial) [$(($(date +%s) - t0)) s]"
}
