#!/bin/bash
# build-kokkos-cuda.sh CACHE_DIR
#
# Builds Kokkos 3.4.01 for CUDA (sm_80) + Serial, for POLYDEM's CUDA compile
# check (compile only: no GPU is needed or used), and installs it into
# CACHE_DIR/kokkos-cuda. Prints that prefix on stdout (last line); progress
# goes to stderr.
#
#   source : packages/kokkos of Debian's trilinos 13.2.0-4 source package,
#            fetched with cmake/scripts/fetch-debian-source.sh into CACHE_DIR/src/trilinos
#            and extracted by cmake/scripts/kokkos-source.sh
#   patch  : cmake/scripts/kokkos-cuda13.patch (CUDA 13 fixes)
#   build  : CACHE_DIR/kokkos-cuda-build, compiler = Kokkos's bin/nvcc_wrapper
#            (installed as CACHE_DIR/kokkos-cuda/bin/nvcc_wrapper), ccache if present
#
# Idempotent: does nothing when the install is complete and was made from the
# same patch and options (stamp CACHE_DIR/kokkos-cuda/.polydem-stamp).
# Concurrent runs on the same CACHE_DIR serialise on a lock file.
#
# Environment: NVCC (default: nvcc on PATH, else /usr/local/cuda/bin/nvcc),
#              POLYDEM_JOBS (default 2), POLYDEM_CUDA_ARCH (default 80).
set -euo pipefail
# the whole script is one brace group: bash parses it before running it, so
# editing or checking out this file while it runs cannot derail the run
{

# the argument (CACHE_DIR: cache) and the Kokkos source: here, tri_version,
# patch_file, src (the patched packages/kokkos)
# shellcheck source=SCRIPTDIR/kokkos-cache.sh
. "$(dirname "${BASH_SOURCE[0]}")/kokkos-cache.sh" "$@"

jobs=${POLYDEM_JOBS:-2}
arch=${POLYDEM_CUDA_ARCH:-80}
case $arch in
  70) arch_opt=Kokkos_ARCH_VOLTA70 ;;
  75) arch_opt=Kokkos_ARCH_TURING75 ;;
  80) arch_opt=Kokkos_ARCH_AMPERE80 ;;
  86) arch_opt=Kokkos_ARCH_AMPERE86 ;;
  *) echo "build-kokkos-cuda: unsupported POLYDEM_CUDA_ARCH=$arch (70, 75, 80, 86)" >&2; exit 2 ;;
esac

build="$cache/kokkos-cuda-build"
prefix="$cache/kokkos-cuda"
stamp="$prefix/.polydem-stamp"

log() { echo "build-kokkos-cuda: $*" >&2; }
cmake=${CMAKE:-cmake}

# nvcc: nvcc_wrapper calls `nvcc` from PATH
if [ -n "${NVCC:-}" ]; then
  PATH="$(dirname "$NVCC"):$PATH"
elif ! command -v nvcc > /dev/null 2>&1 && [ -x /usr/local/cuda/bin/nvcc ]; then
  PATH="/usr/local/cuda/bin:$PATH"
fi
export PATH
if ! command -v nvcc > /dev/null 2>&1; then
  log "nvcc not found (set NVCC or put it on PATH)"
  exit 1
fi
nvcc_path=$(command -v nvcc)
nvcc_version=$(nvcc --version | sed -n 's/.*release \([0-9.]*\).*/\1/p')
# the compiler's identity, not its path (/usr/local/bin/nvcc may be a script
# running /usr/local/cuda/bin/nvcc)
nvcc_build=$(nvcc --version | sed -n 's/^Build //p')

patch_sum=$(sha256sum "$patch_file" | cut -d' ' -f1)
# what the stamp certifies; any change rebuilds
want_stamp="kokkos=3.4.01 trilinos=$tri_version patch=$patch_sum arch=sm_$arch nvcc=$nvcc_version:$nvcc_build"

if [ -f "$stamp" ] && [ "$(head -n1 "$stamp")" = "$want_stamp" ] &&
  [ -f "$prefix/lib/cmake/Kokkos/KokkosConfig.cmake" ] && [ -x "$prefix/bin/nvcc_wrapper" ]; then
  log "up to date: $prefix"
  echo "$prefix"
  exit 0
fi

exec 9> "$cache/.kokkos-cuda.lock"
log "taking the lock $cache/.kokkos-cuda.lock"
flock 9
# another run may have finished while we waited
if [ -f "$stamp" ] && [ "$(head -n1 "$stamp")" = "$want_stamp" ] &&
  [ -f "$prefix/lib/cmake/Kokkos/KokkosConfig.cmake" ] && [ -x "$prefix/bin/nvcc_wrapper" ]; then
  log "up to date: $prefix"
  echo "$prefix"
  exit 0
fi

t0=$(date +%s)

# --- 1. source: only packages/kokkos, patched (cmake/scripts/kokkos-source.sh) ----
old_src_sum=$(cat "$src/.polydem-patched" 2>/dev/null || true)
"$here/kokkos-source.sh" "$cache" > /dev/null
if [ "$old_src_sum" != "$patch_sum" ]; then
  rm -rf "$build"    # configured from the old tree
fi

# --- 2. configure + build + install ------------------------------------------
launcher=()
if command -v ccache > /dev/null 2>&1; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER="$(command -v ccache)")
fi

configure() {    # $1 = C++ standard
  rm -rf "$build"
  "$cmake" -S "$src" -B "$build" \
    -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_INSTALL_PREFIX="$prefix" \
    -DCMAKE_CXX_COMPILER="$src/bin/nvcc_wrapper" \
    -DCMAKE_CXX_FLAGS="-arch=sm_$arch" \
    -DCMAKE_CXX_STANDARD="$1" \
    -DCMAKE_CXX_EXTENSIONS=OFF \
    -DCMAKE_POSITION_INDEPENDENT_CODE=ON \
    "${launcher[@]}" \
    -DKokkos_ENABLE_CUDA=ON \
    -DKokkos_ENABLE_SERIAL=ON \
    -DKokkos_ENABLE_OPENMP=OFF \
    -DKokkos_ENABLE_CUDA_LAMBDA=ON \
    -DKokkos_ENABLE_TESTS=OFF \
    -DKokkos_ENABLE_EXAMPLES=OFF \
    -D"$arch_opt"=ON >&2
}

rm -rf "$prefix"
std=""
for s in 17 14; do
  log "configuring (C++$s, sm_$arch, $nvcc_path $nvcc_version)"
  if configure "$s" && "$cmake" --build "$build" -j "$jobs" >&2; then
    std=$s
    break
  fi
  log "C++$s failed"
done
if [ -z "$std" ]; then
  log "Kokkos CUDA build failed (see the output above)"
  exit 1
fi
"$cmake" --install "$build" >&2

# sanity: the installed wrapper and config are what the check uses
[ -x "$prefix/bin/nvcc_wrapper" ] || { log "no $prefix/bin/nvcc_wrapper after install"; exit 1; }
[ -f "$prefix/lib/cmake/Kokkos/KokkosConfig.cmake" ] || { log "no KokkosConfig.cmake after install"; exit 1; }

{
  echo "$want_stamp"
  echo "cxx_standard=$std"
  echo "built=$(date -u +%Y-%m-%dT%H:%M:%SZ) seconds=$(($(date +%s) - t0))"
} > "$stamp"
log "installed in $prefix (C++$std, $(($(date +%s) - t0)) s)"
echo "$prefix"
exit 0
}
