#!/bin/bash
# kokkos-source.sh CACHE_DIR
#
# Makes sure CACHE_DIR/kokkos-3.4.01-src holds Kokkos 3.4.01, i.e.
# packages/kokkos of Debian's trilinos 13.2.0-4 source package (fetched with
# cmake/scripts/fetch-debian-source.sh into CACHE_DIR/src/trilinos, 166 MB, apt
# verifies it), patched with cmake/scripts/kokkos-cuda13.patch (CUDA 13 only; the
# host backends are unchanged). Prints the source directory (last line of
# stdout). Used by build-kokkos-cuda.sh (CUDA compile check) and
# build-kokkos-host.sh (the Kokkos that LAMMPS is built against).
# Idempotent; concurrent runs serialise on CACHE_DIR/.kokkos-src.lock.
set -euo pipefail
{
# the argument (CACHE_DIR: cache), here, tri_version, patch_file, src
# shellcheck source=SCRIPTDIR/kokkos-cache.sh
. "$(dirname "${BASH_SOURCE[0]}")/kokkos-cache.sh" "$@"
tri_pkg=trilinos
log() { echo "kokkos-source: $*" >&2; }
patch_sum=$(sha256sum "$patch_file" | cut -d' ' -f1)
ready() { [ -f "$src/.polydem-patched" ] && [ "$(cat "$src/.polydem-patched")" = "$patch_sum" ]; }
if ready; then
  echo "$src"
  exit 0
fi
exec 8> "$cache/.kokkos-src.lock"
flock 8
if ! ready; then
  tarball=$("$here/fetch-debian-source.sh" "$tri_pkg" "$tri_version" "$cache/src/$tri_pkg" | head -n1)
  log "extracting packages/kokkos from $(basename "$tarball")"
  tmp="$cache/.kokkos-extract.$$"
  rm -rf "$tmp" "$src"
  mkdir -p "$tmp"
  tar -xf "$tarball" -C "$tmp" --wildcards --no-wildcards-match-slash '*/packages/kokkos'
  mv "$tmp"/*/packages/kokkos "$src"
  rm -rf "$tmp"
  log "applying $(basename "$patch_file")"
  patch -p1 -d "$src" --forward --batch < "$patch_file" >&2
  echo "$patch_sum" > "$src/.polydem-patched"
fi
echo "$src"
exit 0
}
