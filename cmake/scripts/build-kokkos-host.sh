#!/bin/bash
# build-kokkos-host.sh CACHE_DIR VARIANT
#
# Builds Kokkos 3.4.01 for the CPU from Debian's trilinos source package
# (cmake/scripts/kokkos-source.sh) and installs it into CACHE_DIR/kokkos-VARIANT.
# Prints that prefix (last line of stdout); progress goes to stderr.
#
#   openmp  Serial + OpenMP, Release, C++17, PIC: the Kokkos that the default
#           build links (lmp -k on t N runs N OpenMP threads)
#   tsan    Serial + Threads (pthreads: ThreadSanitizer understands them,
#           libgomp is not instrumented), -fsanitize=thread -O1 -g,
#           Kokkos_ENABLE_DEBUG, DEBUG_BOUNDS_CHECK and
#           DEBUG_DUALVIEW_MODIFY_CHECK: unittest/scripts/tsan.sh
#
# Idempotent (stamp CACHE_DIR/kokkos-VARIANT/.polydem-stamp: the options and
# the compiler); concurrent runs serialise on a lock. ccache when present.
# Environment: POLYDEM_JOBS (default 2), CXX (default c++).
set -euo pipefail
{
# here, cache (CACHE_DIR, absolute): kokkos-cache.sh
kokkos_cache_usage="CACHE_DIR openmp|tsan"
# shellcheck source=SCRIPTDIR/kokkos-cache.sh
. "$(dirname "${BASH_SOURCE[0]}")/kokkos-cache.sh" "$@"
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
want_stamp="kokkos=3.4.01 variant=$variant opts=${opts[*]} cxx=$cxx:$("$cxx" -dumpfullversion) script=$(sha256sum "${BASH_SOURCE[0]}" | cut -c1-16)"
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
if [ "$variant" = tsan ]; then
  # Kokkos 3.4's Threads backend hands work and reductions between threads
  # through volatile int flags (m_pool_state) and spin loops: correct on x86,
  # but invisible to TSan, which then reports every handshake and all data
  # passed through it (4.x uses atomics). Make the flag accesses GCC atomic
  # builtins (release stores, acquire loads) in a copy of the source.
  tsrc="$cache/kokkos-tsan-src"
  rm -rf "$tsrc"
  cp -a "$src" "$tsrc"
  src=$tsrc
  T="$src/core/src/Threads"
  # stores: X.m_pool_state = ThreadsExec::S;  X->state() = ThreadsExec::S;
  sed -E -i 's/^(\s*)([^=;]*(m_pool_state|state\(\))) *= *(ThreadsExec::[A-Za-z]+);/\1__atomic_store_n(\&(\2), \4, __ATOMIC_RELEASE);/' \
    "$T"/Kokkos_ThreadsExec.cpp "$T"/Kokkos_ThreadsExec.hpp "$T"/Kokkos_ThreadsTeam.hpp
  # loads: the spin-wait loops and the two plain reads of a flag
  sed -E -i 's/while \(value (==|!=) flag\)/while (value \1 __atomic_load_n(\&flag, __ATOMIC_ACQUIRE))/' \
    "$src"/core/src/impl/Kokkos_Spinwait.hpp "$T"/Kokkos_ThreadsExec_base.cpp
  sed -E -i 's/ThreadsExec::Active == this_thread\.m_pool_state/ThreadsExec::Active == __atomic_load_n(\&this_thread.m_pool_state, __ATOMIC_ACQUIRE)/;
             s/if \(s_threads_process\.m_pool_state == ThreadsExec::Terminating\)/if (__atomic_load_n(\&s_threads_process.m_pool_state, __ATOMIC_ACQUIRE) == ThreadsExec::Terminating)/' \
    "$T"/Kokkos_ThreadsExec.cpp
  # the CAS loops of atomic_add etc. on double/float start from a plain read
  # of the target, which races (benignly: the CAS checks it) with the other
  # threads' CAS; make it an atomic relaxed load
  sed -E -i 's/^(\s*)oldval\.t = \*dest;/\1__atomic_load(dest, \&oldval.t, __ATOMIC_RELAXED);/' \
    "$src"/core/src/impl/Kokkos_Atomic_*.hpp
  left=$(grep -nE '(m_pool_state|state\(\)) *= *ThreadsExec::|while \(value [!=]= flag\)' \
           "$T"/*.cpp "$T"/*.hpp "$src"/core/src/impl/Kokkos_Spinwait.hpp || true)
  left+=$(grep -n 'oldval\.t = \*dest;' "$src"/core/src/impl/Kokkos_Atomic_*.hpp || true)
  if [ -n "$left" ]; then
    log "plain flag accesses left after the TSan edits:"; echo "$left" >&2; exit 1
  fi
  log "TSan edits: $(grep -c __ATOMIC_RELEASE "$T"/*.cpp "$T"/*.hpp | awk -F: '{s += $2} END {print s}') atomic stores"
fi
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
