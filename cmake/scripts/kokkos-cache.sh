# shellcheck shell=bash
# shellcheck disable=SC2034  # the variables are for the scripts that source this file
# Sourced, with their arguments, by kokkos-source.sh, build-kokkos-cuda.sh
# (both take one argument, CACHE_DIR) and build-kokkos-host.sh (CACHE_DIR
# VARIANT, named in kokkos_cache_usage before sourcing): exits 2 with a usage
# line unless the arguments are as many as the usage names; creates CACHE_DIR
# and sets
#   here         this folder (cmake/scripts)
#   cache        CACHE_DIR, absolute
#   tri_version  the Debian trilinos source package whose packages/kokkos is Kokkos 3.4.01
#   patch_file   the patch applied to that source (kokkos-cuda13.patch)
#   src          CACHE_DIR/kokkos-3.4.01-src, the patched source (made by kokkos-source.sh)
kokkos_cache_usage=${kokkos_cache_usage:-CACHE_DIR}
# shellcheck disable=SC2086  # the usage's words counted
if [ $# -ne "$(set -f; set -- $kokkos_cache_usage; echo $#)" ]; then
  echo "usage: $0 $kokkos_cache_usage" >&2
  exit 2
fi
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
mkdir -p "$1"
cache=$(cd "$1" && pwd)
tri_version=13.2.0-4
patch_file="$here/kokkos-cuda13.patch"
src="$cache/kokkos-3.4.01-src"
