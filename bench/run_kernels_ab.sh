#!/bin/bash
# A/B speed comparison of two bench_kernels binaries, run alternately (this
# machine's speed drifts from minute to minute): `rounds` short runs of each,
# then per benchmark the median and the minimum of each side and their
# ratios B/A. The minimum is the steadier figure when other work disturbs
# the machine (it only ever adds time).
#   bash bench/run_kernels_ab.sh bench_kernelsA bench_kernelsB [rounds] [filter]
# filter: a --benchmark_filter regex (default: the overlap and GJK + overlap
# of dodecahedra and 42-point cylinders).
set -euo pipefail
A=$(realpath "$1") B=$(realpath "$2") rounds=${3:-9}
filter=${4:-'overlap_ws12/dodecahedron$|overlap_ws22/cylinder42$|gjk_overlap'}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for r in $(seq "$rounds"); do
  for which in A B; do
    "${!which}" --benchmark_filter="$filter" --benchmark_min_time=0.2 2>/dev/null |
      awk '$2 ~ /^[0-9.]+$/ && $3 == "ns" {print $1, $2}' >> "$out/$which"
  done
done
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2); $(date -u)"
python3 - "$out/A" "$out/B" <<'PY'
import statistics, sys
def load(f):
    d = {}
    for line in open(f):
        k, v = line.split()
        d.setdefault(k, []).append(float(v))
    return d
a, b = load(sys.argv[1]), load(sys.argv[2])
print("%-34s %9s %9s %6s   %9s %9s %6s" % ("ns per call", "med A", "med B", "B/A", "min A", "min B", "B/A"))
for k in a:
    ma, mb, na, nb = statistics.median(a[k]), statistics.median(b[k]), min(a[k]), min(b[k])
    print("%-34s %9.0f %9.0f %6.3f   %9.0f %9.0f %6.3f" % (k, ma, mb, mb / ma, na, nb, nb / na))
PY
