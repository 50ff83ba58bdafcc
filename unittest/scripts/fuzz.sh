#!/bin/bash
# Coverage-guided fuzzing of POLYDEM's readers (issue 17) with libFuzzer:
# the harnesses of unittest/fuzz/fuzz_readers.cpp (STL, shape files) built
# with clang -fsanitize=fuzzer,address,undefined, each run for SECONDS from
# a copy of the committed seed corpus (which it grows in WORK/corpus-*).
# Prints libFuzzer's final statistics (executions, coverage, corpus) and
# any crash/leak/timeout file it wrote (WORK/crash-*, ...); exits non-zero
# on a finding. ctest runs the same harnesses without clang (fuzz.stl,
# fuzz.shape: bounded mutation, not coverage-guided).
#   bash unittest/scripts/fuzz.sh [SECONDS per reader (60)] [WORK dir (/tmp/polydem-fuzz)]
# Needs clang++ with libFuzzer (Debian: apt-get install clang), CGAL, GMP, MPFR.
set -euo pipefail
secs=${1:-60}
work=${2:-/tmp/polydem-fuzz}
src=$(cd "$(dirname "$0")/../.." && pwd)
cxx=${CXX_FUZZ:-clang++}
mkdir -p "$work"
flags=(-std=c++17 -O1 -g -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined
       -frounding-math -DBOOST_ALL_NO_LIB -DCGAL_USE_GMPXX=1 -I"$src/src/POLYDEM")
# the readers once, with coverage instrumentation (objects shared by both harnesses)
objs=()
for f in "$src"/src/POLYDEM/polydem_*.cpp; do
  o="$work/$(basename "${f%.cpp}").o"
  if [ ! -f "$o" ] || [ "$f" -nt "$o" ]; then
    "$cxx" "${flags[@]/-fsanitize=fuzzer,/-fsanitize=fuzzer-no-link,}" -c "$f" -o "$o"
  fi
  objs+=("$o")
done
status=0
for r in stl shape; do
  R=$(echo $r | tr a-z A-Z)
  "$cxx" "${flags[@]}" -DPOLYDEM_FUZZ_$R "$src/unittest/fuzz/fuzz_readers.cpp" "${objs[@]}" \
    -lgmpxx -lgmp -lmpfr -o "$work/fuzz_$r"
  mkdir -p "$work/corpus-$r"
  cp -n "$src"/unittest/fuzz/corpus/$r/* "$work/corpus-$r/"
  echo "== fuzz_$r: ${secs} s"
  ( cd "$work" && ASAN_OPTIONS=detect_leaks=1 ./fuzz_$r -max_total_time="$secs" -timeout=10 \
      -rss_limit_mb=4096 -print_final_stats=1 corpus-$r ) > "$work/fuzz_$r.log" 2>&1 || status=1
  grep -E "^#[0-9]+.*(DONE|pulse)|stat::number_of_executed_units|stat::peak_rss|cov:" \
    "$work/fuzz_$r.log" | tail -3
  echo "corpus: $(ls "$work/corpus-$r" | wc -l) inputs; findings: $(ls "$work" | grep -cE "^(crash|leak|timeout|oom)-" || true)"
done
exit $status
