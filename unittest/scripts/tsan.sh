#!/bin/bash
# tsan.sh [THREADS]   ThreadSanitizer and Kokkos's debug checks on the /kk styles (issue 19)
#
# Builds a second tree (default build-tsan/) against Kokkos 3.4.01 Serial +
# Threads (pthreads, which TSan understands; libgomp is not instrumented),
# itself built with -fsanitize=thread, Kokkos_ENABLE_DEBUG, DEBUG_BOUNDS_CHECK
# and DEBUG_DUALVIEW_MODIFY_CHECK (cmake/scripts/build-kokkos-host.sh tsan). LAMMPS,
# its KOKKOS package, POLYDEM and the tests are all compiled with
# -fsanitize=thread. Then runs, with THREADS threads (default 4):
#   - every /kk test (the *_threads ctest entries, label "threads", once each)
#   - tsan.planted_race: TSan must report a planted race (all threads += into
#     one View slot), tsan.atomic_clean: the atomic version must be clean
#   - threads.dualview_check_*: the DualView modify check fires on a missing sync
# Any TSan report makes its test fail (exit code 66). Not part of tools/test.sh:
# a cold run rebuilds all of LAMMPS with TSan (times in bench/RESULTS.md).
#
# Environment: POLYDEM_TSAN_BUILD_DIR (default build-tsan), POLYDEM_JOBS (default 2),
#              TSAN_OPTIONS (added to the defaults below).
set -euo pipefail
cd "$(dirname "$0")/../.."
threads=${1:-4}
build=${POLYDEM_TSAN_BUILD_DIR:-build-tsan}
jobs=${POLYDEM_JOBS:-2}
start=$(date +%s)
bash tools/install-deps.sh
san=-fsanitize=thread
cmake -S . -B "$build" -DPOLYDEM_KOKKOS_BACKEND=tsan -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  "-DCMAKE_CXX_FLAGS=$san" "-DCMAKE_C_FLAGS=$san" \
  "-DCMAKE_EXE_LINKER_FLAGS=$san" "-DCMAKE_SHARED_LINKER_FLAGS=$san" \
  -DPOLYDEM_SANITIZE=OFF -DPOLYDEM_CUDA_CHECK=OFF -DPOLYDEM_BUILD_BENCH=OFF \
  -DPOLYDEM_TEST_THREADS="$threads" -DPOLYDEM_TEST_REPEAT_MAX=1
targets=(lmp test_kokkos_integrator test_pair_kokkos test_contact_computes test_pair_regression
         test_wall_kokkos test_wall_ellipsoid_kokkos test_ellipsoid_kokkos test_insert_ranks
         dualview_check planted_race)
cmake --build "$build" -j"$jobs" --target "${targets[@]}"
echo "tsan.sh: build took $(( $(date +%s) - start )) s"
export TSAN_OPTIONS="exitcode=66 halt_on_error=0 second_deadlock_stack=1 suppressions=$PWD/unittest/threads/tsan.supp ${TSAN_OPTIONS:-}"
# one test at a time: each runs $threads threads
ctest --test-dir "$build" --output-on-failure -R '(_threads$|^tsan\.|^threads\.)'
echo "tsan.sh: build + tests took $(( $(date +%s) - start )) s"
