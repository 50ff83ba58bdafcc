#!/bin/bash
# run.sh OUTDIR [--cpu] [--build-only] [--references] [--jobs N] [--limit SECONDS] [--threads N]
#
# The GPU run kit's one command, run from an unpacked kit (tools/gpu/bundle.sh)
# or from a prebuilt run (tools/gpu/bundle.sh --prebuilt DIR):
#
#   tar xzf polydem-gpu-kit.tar.gz && bash polydem-gpu-kit/run.sh /path/to/out
#   bash DIR/run.sh /path/to/out --limit 300            # prebuilt: nothing to build
#
# From the kit, on a node with an NVIDIA GPU, nvcc (CUDA >= 11; 13 tested),
# CMake >= 3.16, a C++17 compiler and python3 (no MPI, no network), it first
# builds Kokkos 3.4.01 for CUDA (sm_80 code + PTX: Kokkos 3.4 cannot name
# Hopper, the driver JIT-compiles the PTX for sm_90) and LAMMPS + POLYDEM with
# the KOKKOS package and LAMMPS's MPI stubs. A prebuilt run needs only the
# NVIDIA driver and python3. Then, in this order:
#   kernels   the header-only kernels on the device against the host
#   kk_pair, kk_wall, kk_ellipsoid, kk_insert, kk_restart
#             /kk on the GPU against the plain styles, judged against the
#             run's own sensitivity (compare_runs.py); a prebuilt run carries
#             the plain reference logs (ref/), the kit computes them
#   example   the main example (examples/hopper) with -sf kk against its
#             reference log (log.hopper), judged the same way
#   memcheck, racecheck
#             compute-sanitizer on a small pair and wall case (if present)
#   bench_*   dense dodecahedra at N = 1e5 and 1e6 and a 2e5-grain slice of
#             the silo: particle-steps/s and peak GPU memory
# and writes OUTDIR/summary.txt (one line per step: PASS / FAIL / SKIP,
# seconds, figures) and OUTDIR/logs.tar.gz (every step's log). It stops
# starting steps when the time limit (default 570 s, including any build)
# would be passed, and says which it skipped; a step that overruns its own
# limit is killed.
#
#   --cpu         the same on the CPU: Kokkos OpenMP + Serial, -k on t N
#                 (no compute-sanitizer, smaller benchmarks); this is how the
#                 kit is verified on a machine without a GPU
#   --build-only  build (and, with CUDA, link) and stop
#   --references  run only the plain styles' reference logs into OUTDIR
#                 (bundle.sh --prebuilt does this for ref/)
#   --jobs N      parallel compiles (default: all cores)
#   --threads N   OpenMP threads of --cpu runs (default 2)
#   --limit S     time limit in seconds (default 570)
# Environment: POLYDEM_KIT_WORK (build folder, default: KIT/work),
#              NVCC, CXX (host compiler), POLYDEM_CUDA_ARCH (default 80),
#              POLYDEM_BUNDLED_GLIBC=1 (prebuilt: use the bundled glibc even
#              where the node's is new enough; a check of that path).
set -uo pipefail
kit=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
prebuilt=0
[ -d "$kit/polydem" ] && { [ -x "$kit/bin/lmp" ] || [ -x "$kit/bin-cpu/lmp" ]; } && prebuilt=1
if [ $prebuilt = 0 ] && { [ ! -d "$kit/polydem" ] || [ ! -d "$kit/lammps" ] || [ ! -d "$kit/kokkos" ]; }; then
  echo "run.sh: $kit is neither an unpacked GPU run kit nor a prebuilt run (tools/gpu/bundle.sh)" >&2
  exit 2
fi
if [ $# -lt 1 ]; then
  sed -n '2,4p' "$0" >&2
  exit 2
fi
out=$(mkdir -p "$1" && cd "$1" && pwd)
shift
mode=cuda build_only=0 references=0 jobs=$(nproc) threads=2 limit=570
while [ $# -gt 0 ]; do
  case $1 in
    --cpu) mode=cpu ;;
    --build-only) build_only=1 ;;
    --references) references=1 ;;
    --jobs) jobs=$2; shift ;;
    --threads) threads=$2; shift ;;
    --limit) limit=$2; shift ;;
    *) echo "run.sh: unknown option $1" >&2; exit 2 ;;
  esac
  shift
done
t_start=$(date +%s)
if [ $prebuilt = 1 ]; then
  work=${POLYDEM_KIT_WORK:-${TMPDIR:-/tmp}/polydem-run.$$}
else
  work=${POLYDEM_KIT_WORK:-$kit/work}
fi
mkdir -p "$work"
src=$kit/polydem
summary=$out/summary.txt
: > "$summary"
export LD_LIBRARY_PATH="$kit/deps/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
export OMP_PROC_BIND=false OMP_NUM_THREADS=$threads
# the driver compiles the PTX for a newer GPU (sm_90) once per module: keep
# all of it in its cache for the later steps
export CUDA_CACHE_MAXSIZE=4294967296

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
  [ $mode = cpu ] && max=$((4 * max))    # a CPU node is slower
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
    example) echo "$(grep -h '^compare_runs' "$f" | sed 's/^compare_runs:/:/' | tail -n1)$(grep -h '^BENCH' "$f" | sed 's/^BENCH/;/' | tail -n1)" ;;
    bench_*) grep -h '^BENCH' "$f" | sed 's/^BENCH/:/' | tail -n1 ;;
  esac
}


{
  if [ $prebuilt = 1 ]; then
    echo "POLYDEM prebuilt run: $(sed -n 2p "$kit/MANIFEST"); $(grep '^prebuilt' "$kit/MANIFEST" | paste -sd ';')"
  else
    echo "POLYDEM GPU run kit: $(head -n2 "$kit/MANIFEST" | tail -n1)"
  fi
  echo "mode $mode, $(nproc) cores, limit $limit s, $(date -u +%Y-%m-%dT%H:%M:%SZ)"
  if [ $mode = cuda ]; then
    command -v nvidia-smi > /dev/null && nvidia-smi --query-gpu=name,memory.total,driver_version \
      --format=csv,noheader 2> /dev/null | sed 's/^/gpu /'
  fi
} | tee -a "$summary"

if [ $mode = cuda ]; then
  kkargs=(-k on g 1 -sf kk -pk kokkos newton off)
else
  kkargs=(-k on t "$threads" -sf kk -pk kokkos newton off)
fi

if [ $prebuilt = 1 ]; then
  # --- the prebuilt executables ------------------------------------------------------
  bin=$kit/bin
  [ $mode = cpu ] && bin=$kit/bin-cpu
  if [ $references = 1 ]; then    # the plain styles: either build, the CPU one first
    bin=$kit/bin-cpu
    [ -x "$bin/lmp" ] || bin=$kit/bin
  fi
  if [ ! -x "$bin/lmp" ]; then
    note "FAIL  $bin/lmp missing: this prebuilt run has no $mode build (bundle.sh --prebuilt)"
    exit 1
  fi
  # where this node's glibc is older than the one they were linked against,
  # run them with the bundled glibc and its loader
  prefix=()
  need=$(cat "$kit/lib/glibc/REQUIRED" 2> /dev/null || echo 0)
  have=$(getconf GNU_LIBC_VERSION 2> /dev/null | awk '{print $2}')
  if [ "${POLYDEM_BUNDLED_GLIBC:-0}" = 1 ] ||
    { [ -n "$have" ] && [ "$(printf '%s\n%s\n' "$need" "$have" | sort -V | head -n1)" != "$need" ]; }; then
    prefix=("$kit/lib/glibc/ld-linux-x86-64.so.2" --library-path "$kit/lib/glibc:$kit/lib")
    if [ "${POLYDEM_BUNDLED_GLIBC:-0}" = 1 ]; then
      note "glibc: the bundled one runs the executables (POLYDEM_BUNDLED_GLIBC=1)"
    else
      note "glibc $have here, $need needed: the bundled glibc runs the executables"
    fi
  fi
  lmp=("${prefix[@]}" "$bin/lmp")
  kernels_exe=("${prefix[@]}" "$bin/polydem_kernels_device")
else
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
  else
    kk_cfg=(-DCMAKE_CXX_COMPILER="${CXX:-g++}" -DKokkos_ENABLE_OPENMP=ON -DKokkos_ENABLE_SERIAL=ON)
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
  step kokkos 60 100000 build_kokkos || { note "stopped: no Kokkos"; exit 1; }
  kconfig=$(dirname "$(find "$kprefix" -name KokkosConfig.cmake | head -n1)")

  # --- 2. LAMMPS + POLYDEM -----------------------------------------------------------------
  build=$work/build-$mode
  lmp_cfg=(-DLAMMPS_SOURCE_DIR="$kit/lammps" -DKokkos_DIR="$kconfig" -DBUILD_MPI=OFF
    -DPOLYDEM_ENABLE_TESTS=OFF -DPOLYDEM_BUILD_BENCH=OFF -DPOLYDEM_CUDA_CHECK=OFF
    -DPOLYDEM_KOKKOS_OTHER_PAIRS=OFF
    -DPOLYDEM_CGAL_PREFIX="$kit/deps" -DCMAKE_BUILD_TYPE=Release -DPOLYDEM_CACHE_DIR="$work/cache"
    -DCMAKE_BUILD_WITH_INSTALL_RPATH=ON -DCMAKE_INSTALL_RPATH='$ORIGIN/../lib'
    -DCMAKE_EXE_LINKER_FLAGS=-Wl,--disable-new-dtags)
  # RPATH, not RUNPATH, $ORIGIN/../lib only: a prebuilt run's lib/ (bundle.sh
  # --prebuilt), for the libraries' own dependencies too (libpng's libz); in
  # the kit, LD_LIBRARY_PATH finds deps/lib
  if [ $mode = cuda ]; then
    lmp_cfg+=(-DCMAKE_CXX_COMPILER="$kprefix/bin/nvcc_wrapper" -DCMAKE_CXX_FLAGS="-arch=sm_$arch")
  else
    lmp_cfg+=(-DCMAKE_CXX_COMPILER="${CXX:-g++}" -DBUILD_OMP=ON)
  fi
  build_lammps() {
    cmake -S "$src" -B "$build" "${gen[@]}" "${lmp_cfg[@]}" &&
      cmake --build "$build" -j "$jobs" --target lmp
  }
  step lammps 120 100000 build_lammps || { note "stopped: no lmp"; exit 1; }
  lmp=("$build/lmp")

  # the kernel check program (unittest/cuda/kernels_cuda.cpp)
  klib=$(dirname "$(find "$kprefix" -name 'libkokkoscore*' | head -n1)")
  build_kernels() {
    local cxx=("${CXX:-g++}" -fopenmp) dev=()
    [ $mode = cuda ] && cxx=("$kprefix/bin/nvcc_wrapper") && dev=(-arch="sm_$arch" -expt-extended-lambda)
    "${cxx[@]}" -std=c++17 -O2 "${dev[@]}" -DPOLYDEM_USE_KOKKOS -DPOLYDEM_KERNELS_MAIN \
      -I"$src/src/POLYDEM" -isystem "$kprefix/include" "$src/unittest/cuda/kernels_cuda.cpp" \
      -o "$build/polydem_kernels_device" "$build/libpolydem_shapes.a" -L"$klib" -lkokkoscore \
      "$kit/deps/lib/libmpfr.so" "$kit/deps/lib/libgmp.so" -ldl -lpthread -Wl,--disable-new-dtags -Wl,-rpath,'$ORIGIN/../lib'
  }
  step kernels_build 30 240 build_kernels
  kernels_exe=("$build/polydem_kernels_device")
  if [ $build_only = 1 ]; then
    note "built in $(elapsed) s (--build-only)"
    exit 0
  fi
fi

# --- 3. checks ----------------------------------------------------------------------------
pot=$src/potentials
data=$src/tools/gpu/data
inputs=$src/tools/gpu/inputs
scratch=$work/runs
mkdir -p "$scratch"
ref=$kit/ref    # a prebuilt run's reference logs; the kit makes its own here
[ -d "$ref" ] || { ref=$scratch/ref && mkdir -p "$ref"; }

# every log into one archive at the end (at most a few files come back)
pack_logs() {
  (cd "$out" && ls | grep -v -e '^summary.txt$' -e '^logs.tar.gz$' > "$work/logs.list"
    if [ -s "$work/logs.list" ]; then
      tar -czf logs.tar.gz -T "$work/logs.list" && xargs rm -f < "$work/logs.list"
    fi)
  [ $prebuilt = 1 ] && [ -z "${POLYDEM_KIT_WORK:-}" ] && rm -rf "$work"
}

# the cases /kk is judged on: NAME INPUT VARS... (the same in every mode, so
# one set of reference logs serves the GPU and the --cpu runs)
kk_cases() {
  "$1" pair "$src/bench/in.dodeca_dense" -var nx 8 -var ny 8 -var nz 8 -var steps 50 -var every 10
  "$1" wall "$src/bench/wall_mesh/in.floor" -var mesh "$data/floor10k.stl" -var steps1 1000 \
    -var steps2 500 -var every 250
  "$1" ellipsoid "$src/bench/in.ellipsoid_cundall" -var nside 6 -var pre 200 -var steps 200 -var every 100
  "$1" insert "$inputs/in.kk_insert" -var mesh "$data/floor10k.stl"
  "$1" restart "$inputs/in.kk_restart" -var phase read -var restart "$ref/kk.restart"
}

if [ $references = 1 ]; then
  # the plain styles' logs: each case plain and perturbed; the restart file
  # the restart case reads; the main example perturbed (its plain log is
  # examples/hopper/log.hopper, 2 MPI ranks: a 1-rank run differs from it by
  # round-off, the perturbation a /kk run brings too)
  ref=$out
  reference() {
    local name=$1 input=$2
    shift 2
    local t0=$(date +%s)
    (cd "$scratch" &&
      "${lmp[@]}" -in "$input" -var pot "$pot" "$@" -log "$out/$name.plain" -screen none &&
      "${lmp[@]}" -in "$input" -var pot "$pot" "$@" -var perturb 1e-12 -log "$out/$name.perturbed" \
        -screen none) || { echo "reference $name failed"; return 1; }
    echo "reference $name ($(($(date +%s) - t0)) s)"
  }
  (cd "$scratch" && "${lmp[@]}" -in "$inputs/in.kk_restart" -var pot "$pot" -var phase write \
    -var restart "$out/kk.restart" -log none -screen none) || { echo "restart file failed"; exit 1; }
  kk_cases reference || exit 1
  t0=$(date +%s)
  (cd "$scratch" && rm -rf hopper && cp -r "$src/examples/hopper" . && cd hopper &&
    "${lmp[@]}" -in in.hopper -var pot "$pot" -log "$out/hopper.perturbed" -screen none) ||
    { echo "reference hopper failed"; exit 1; }
  echo "reference hopper ($(($(date +%s) - t0)) s)"
  rm -f "$summary"
  [ $prebuilt = 1 ] && [ -z "${POLYDEM_KIT_WORK:-}" ] && rm -rf "$work"
  exit 0
fi

shapes=()
for s in cube tetrahedron octahedron dodecahedron icosahedron mineral18 cylinder42; do
  shapes+=("$pot/$s.shape")
done
kargs=()
[ $mode = cpu ] && kargs=(--kokkos-threads="$threads")
step kernels 20 120 "${kernels_exe[@]}" "${shapes[@]}" -n 4096 "${kargs[@]}"

# kk_case NAME INPUT VARS...: /kk against the plain and perturbed plain logs
# (ref/, or run here where there is no ref/), compare_runs.py
kk_case() {
  local name=$1 input=$2
  shift 2
  (
    cd "$scratch" || exit 1
    if [ -f "$ref/$name.plain" ] && [ -f "$ref/$name.perturbed" ]; then
      cp "$ref/$name.plain" "$ref/$name.perturbed" .
    else
      if [ "$name" = restart ] && [ ! -f "$ref/kk.restart" ]; then
        "${lmp[@]}" -in "$inputs/in.kk_restart" -var pot "$pot" -var phase write \
          -var restart "$ref/kk.restart" -log none -screen none || exit 1
      fi
      "${lmp[@]}" -in "$input" -var pot "$pot" "$@" -log "$name.plain" -screen none &&
        "${lmp[@]}" -in "$input" -var pot "$pot" "$@" -var perturb 1e-12 -log "$name.perturbed" \
          -screen none || exit 1
    fi
    "${lmp[@]}" "${kkargs[@]}" -in "$input" -var pot "$pot" "$@" -log "$name.kk" -screen none &&
      python3 "$src/tools/gpu/compare_runs.py" "$name.plain" "$name.perturbed" "$name.kk"
    rc=$?
    cp "$name".plain "$name".perturbed "$name".kk "$out/" 2> /dev/null
    exit $rc
  )
}
# the first /kk runs on a GPU newer than sm_80 wait for the driver to
# compile the PTX of lmp's kernels (cached for the later steps): measured
# apart, so that it does not count against the first check
warmup() {
  (cd "$scratch" &&
    "${lmp[@]}" "${kkargs[@]}" -in "$src/bench/in.dodeca_dense" -var pot "$pot" -var nx 3 -var ny 3 \
      -var nz 3 -var steps 5 -log none -screen none &&
    "${lmp[@]}" "${kkargs[@]}" -in "$src/bench/wall_mesh/in.floor" -var pot "$pot" \
      -var mesh "$data/floor10k.stl" -var steps1 5 -var steps2 5 -var every 5 -log none -screen none &&
    "${lmp[@]}" "${kkargs[@]}" -in "$src/bench/in.ellipsoid_cundall" -var pot "$pot" -var nside 3 \
      -var pre 5 -var steps 5 -var every 5 -log none -screen none)
}
[ $mode = cuda ] && step warmup 30 240 warmup
kk_step() {    # NAME INPUT VARS...
  local name=$1
  step "kk_$name" 20 120 kk_case "$@"
}
kk_cases kk_step

# particle-steps per second of a log's last run
rate() {
  awk '/^Loop time of/ {t = $4; n = $9; N = $12} END {if (t > 0) printf "%.4g", n * N / t}' "$1"
}
# peak GPU memory while a command runs (nvidia-smi sampled every 0.2 s)
with_gpu_memory() {
  local mem=$scratch/gpumem.$$ w=""
  if [ $mode = cuda ] && command -v nvidia-smi > /dev/null; then
    nvidia-smi --query-gpu=memory.used --format=csv,noheader,nounits -lms 200 > "$mem" 2> /dev/null &
    w=$!
  fi
  "$@"
  local rc=$?
  if [ -n "$w" ]; then
    kill "$w" 2> /dev/null
    wait "$w" 2> /dev/null
    echo "GPUMEM $(sort -n "$mem" | tail -n1) MiB"
  fi
  return $rc
}
# the main example with -sf kk against log.hopper (the plain styles, 2 ranks)
# and its perturbed twin (ref/hopper.perturbed, 1 rank), row by row while the
# perturbed run has not yet saturated; --cpu: the discharge cut to 5,000
# steps (its rows are the first rows of the full run's)
example_vars=()
[ $mode = cpu ] && example_vars=(-var tdis 5000)
example() {
  (cd "$scratch" && rm -rf hopper && cp -r "$src/examples/hopper" . && cd hopper &&
    "${lmp[@]}" "${kkargs[@]}" -in in.hopper -var pot "$pot" "${example_vars[@]}" -log log.kk \
      -screen none || exit 1
    cp log.kk "$out/log.hopper.kk"
    echo "BENCH $(rate log.kk) particle-steps/s (last run)"
    if [ -f "$ref/hopper.perturbed" ]; then
      python3 "$src/tools/gpu/compare_runs.py" log.hopper "$ref/hopper.perturbed" log.kk --common
    else
      echo "compare_runs: no perturbed reference (ref/hopper.perturbed): not judged"
    fi)
}
step example 60 240 example

sanitize() {    # TOOL
  command -v compute-sanitizer > /dev/null || { echo "compute-sanitizer not found"; return 3; }
  (cd "$scratch" &&
    compute-sanitizer --tool "$1" --error-exitcode 1 "${lmp[@]}" "${kkargs[@]}" \
      -in "$src/bench/in.dodeca_dense" -var pot "$pot" -var nx 3 -var ny 3 -var nz 3 -var steps 5 \
      -log none -screen none &&
    compute-sanitizer --tool "$1" --error-exitcode 1 "${lmp[@]}" "${kkargs[@]}" \
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
  (cd "$scratch" && with_gpu_memory "${lmp[@]}" "${kkargs[@]}" -in "$src/bench/in.dodeca_dense" \
    -var pot "$pot" -var nx "$1" -var ny "$1" -var nz "$1" -var steps 100 -log "dense$1.log" \
    -screen none > "dense$1.mem" && cp "dense$1.log" "$out/" &&
    echo "BENCH $(rate "dense$1.log") particle-steps/s, N = $(($1 * $1 * $1)), 100 steps$(sed 's/^GPUMEM/, peak GPU memory/' "dense$1.mem")")
}
bench_silo() {    # grains steps
  local mesh=$data
  if [ ! -f "$data/silo.stl" ]; then    # a prebuilt run carries it compressed
    mesh=$scratch/silo
    mkdir -p "$mesh" && cp "$data/lid.stl" "$mesh/" &&
      python3 -c 'import gzip, shutil, sys; shutil.copyfileobj(gzip.open(sys.argv[1]), open(sys.argv[2], "wb"))' \
        "$data/silo.stl.gz" "$mesh/silo.stl" || return 1
  fi
  (cd "$scratch" && with_gpu_memory "${lmp[@]}" "${kkargs[@]}" -in "$inputs/in.silo_slice" \
    -var pot "$pot" -var mesh "$mesh" -var n "$1" -var steps "$2" -log silo.log -screen none \
    > silo.mem && cp silo.log "$out/" &&
    echo "BENCH $(rate silo.log) particle-steps/s, silo slice of $(awk '/^Loop time/ {print $12}' silo.log) grains, $2 steps, $(awk '/^ *Step/ {getline; c = $5} END {print c}' silo.log) contacts per grain at the start$(sed 's/^GPUMEM/, peak GPU memory/' silo.mem)")
}
if [ $mode = cuda ]; then
  step bench_dense_1e5 30 120 bench_dense 46
  step bench_silo_2e5 60 180 bench_silo 200000 200
  step bench_dense_1e6 90 240 bench_dense 100
else    # the CPU path checks the benchmarks' plumbing at small N
  step bench_dense_8e3 10 60 bench_dense 20
  step bench_silo_2e3 10 60 bench_silo 2000 20
fi

fails=$(grep -c '^FAIL' "$summary")
note "done in $(elapsed) s: $(grep -c '^PASS' "$summary") passed, $fails failed, $(grep -c '^SKIP' "$summary") skipped"
pack_logs
[ "$fails" -eq 0 ]
