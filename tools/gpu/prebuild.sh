#!/bin/bash
# prebuild.sh KIT CACHE DIR JOBS MODE...   (called by bundle.sh --prebuilt)
#
# Builds the unpacked kit KIT here for each MODE (cuda: Kokkos CUDA; cpu:
# Kokkos OpenMP + Serial) in CACHE/MODE, which keeps the kit's files at a
# fixed path and rewrites only the files whose content changed (so a second
# bundle recompiles only those), then writes the ready run into DIR:
#   bin/       lmp and polydem_kernels_device built for CUDA (MODE cuda)
#   bin-cpu/   the same for Kokkos OpenMP (MODE cpu)
#   lib/       the shared libraries they load that a bare Linux may lack
#              (found through their RUNPATH $ORIGIN/../lib); lib/glibc/ the C
#              library and its loader, for nodes with an older glibc
#   polydem/   the inputs, meshes, shapes and compare_runs.py the steps read
#   ref/       the plain styles' reference logs and restart file
#   run.sh, MANIFEST
set -euo pipefail
kit=$1 cache=$2 dir=$3 jobs=$4
shift 4
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
log() { echo "prebuild: $*" >&2; }
mkdir -p "$dir/lib/glibc" "$dir/polydem"
cp "$kit/run.sh" "$kit/MANIFEST" "$dir/"

for mode in "$@"; do
  stable=$cache/$mode
  mkdir -p "$stable"
  # --- the kit at a fixed path, changed files only --------------------------------
  python3 - "$kit" "$stable/kit" <<'PY'
import filecmp, os, shutil, sys
src, dst = sys.argv[1], sys.argv[2]
keep = set()
for root, dirs, files in os.walk(src):
    rel = os.path.relpath(root, src)
    os.makedirs(os.path.join(dst, rel), exist_ok=True)
    for f in files:
        a, b = os.path.join(root, f), os.path.join(dst, rel, f)
        keep.add(os.path.normpath(b))
        if os.path.islink(a):
            if os.path.lexists(b):
                os.remove(b)
            os.symlink(os.readlink(a), b)
        elif not (os.path.isfile(b) and not os.path.islink(b) and filecmp.cmp(a, b, shallow=False)):
            if os.path.lexists(b):
                os.remove(b)
            shutil.copy(a, b)
for root, dirs, files in os.walk(dst):
    for f in files:
        b = os.path.normpath(os.path.join(root, f))
        if b not in keep:
            os.remove(b)
PY
  # --- build --------------------------------------------------------------------------
  mflag=()
  [ "$mode" = cpu ] && mflag=(--cpu)
  t0=$(date +%s)
  rm -rf "$stable/buildlog"
  POLYDEM_KIT_WORK="$stable/work" bash "$stable/kit/run.sh" "$stable/buildlog" --build-only \
    "${mflag[@]}" --jobs "$jobs" --limit 1000000 > /dev/null ||
    { log "the $mode build failed (logs in $stable/buildlog)"; exit 1; }
  log "$mode build: $(($(date +%s) - t0)) s"
  build=$stable/work/build-$mode
  bin=$dir/bin
  [ "$mode" = cpu ] && bin=$dir/bin-cpu
  mkdir -p "$bin"
  cp "$build/lmp" "$build/polydem_kernels_device" "$bin/"
  strip "$bin/lmp" "$bin/polydem_kernels_device"
  echo "prebuilt $mode: $(date -u +%Y-%m-%dT%H:%M:%SZ), $(nproc) cores, $(($(date +%s) - t0)) s to build" >> "$dir/MANIFEST"
  # every shared library they load (the CUDA runtime too: Kokkos 3.4 links
  # it shared), but the CUDA driver (the node's); glibc's own apart
  for exe in "$bin"/*; do
    LD_LIBRARY_PATH="$stable/kit/deps/lib:/usr/local/cuda/lib:/usr/local/cuda/lib64" ldd "$exe"
  done | awk '$2 == "=>" && $3 ~ /^\// {print $1, $3} $1 ~ /^\/.*ld-linux/ {print "ld-linux-x86-64.so.2", $1}' |
    sort -u | while read -r name path; do
      case $(realpath "$path") in "$dir"/*) continue ;; esac    # already here (RUNPATH)
      case $name in
        libcuda.so*) ;;
        libc.so.* | libm.so.* | libdl.so.* | libpthread.so.* | librt.so.* | ld-linux*)
          cp -L "$path" "$dir/lib/glibc/$name" ;;
        *) cp -L "$path" "$dir/lib/$name" ;;
      esac
    done
done
# the newest glibc symbol version the executables and libraries need
objdump -T "$dir"/bin*/* "$dir"/lib/*.so* 2> /dev/null | grep -o 'GLIBC_[0-9.]*' | sed 's/GLIBC_//' |
  sort -uV | tail -n1 > "$dir/lib/glibc/REQUIRED"

# --- what the steps read ---------------------------------------------------------------------
(cd "$kit/polydem" && tar -c potentials bench/in.dodeca_dense bench/in.ellipsoid_cundall \
  bench/wall_mesh/in.floor examples/hopper/in.hopper examples/hopper/log.hopper \
  examples/hopper/hopper.stl examples/hopper/floor.stl examples/hopper/gate.stl \
  tools/gpu/compare_runs.py tools/gpu/inputs tools/gpu/data) | tar -x -C "$dir/polydem"
gzip -9 "$dir/polydem/tools/gpu/data/silo.stl"    # 7.2 -> 1.4 MiB; run.sh unpacks it (python3)

# --- the plain styles' reference logs, with the bundled lmp -----------------------------------
log "reference logs (plain styles)"
t0=$(date +%s)
bash "$dir/run.sh" "$dir/ref" --references >&2 || { log "the reference runs failed"; exit 1; }
log "references: $(($(date +%s) - t0)) s"

# --- the bare-environment check -------------------------------------------------------------------
bash "$here/check_bare.sh" "$dir"
