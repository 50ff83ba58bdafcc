#!/bin/sh
# fetch-debian-source.sh PKG VERSION DESTDIR
#
# Downloads the tarballs of Debian source package PKG=VERSION into
# DESTDIR with apt-get, using a private apt configuration (deb-src sources
# file and package lists under DESTDIR/.apt): the system's apt configuration
# is never touched, no root needed. apt verifies the checksums against the
# signed Release file. Idempotent: when the orig tarball(s) are already in
# DESTDIR nothing is downloaded.
#
# Prints the absolute path of each orig tarball (one per line) on stdout;
# everything else goes to stderr.
#
# Environment: POLYDEM_DEBIAN_SUITE  (default bookworm; trixie, sid, ...),
#              POLYDEM_DEBIAN_MIRROR (default: the archive URI of the system's
#              own apt sources, i.e. the URI of its main Debian suite).
#
# Only the orig tarball(s) are needed: where the archive no longer serves the
# .dsc or the debian.tar.* (trixie's and sid's lammps answer 404 for them)
# but the orig tarballs arrive, each checked by apt against the signed
# Sources index, that is accepted with a warning.
set -eu

if [ $# -ne 3 ]; then
  echo "usage: $0 PKG VERSION DESTDIR" >&2
  exit 2
fi
pkg=$1
version=$2
destdir=$3

suite=${POLYDEM_DEBIAN_SUITE:-bookworm}

# private_apt_init, private_apt: an apt of our own (debian-archive-uri.sh)
. "$(dirname "$0")/debian-archive-uri.sh"

# upstream version: drop the epoch and the Debian revision
upver=${version#*:}
upver=${upver%-*}

list_origs() {
  # orig tarballs (main + components), not their signatures
  for f in "$destdir/${pkg}_${upver}.orig.tar."* "$destdir/${pkg}_${upver}.orig-"*.tar.*; do
    case $f in
      *.asc | *'*'*) continue ;;
    esac
    [ -f "$f" ] && echo "$f"
  done
  return 0
}

mkdir -p "$destdir"
destdir=$(cd "$destdir" && pwd)

# complete when the .dsc (or, if it is not served, the stamp written after a
# successful apt-get run) and at least one orig tarball are present
stamp="$destdir/.fetched-${pkg}_${version}"
if [ -f "$stamp" ] && [ -n "$(list_origs)" ]; then
  echo "fetch-debian-source: ${pkg}=${version} already in $destdir" >&2
  list_origs
  exit 0
fi

private_apt_init fetch-debian-source deb-src "$destdir" "$suite" || exit 1
apt_dir=$private_apt_dir

echo "fetch-debian-source: apt-get source --download-only ${pkg}=${version}" >&2
rc=0
aptlog="$apt_dir/source.log"
(cd "$destdir" && private_apt -q source --download-only "${pkg}=${version}" > "$aptlog" 2>&1) || rc=$?
cat "$aptlog" >&2

if [ -z "$(list_origs)" ]; then
  echo "fetch-debian-source: no orig tarball for ${pkg}=${version} in $destdir" >&2
  exit 1
fi
if [ $rc -ne 0 ]; then
  # e.g. trixie's lammps: the .dsc answers 404 but the tarballs (each
  # checked against the signed Sources index) arrive; sid's: the .dsc and the
  # debian.tar.xz answer 404, the orig arrives. Accept failures of those two
  # kinds of file, and only those: every orig tarball the Sources index lists
  # must be here.
  if grep -E '^E: Failed to fetch [a-z]+://' "$aptlog" |
    grep -vE '\.dsc |\.debian\.tar\.[a-z0-9]+ |\.diff\.gz ' | grep -q .; then
    echo "fetch-debian-source: apt-get failed ($rc) on more than the .dsc / debian.tar" >&2
    exit 1
  fi
  echo "fetch-debian-source: warning: only the .dsc or debian.tar failed (apt-get exited with $rc); using the orig tarball(s) apt verified" >&2
fi
touch "$stamp"
list_origs
