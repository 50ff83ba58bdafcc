#!/bin/bash
# cuda-compile-check.sh SRC_DIR CACHE_DIR FILE...
#
# POLYDEM's CUDA compile check: compiles each FILE for CUDA (sm_80) with
# Kokkos 3.4.01's nvcc_wrapper, object only (-c). Never links or runs (no GPU
# is needed). Exits non-zero if any file fails, after showing the compiler
# output of every failing file.
#
#   SRC_DIR    the POLYDEM source tree (top-level CMakeLists.txt), or a plain
#              LAMMPS source tree (src/, cmake/), e.g. to try LAMMPS's own
#              KOKKOS styles
#   CACHE_DIR  where Kokkos for CUDA is built (cmake/scripts/build-kokkos-cuda.sh)
#   FILE       two kinds:
#     *_kokkos.cpp  LAMMPS KOKKOS styles: compiled with the exact command of a
#                   second build tree of SRC_DIR configured with nvcc_wrapper and
#                   this Kokkos (LAMMPS include dirs, generated style headers,
#                   -DLMP_KOKKOS -DLAMMPS_SMALLBIG, MPI, ...). Only the object
#                   files of the FILEs are built. FILE may be the file in
#                   src/POLYDEM or its staged link; for a LAMMPS tree, any
#                   source of it.
#     anything else standalone translation units (e.g. unittest/cuda/kernels_cuda.cpp):
#                   compiled with Kokkos's flags, -I SRC_DIR/src/POLYDEM,
#                   -DPOLYDEM_USE_KOKKOS -DPOLYDEM_REQUIRE_CUDA
#
# Host/device mistakes that nvcc only warns about are made errors: calling a
# __device__ function from __host__ __device__ code (cudafe diagnostics 20007,
# 20008) or a __host__ one (20011, 20013-20015); LAMMPS's own KOKKOS styles
# (pair lj/cut, gran/hooke/history, fix nve, nve/sphere, atom_vec sphere)
# compile cleanly with these.
#
# Environment:
#   POLYDEM_CUDA_CHECK_BUILD_DIR   the second build tree (default:
#                                  CACHE_DIR/cuda-check-build/<hash of SRC_DIR + options>)
#   POLYDEM_CUDA_CHECK_CMAKE_ARGS  extra arguments for configuring it
#                                  (e.g. -DLAMMPS_SOURCE_DIR=/path)
#   POLYDEM_JOBS                   parallel compiles (default 2)
#   NVCC                           nvcc to use (default: PATH, then /usr/local/cuda/bin)
set -euo pipefail
# the whole script is one brace group: bash parses it before running it, so
# editing or checking out this file while it runs cannot derail the run
{

if [ $# -lt 3 ]; then
  echo "usage: $0 SRC_DIR CACHE_DIR FILE..." >&2
  exit 2
fi
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
srcdir=$(cd "$1" && pwd)
mkdir -p "$2"
cache=$(cd "$2" && pwd)
shift 2
jobs=${POLYDEM_JOBS:-2}

log() { echo "cuda-compile-check: $*" >&2; }
now() { date +%s.%N; }
elapsed() { awk -v a="$1" -v b="$(now)" 'BEGIN { printf "%.1f", b - a }'; }

t_start=$(now)

if [ -n "${NVCC:-}" ]; then
  PATH="$(dirname "$NVCC"):$PATH"
elif ! command -v nvcc > /dev/null 2>&1 && [ -x /usr/local/cuda/bin/nvcc ]; then
  PATH="/usr/local/cuda/bin:$PATH"
fi
export PATH

# --- inputs --------------------------------------------------------------------
kk_files=()
tu_files=()
for f in "$@"; do
  if [ ! -f "$f" ]; then
    log "no such file: $f"
    exit 2
  fi
  f=$(cd "$(dirname "$f")" && pwd)/$(basename "$f")
  case $f in
    *_kokkos.cpp) kk_files+=("$f") ;;
    *) tu_files+=("$f") ;;
  esac
done

# --- 1. Kokkos for CUDA --------------------------------------------------------
t0=$(now)
prefix=$("$here/../../cmake/scripts/build-kokkos-cuda.sh" "$cache" | tail -n1)
wrapper="$prefix/bin/nvcc_wrapper"
std=$(sed -n 's/^cxx_standard=//p' "$prefix/.polydem-stamp")
arch=$(sed -n 's/.* arch=sm_\([0-9]*\) .*/\1/p' "$prefix/.polydem-stamp")
log "Kokkos CUDA: $prefix (C++$std, sm_$arch) [$(elapsed "$t0") s]"

launcher=()
if command -v ccache > /dev/null 2>&1; then
  launcher=(ccache)
fi
# nvcc only warns when host code is called from device code; make it an error
diag_flags=(-Xcudafe "--diag_error=20007,--diag_error=20008,--diag_error=20011,--diag_error=20013,--diag_error=20014,--diag_error=20015")

# compile jobs: each writes its output to a log; at most $jobs at once
work="${TMPDIR:-/tmp}/polydem-cuda-check.$$"
mkdir -p "$work"
trap 'rm -rf "$work"' EXIT
names=()
failed=()
running=0

start_job() {    # name dir command...
  local name=$1 dir=$2
  shift 2
  names+=("$name")
  local id=${#names[@]}
  (
    ts=$(now)
    cd "$dir"
    if "$@" > "$work/$id.log" 2>&1; then
      echo 0 > "$work/$id.rc"
    else
      echo 1 > "$work/$id.rc"
    fi
    elapsed "$ts" > "$work/$id.time"
  ) &
  running=$((running + 1))
  if [ $running -ge "$jobs" ]; then
    wait -n || true
    running=$((running - 1))
  fi
}

report_jobs() {
  wait || true
  running=0
  local i id rc
  for i in "${!names[@]}"; do
    id=$((i + 1))
    [ -f "$work/$id.reported" ] && continue
    touch "$work/$id.reported"
    rc=$(cat "$work/$id.rc" 2> /dev/null || echo 1)
    if [ "$rc" = 0 ]; then
      log "ok      ${names[$i]} [$(cat "$work/$id.time") s]"
      if [ -s "$work/$id.log" ]; then
        sed 's/^/    /' "$work/$id.log" >&2
      fi
    else
      log "FAILED  ${names[$i]} [$(cat "$work/$id.time" 2> /dev/null || echo ?) s]"
      sed 's/^/    /' "$work/$id.log" >&2
      failed+=("${names[$i]}")
    fi
  done
}

# --- 2. standalone translation units ---------------------------------------------
if [ ${#tu_files[@]} -gt 0 ]; then
  objdir="$cache/cuda-check-objs"
  mkdir -p "$objdir"
  for f in "${tu_files[@]}"; do
    obj="$objdir/$(basename "$f" .cpp)-$(echo "$f" | sha256sum | cut -c1-8).o"
    start_job "$f" "$(dirname "$f")" "${launcher[@]}" "$wrapper" \
      -std="c++$std" -arch="sm_$arch" -expt-extended-lambda -Wext-lambda-captures-this \
      "${diag_flags[@]}" -DPOLYDEM_USE_KOKKOS -DPOLYDEM_REQUIRE_CUDA \
      -I"$srcdir/src/POLYDEM" -isystem "$prefix/include" -c "$f" -o "$obj"
  done
  report_jobs
fi

# --- 3. LAMMPS KOKKOS styles ---------------------------------------------------------
if [ ${#kk_files[@]} -gt 0 ]; then
  if [ -f "$srcdir/cmake/CMakeLists.txt" ] && [ -f "$srcdir/src/atom.cpp" ]; then
    # a plain LAMMPS tree
    cmake_src="$srcdir/cmake"
    cfg_args=(-DPKG_KOKKOS=ON -DEXTERNAL_KOKKOS=ON -DPKG_ASPHERE=ON -DPKG_GRANULAR=ON
      -DBUILD_MPI=ON -DBUILD_OMP=OFF -DLAMMPS_EXCEPTIONS=ON)
  elif [ -f "$srcdir/CMakeLists.txt" ]; then
    # the POLYDEM project: LAMMPS + POLYDEM, without tests and benchmarks
    cmake_src="$srcdir"
    cfg_args=(-DPOLYDEM_ENABLE_TESTS=OFF -DPOLYDEM_BUILD_BENCH=OFF -DPOLYDEM_CUDA_CHECK=OFF
      -DPOLYDEM_CACHE_DIR="$cache")
  else
    log "$srcdir is neither the POLYDEM tree nor a LAMMPS tree"
    exit 2
  fi
  # shellcheck disable=SC2206
  cfg_args+=(-G "Unix Makefiles"
    -DCMAKE_BUILD_TYPE=None
    -DCMAKE_CXX_COMPILER="$wrapper"
    -DCMAKE_CXX_FLAGS="-arch=sm_$arch"
    -DCMAKE_CXX_STANDARD="$std"
    -DBUILD_SHARED_LIBS=ON
    -DCMAKE_EXPORT_COMPILE_COMMANDS=ON
    -DKokkos_DIR="$prefix/lib/cmake/Kokkos"
    ${POLYDEM_CUDA_CHECK_CMAKE_ARGS:-})
  want="$(printf '%s\n' "$cmake_src" "$(head -n1 "$prefix/.polydem-stamp")" "${cfg_args[@]}")"
  # default: in the cache, one tree per source tree and configuration, so that
  # a fresh build directory of the same checkout is warm too
  build=${POLYDEM_CUDA_CHECK_BUILD_DIR:-$cache/cuda-check-build/$(echo "$want" | sha256sum | cut -c1-12)}
  mkdir -p "$build"
  build=$(cd "$build" && pwd)

  t0=$(now)
  exec 8> "$build/.lock"
  flock 8
  if [ -f "$build/CMakeCache.txt" ] && [ -f "$build/.polydem-cfg" ] &&
    [ "$(cat "$build/.polydem-cfg")" = "$want" ] && [ -f "$build/compile_commands.json" ]; then
    # re-runs cmake only if a CMakeLists, a CONFIGURE_DEPENDS glob... changed
    log "checking the CUDA build tree $build"
    if ! make -C "$build" cmake_check_build_system > "$work/cfg.log" 2>&1; then
      cat "$work/cfg.log" >&2
      log "re-configuring $build failed"
      exit 1
    fi
  else
    log "configuring the CUDA build tree $build"
    rm -f "$build/CMakeCache.txt" "$build/.polydem-cfg"
    if ! "${CMAKE:-cmake}" -S "$cmake_src" -B "$build" "${cfg_args[@]}" > "$work/cfg.log" 2>&1; then
      cat "$work/cfg.log" >&2
      log "configuring $build failed"
      exit 1
    fi
    echo "$want" > "$build/.polydem-cfg"
  fi
  log "CUDA build tree ready [$(elapsed "$t0") s]"

  # the compile command of each file, from compile_commands.json; FILEs and
  # entries are compared after resolving links (the staged tree links to src/POLYDEM)
  if ! python3 - "$build/compile_commands.json" "$work/cmds" "${kk_files[@]}" <<'EOF'; then
import json, os, shlex, sys
db, out, files = sys.argv[1], sys.argv[2], sys.argv[3:]
entries = {}
for e in json.load(open(db)):
    path = os.path.join(e["directory"], e["file"])
    entries.setdefault(os.path.realpath(path), e)
missing = []
os.makedirs(out, exist_ok=True)
for i, f in enumerate(files):
    e = entries.get(os.path.realpath(f))
    if e is None:
        missing.append(f)
        continue
    args = e.get("arguments") or shlex.split(e["command"])
    with open(os.path.join(out, "%d.dir" % i), "w") as fh:
        fh.write(e["directory"])
    with open(os.path.join(out, "%d.args" % i), "wb") as fh:
        fh.write(b"\0".join(a.encode() for a in args) + b"\0")
if missing:
    sys.stderr.write("cuda-compile-check: not compiled by the CUDA build tree (not staged into "
                     "LAMMPS, or its package is off):\n  " + "\n  ".join(missing) + "\n")
    sys.exit(1)
EOF
    exit 1
  fi

  # generated headers a style might include (lmpgitversion.h is made at build time)
  if make -C "$build" help 2> /dev/null | grep -q '\.\.\. gitversion$'; then
    make -C "$build" gitversion > /dev/null 2>&1 || true
  fi

  # paths inside the (hash-named) tree count as relative for ccache, so a
  # re-created tree still hits the cache
  kk_launcher=("${launcher[@]}")
  if [ ${#launcher[@]} -gt 0 ] && [ -z "${CCACHE_BASEDIR:-}" ]; then
    kk_launcher=(env CCACHE_BASEDIR="$build" "${launcher[@]}")
  fi
  for i in "${!kk_files[@]}"; do
    mapfile -d '' args < "$work/cmds/$i.args"
    start_job "${kk_files[$i]}" "$(cat "$work/cmds/$i.dir")" "${kk_launcher[@]}" "${args[@]}" "${diag_flags[@]}"
  done
  report_jobs
fi

total=$(( ${#tu_files[@]} + ${#kk_files[@]} ))
if [ ${#failed[@]} -gt 0 ]; then
  log "${#failed[@]} of $total file(s) FAILED to compile for CUDA [$(elapsed "$t_start") s]:"
  printf '  %s\n' "${failed[@]}" >&2
  exit 1
fi
log "all $total file(s) compile for CUDA (sm_$arch, C++$std) [$(elapsed "$t_start") s]"
exit 0
}
