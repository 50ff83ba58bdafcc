# Shared by the settled-bed A/B scripts (silo_bed/run_ab.sh,
# fixed_bed_settled/run_ab.sh); sourced, not run.
#   bed_ab LABEL ROUNDS INPUT [lmp arguments...]
# runs `$A -in INPUT -var mode time ARGS` and the same with $B alternately,
# ROUNDS times each, in the current folder, and prints the CPU microseconds
# per grain-step of every run ("Loop time" x "% CPU use" / (steps x grains))
# and the ratio B/A of the medians.
bed_ab() {
  local label=$1 rounds=$2 input=$3 which r a b
  shift 3
  declare -A res
  for r in $(seq "$rounds"); do
    for which in A B; do
      "${!which}" -in "$input" -var mode time "$@" -log "log.$which" -screen none
      res[$which]+="$(awk '/^Loop time of/ {t = $4; n = $9; N = $12} /% CPU use/ {c = $1 + 0}
        END {printf "%.3f", 1e6 * t * c / 100 / (n * N)}' "log.$which") "
    done
  done
  median() { tr ' ' '\n' | grep -v '^$' | sort -g | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}'; }
  a=$(echo "${res[A]}" | median) b=$(echo "${res[B]}" | median)
  echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2); $(date -u)"
  printf "%s  A: %s us   B: %s us   (CPU us/grain-step per run)  median B/A = %.3f\n" \
    "$label" "${res[A]}" "${res[B]}" "$(echo "$b / $a" | bc -l)"
}
