# shellcheck shell=bash
# shellcheck disable=SC2034  # the variables are for the scripts that source this file
# Sourced, with their arguments, by kokkos-source.sh and build-kokkos-cuda.sh
# (both take one argument, CACHE_DIR): exits 2 with a usage line unless there
# is exactly one; creates CACHE_DIR and sets
#   here         this folder (cmake/scripts)
#   cache        CACHE_DIR, absolute
#   tri_version  the Debian trilinos source package whose packages/kokkos is Kokkos 3.4.01
#   patch_file   the patch applied to that source (kokkos-cuda13.patch)
#   src          CACHE_DIR/kokkos-3.4.01-src, the patched source (made by kokkos-source.sh)
if [ $# -ne 1 ]; then
  echo "usage: $0 CACHE_DIR" >&2
  exit 2
fi
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
mkdir -p "$1"
cache=$(cd "$1" && pwd)
tri_version=13.2.0-4
patch_file="$here/kokkos-cuda13.patch"
src="$cache/kokkos-3.4.01-src"
