#!/bin/bash
# build-kokkos-host.sh CACHE_DIR VARIANT
#
# Builds Kokkos 3.4.01 for the CPU from Debian's trilinos source package
# (tools/kokkos-source.sh) and installs it into CACHE_DIR/kokkos-VARIANT.
# Prints that prefix (last line of stdout); progress goes to stderr.
#
#   openmp  Serial + OpenMP, Release, C++17, PIC: the Kokkos that the default
#           build links (lmp -k on t N runs N OpenMP threads)
#   tsan    Serial + Threads (pthreads: ThreadSanitizer understands them,
#           libgomp is not instrumented), -fsanitize=thread -O1 -g,
#           Kokkos_ENABLE_DEBUG, DEBUG_BOUNDS_CHECK and
#           DEBUG_DUALVIEW_MODIFY_CHECK: tools/tsan.sh
#
# Idempotent (stamp CACHE_DIR/kokkos-VARIANT/.polydem-stamp: the options and
# the compiler); concurrent runs serialise on a lock. ccache when present.
# Environment: POLYDEM_JOBS (default 2), CXX (default c++).
set -euo pipefail
{
if [ $# -ne 2 ]; then
  echo "usage: $0 CACHE_DIR openmp|tsan" >&2
  exit 2
fi
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
mkdir -p "$1"
cache=$(cd "$1" && pwd)
variant=$2
jobs=${POLYDEM_JOBS:-2}
cxx=$(command -v "${CXX:-c++}")
cmake=${CMAKE:-cmake}
log() { echo "build-kokkos-host: $*" >&2; }

case $variant in
  openmp)
    opts=(-DCMAKE_BUILD_TYPE=Release -DKokkos_ENABLE_SERIAL=ON -DKokkos_ENABLE_OPENMP=ON) ;;
  tsan)
    opts=(-DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS=-fsanitize=thread -O1 -g"
          "-DCMAKE_EXE_LINKER_FLAGS=-fsanitize=thread" "-DCMAKE_SHARED_LINKER_FLAGS=-fsanitize=thread"
          -DKokkos_ENABLE_SERIAL=ON -DKokkos_ENABLE_PTHREAD=ON
          -DKokkos_ENABLE_DEBUG=ON -DKokkos_ENABLE_DEBUG_BOUNDS_CHECK=ON
          -DKokkos_ENABLE_DEBUG_DUALVIEW_MODIFY_CHECK=ON) ;;
  *) echo "build-kokkos-host: unknown VARIANT '$variant' (openmp, tsan)" >&2; exit 2 ;;
esac

build="$cache/kokkos-$variant-build"
prefix="$cache/kokkos-$variant"
stamp="$prefix/.polydem-stamp"
want_stamp="kokkos=3.4.01 variant=$variant opts=${opts[*]} cxx=$cxx:$("$cxx" -dumpfullversion)"
done_() {
  [ -f "$stamp" ] && [ "$(head -n1 "$stamp")" = "$want_stamp" ] &&
    [ -f "$prefix/lib/cmake/Kokkos/KokkosConfig.cmake" ]
}
if done_; then
  log "up to date: $prefix"
  echo "$prefix"
  exit 0
fi
exec 9> "$cache/.kokkos-$variant.lock"
flock 9
if done_; then
  echo "$prefix"
  exit 0
fi
t0=$(date +%s)
src=$("$here/kokkos-source.sh" "$cache" | tail -n1)
launcher=()
if command -v ccache > /dev/null 2>&1; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER="$(command -v ccache)")
fi
rm -rf "$build" "$prefix"
log "configuring $variant in $build"
"$cmake" -S "$src" -B "$build" \
  -DCMAKE_INSTALL_PREFIX="$prefix" -DCMAKE_INSTALL_LIBDIR=lib \
  -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_CXX_STANDARD=17 -DCMAKE_CXX_EXTENSIONS=OFF \
  -DCMAKE_POSITION_INDEPENDENT_CODE=ON "${launcher[@]}" \
  -DKokkos_ENABLE_TESTS=OFF -DKokkos_ENABLE_EXAMPLES=OFF "${opts[@]}" >&2
"$cmake" --build "$build" -j "$jobs" >&2
"$cmake" --install "$build" >&2
[ -f "$prefix/lib/cmake/Kokkos/KokkosConfig.cmake" ] || { log "no KokkosConfig.cmake after install"; exit 1; }
{
  echo "$want_stamp"
  echo "built=$(date -u +%Y-%m-%dT%H:%M:%SZ) seconds=$(($(date +%s) - t0))"
} > "$stamp"
log "installed in $prefix ($(($(date +%s) - t0)) s)"
echo "$prefix"
exit 0
}
