#!/bin/bash
# run.sh OUTDIR [--cpu] [--build-only] [--jobs N] [--limit SECONDS] [--threads N]
#
# The GPU run kit's one command (issue 19), run from an unpacked kit
# (tools/gpu/bundle.sh):
#
#   tar xzf polydem-gpu-kit.tar.gz && bash polydem-gpu-kit/run.sh /path/to/out
#
# On a node with an NVIDIA GPU, nvcc (CUDA >= 11; 13 tested for compiling),
# CMake >= 3.16, a C++17 compiler and python3 (no MPI, no network) it builds
# Kokkos 3.4.01 for CUDA (sm_80 code + PTX: Kokkos 3.4 cannot name Hopper,
# the driver JIT-compiles the PTX for sm_90) and LAMMPS + POLYDEM with the
# KOKKOS package and LAMMPS's MPI stubs, then runs, in this order:
#   kernels   the header-only kernels on the device against the host
#   kk_pair, kk_wall, kk_ellipsoid
#             /kk on the GPU against the plain styles on the CPU, judged
#             against the run's own sensitivity (compare_runs.py)
#   example   the main example (examples/hopper) with -sf kk
#   memcheck, racecheck
#             compute-sanitizer on a small pair and wall case (if present)
#   bench_*   dense dodecahedra at N = 1e5 and 1e6, the silo: particle-steps/s
# and writes OUTDIR/summary.txt (one line per step: PASS / FAIL / SKIP,
# seconds, figures) and each step's log. It stops starting steps when the
# time limit (default 570 s, including the build) would be passed, and says
# which it skipped.
#
#   --cpu         the same on the CPU: Kokkos OpenMP + Serial, -k on t N
#                 (no compute-sanitizer); this is how the kit is verified
#                 on a machine without a GPU
#   --build-only  build (and, with CUDA, link) and stop
#   --jobs N      parallel compiles (default: all cores)
#   --threads N   OpenMP threads of --cpu runs (default 2)
#   --limit S     time limit in seconds (default 570)
# Environment: POLYDEM_KIT_WORK (build folder, default: KIT/work),
#              NVCC, CXX (host compiler), POLYDEM_CUDA_ARCH (default 80).
set -uo pipefail
kit=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
if [ ! -d "$kit/polydem" ] || [ ! -d "$kit/lammps" ] || [ ! -d "$kit/kokkos" ]; then
  echo "run.sh: $kit is not an unpacked GPU run kit (make one with tools/gpu/bundle.sh)" >&2
  exit 2
fi
if [ $# -lt 1 ]; then
  sed -n '2,4p' "$0" >&2
  exit 2
fi
out=$(mkdir -p "$1" && cd "$1" && pwd)
shift
mode=cuda build_only=0 jobs=$(nproc) threads=2 limit=570
while [ $# -gt 0 ]; do
  case $1 in
    --cpu) mode=cpu ;;
    --build-only) build_only=1 ;;
    --jobs) jobs=$2; shift ;;
    --threads) threads=$2; shift ;;
    --limit) limit=$2; shift ;;
    *) echo "run.sh: unknown option $1" >&2; exit 2 ;;
  esac
  shift
done
t_start=$(date +%s)
work=${POLYDEM_KIT_WORK:-$kit/work}
mkdir -p "$work"
src=$kit/polydem
summary=$out/summary.txt
: > "$summary"
export LD_LIBRARY_PATH="$kit/deps/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
export OMP_PROC_BIND=false OMP_NUM_THREADS=$threads

elapsed() { echo $(($(date +%s) - t_start)); }
left() { echo $((limit - $(elapsed))); }
note() { echo "$*" | tee -a "$summary"; }
# step NAME MIN_SECONDS MAX_SECONDS COMMAND...: runs COMMAND (log OUT/NAME.log)
# unless fewer than MIN_SECONDS are left; at most MAX_SECONDS (and the time
# left), then the command and everything it started is killed
kill_tree() {
  local c
  for c in $(pgrep -P "$1" 2> /dev/null); do kill_tree "$c" "$2"; done
  kill "-$2" "$1" 2> /dev/null
}
step() {
  local name=$1 need=$2 max=$3
  shift 3
  local l
  l=$(left)
  if [ "$l" -lt "$need" ]; then
    note "SKIP  $name (needs ~${need} s, ${l} s left)"
    return 1
  fi
  [ "$max" -gt "$((l - 5))" ] && max=$((l - 5))
  local t0 rc timed_out=0
  t0=$(date +%s)
  "$@" > "$out/$name.log" 2>&1 &
  local pid=$!
  while kill -0 "$pid" 2> /dev/null; do
    if [ $(($(date +%s) - t0)) -ge "$max" ]; then
      timed_out=1
      kill_tree "$pid" TERM
      sleep 3
      kill_tree "$pid" KILL
      break
    fi
    sleep 1
  done
  wait "$pid"
  rc=$?
  local dt=$(($(date +%s) - t0))
  if [ $timed_out = 1 ]; then
    note "FAIL  $name (stopped at its time limit, ${dt} s; log $name.log)"
    rc=124
  elif [ $rc -eq 0 ]; then
    note "PASS  $name (${dt} s)$(step_figure "$name")"
  else
    note "FAIL  $name (exit $rc after ${dt} s; log $name.log)"
    tail -n 5 "$out/$name.log" | sed 's/^/      /' >> "$summary"
  fi
  return $rc
}
# the figure a step's log ends with (kernels: its lines; compare: the verdict;
# bench: particle-steps/s)
step_figure() {
  local f=$out/$1.log
  case $1 in
    kernels) echo ": $(grep -h '^kernels' "$f" | sed 's/ relative (.*): / -> /' | paste -sd ';')" ;;
    kk_*) grep -h '^compare_runs' "$f" | sed 's/^compare_runs:/:/' | tail -n1 ;;
    bench_* | example) grep -h '^BENCH' "$f" | sed 's/^BENCH/:/' | tail -n1 ;;
  esac
}

{
  echo "POLYDEM GPU run kit: $(head -n2 "$kit/MANIFEST" | tail -n1)"
  echo "mode $mode, $(nproc) cores, limit $limit s, $(date -u +%Y-%m-%dT%H:%M:%SZ)"
  if [ $mode = cuda ]; then
    command -v nvidia-smi > /dev/null && nvidia-smi --query-gpu=name,memory.total,driver_version \
      --format=csv,noheader 2> /dev/null | sed 's/^/gpu /'
  fi
} | tee -a "$summary"

# --- compilers -------------------------------------------------------------------
gen=()
command -v ninja > /dev/null && gen=(-G Ninja)
launcher=()
command -v ccache > /dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
arch=${POLYDEM_CUDA_ARCH:-80}
case $arch in
  70) arch_opt=Kokkos_ARCH_VOLTA70 ;; 75) arch_opt=Kokkos_ARCH_TURING75 ;;
  80) arch_opt=Kokkos_ARCH_AMPERE80 ;; 86) arch_opt=Kokkos_ARCH_AMPERE86 ;;
  *) echo "run.sh: POLYDEM_CUDA_ARCH=$arch not known to Kokkos 3.4 (70 75 80 86)" >&2; exit 2 ;;
esac
if [ $mode = cuda ]; then
  if [ -n "${NVCC:-}" ]; then
    PATH="$(dirname "$NVCC"):$PATH"
  elif ! command -v nvcc > /dev/null && [ -x /usr/local/cuda/bin/nvcc ]; then
    PATH="/usr/local/cuda/bin:$PATH"
  fi
  export PATH
  if ! command -v nvcc > /dev/null; then
    note "FAIL  nvcc not found (set NVCC, or use --cpu)"
    exit 1
  fi
  note "nvcc  $(nvcc --version | sed -n 's/.*release \([0-9.]*\).*/\1/p') ($(command -v nvcc)), code sm_$arch + compute_$arch PTX"
  export NVCC_WRAPPER_DEFAULT_COMPILER=${CXX:-g++}
  kk_cfg=(-DCMAKE_CXX_COMPILER="$kit/kokkos/bin/nvcc_wrapper" -DCMAKE_CXX_FLAGS="-arch=sm_$arch"
    -DKokkos_ENABLE_CUDA=ON -DKokkos_ENABLE_CUDA_LAMBDA=ON -D"$arch_opt"=ON -DKokkos_ENABLE_SERIAL=ON)
  kkargs=(-k on g 1 -sf kk -pk kokkos newton off)
else
  kk_cfg=(-DCMAKE_CXX_COMPILER="${CXX:-g++}" -DKokkos_ENABLE_OPENMP=ON -DKokkos_ENABLE_SERIAL=ON)
  kkargs=(-k on t "$threads" -sf kk -pk kokkos newton off)
fi

# --- 1. Kokkos ----------------------------------------------------------------------
kprefix=$work/kokkos-$mode
build_kokkos() {
  cmake -S "$kit/kokkos" -B "$work/kokkos-$mode-build" "${gen[@]}" "${launcher[@]}" \
    -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX="$kprefix" -DCMAKE_CXX_STANDARD=17 \
    -DCMAKE_CXX_EXTENSIONS=OFF -DCMAKE_POSITION_INDEPENDENT_CODE=ON -DKokkos_ENABLE_TESTS=OFF \
    -DKokkos_ENABLE_EXAMPLES=OFF "${kk_cfg[@]}" &&
    cmake --build "$work/kokkos-$mode-build" -j "$jobs" &&
    cmake --install "$work/kokkos-$mode-build"
}
step kokkos 60 400 build_kokkos || { note "stopped: no Kokkos"; exit 1; }
kconfig=$(dirname "$(find "$kprefix" -name KokkosConfig.cmake | head -n1)")

# --- 2. LAMMPS + POLYDEM -----------------------------------------------------------------
build=$work/build-$mode
lmp_cfg=(-DLAMMPS_SOURCE_DIR="$kit/lammps" -DKokkos_DIR="$kconfig" -DBUILD_MPI=OFF
  -DPOLYDEM_ENABLE_TESTS=OFF -DPOLYDEM_BUILD_BENCH=OFF -DPOLYDEM_CUDA_CHECK=OFF
  -DPOLYDEM_CGAL_PREFIX="$kit/deps" -DCMAKE_BUILD_TYPE=Release -DPOLYDEM_CACHE_DIR="$work/cache")
if [ $mode = cuda ]; then
  lmp_cfg+=(-DCMAKE_CXX_COMPILER="$kprefix/bin/nvcc_wrapper" -DCMAKE_CXX_FLAGS="-arch=sm_$arch")
else
  lmp_cfg+=(-DCMAKE_CXX_COMPILER="${CXX:-g++}" -DBUILD_OMP=ON)
fi
build_lammps() {
  cmake -S "$src" -B "$build" "${gen[@]}" "${lmp_cfg[@]}" &&
    cmake --build "$build" -j "$jobs" --target lmp
}
step lammps 120 480 build_lammps || { note "stopped: no lmp"; exit 1; }
lmp=$build/lmp

# the kernel check program (unittest/cuda/kernels_cuda.cpp)
klib=$(dirname "$(find "$kprefix" -name 'libkokkoscore*' | head -n1)")
build_kernels() {
  local cxx=("${CXX:-g++}" -fopenmp) dev=()
  [ $mode = cuda ] && cxx=("$kprefix/bin/nvcc_wrapper") && dev=(-arch="sm_$arch" -expt-extended-lambda)
  "${cxx[@]}" -std=c++17 -O2 "${dev[@]}" -DPOLYDEM_USE_KOKKOS -DPOLYDEM_KERNELS_MAIN \
    -I"$src/src/POLYDEM" -isystem "$kprefix/include" "$src/unittest/cuda/kernels_cuda.cpp" \
    -o "$build/polydem_kernels_device" "$build/libpolydem_shapes.a" -L"$klib" -lkokkoscore \
    "$kit/deps/lib/libmpfr.so" "$kit/deps/lib/libgmp.so" -ldl -lpthread
}
step kernels_build 30 240 build_kernels
if [ $build_only = 1 ]; then
  note "built in $(elapsed) s (--build-only)"
  exit 0
fi

# --- 3. checks ----------------------------------------------------------------------------
pot=$src/potentials
data=$src/tools/gpu/data
shapes=()
for s in cube tetrahedron octahedron dodecahedron icosahedron mineral18 cylinder42; do
  shapes+=("$pot/$s.shape")
done
kargs=()
[ $mode = cpu ] && kargs=(--kokkos-threads="$threads")
step kernels 20 120 "$build/polydem_kernels_device" "${shapes[@]}" -n 4096 "${kargs[@]}"

scratch=$work/runs
mkdir -p "$scratch"
# kk_case NAME INPUT VARS...: plain, plain perturbed, /kk; compare_runs.py
kk_case() {
  local name=$1 input=$2
  shift 2
  (
    cd "$scratch" || exit 1
    "$lmp" -in "$input" -var pot "$pot" "$@" -log "$name.plain" -screen none &&
      "$lmp" -in "$input" -var pot "$pot" "$@" -var perturb 1e-12 -log "$name.perturbed" -screen none &&
      "$lmp" "${kkargs[@]}" -in "$input" -var pot "$pot" "$@" -log "$name.kk" -screen none &&
      python3 "$src/tools/gpu/compare_runs.py" "$name.plain" "$name.perturbed" "$name.kk"
    rc=$?
    cp "$name".plain "$name".perturbed "$name".kk "$out/" 2> /dev/null
    exit $rc
  )
}
step kk_pair 30 120 kk_case pair "$src/bench/in.dodeca_dense" -var nx 8 -var ny 8 -var nz 8 -var steps 50
step kk_wall 30 120 kk_case wall "$src/bench/wall_mesh/in.floor" -var mesh "$data/floor10k.stl" \
  -var steps1 1000 -var steps2 500 -var every 250
step kk_ellipsoid 30 120 kk_case ellipsoid "$src/bench/in.ellipsoid_cundall" -var nside 6 \
  -var pre 200 -var steps 200 -var every 100

# particle-steps per second of a log's last run
rate() {
  awk '/^Loop time of/ {t = $4; n = $9; N = $12} END {if (t > 0) printf "%.4g", n * N / t}' "$1"
}
example() {
  (cd "$scratch" && cp -r "$src/examples/hopper" . && cd hopper &&
    "$lmp" "${kkargs[@]}" -in in.hopper -log log.kk -screen none &&
    cp log.kk "$out/log.hopper.kk" &&
    echo "BENCH $(rate log.kk) particle-steps/s (last run)")
}
step example 60 240 example

sanitize() {    # TOOL
  command -v compute-sanitizer > /dev/null || { echo "compute-sanitizer not found"; return 3; }
  (cd "$scratch" &&
    compute-sanitizer --tool "$1" --error-exitcode 1 "$lmp" "${kkargs[@]}" \
      -in "$src/bench/in.dodeca_dense" -var pot "$pot" -var nx 3 -var ny 3 -var nz 3 -var steps 5 \
      -log none -screen none &&
    compute-sanitizer --tool "$1" --error-exitcode 1 "$lmp" "${kkargs[@]}" \
      -in "$src/bench/wall_mesh/in.floor" -var pot "$pot" -var mesh "$data/floor10k.stl" \
      -var steps1 5 -var steps2 5 -var every 5 -log none -screen none)
}
if [ $mode = cuda ]; then
  step memcheck 60 150 sanitize memcheck
  step racecheck 60 150 sanitize racecheck
else
  note "SKIP  memcheck, racecheck (compute-sanitizer needs a GPU)"
fi

bench_dense() {    # N per side
  (cd "$scratch" && "$lmp" "${kkargs[@]}" -in "$src/bench/in.dodeca_dense" -var pot "$pot" \
    -var nx "$1" -var ny "$1" -var nz "$1" -var steps 100 -log "dense$1.log" -screen none &&
    cp "dense$1.log" "$out/" && echo "BENCH $(rate "dense$1.log") particle-steps/s, N = $(($1 * $1 * $1)), 100 steps")
}
bench_silo() {
  (cd "$scratch" && "$lmp" "${kkargs[@]}" -in "$src/bench/wall_mesh/in.silo" -var pot "$pot" \
    -var mesh "$data/silo10k.stl" -log silo.log -screen none &&
    cp silo.log "$out/" && echo "BENCH $(rate silo.log) particle-steps/s, silo 9,840 triangles (last 1000 steps)")
}
step bench_dense_1e5 30 120 bench_dense 46
step bench_silo 30 150 bench_silo
step bench_dense_1e6 90 240 bench_dense 100

fails=$(grep -c '^FAIL' "$summary")
note "done in $(elapsed) s: $(grep -c '^PASS' "$summary") passed, $fails failed, $(grep -c '^SKIP' "$summary") skipped"
[ "$fails" -eq 0 ]
