#!/bin/sh
# fetch-debian-deb.sh SUITE DESTDIR PKG...
#
# Downloads the binary packages PKG... (amd64 or the machine's architecture)
# of Debian suite SUITE with apt-get download, using a private apt
# configuration (sources file and package lists under DESTDIR/.apt; the
# system's apt configuration and dpkg database are never touched, nothing
# is installed), and unpacks each with dpkg-deb -x into DESTDIR/root. apt
# verifies every .deb against the signed Release/Packages indexes.
# Idempotent: when DESTDIR/.fetched names the same packages, nothing is done.
#
# Used for Kokkos 4.5.1's headers and CMake config (sid's
# libtrilinos-kokkos-dev): the compile check of the /kk styles against LAMMPS
# 4 Feb 2025. Its libraries need a newer glibc than Debian 12's: they are
# unpacked (CMake's config checks that they exist) but never linked or run.
#
# Prints DESTDIR/root on stdout; everything else goes to stderr.
# Environment: POLYDEM_DEBIAN_MIRROR (default: the system's own archive URI).
set -eu

if [ $# -lt 3 ]; then
  echo "usage: $0 SUITE DESTDIR PKG..." >&2
  exit 2
fi
suite=$1
destdir=$2
shift 2
pkgs="$*"    # Debian package names: no blanks

# private_apt_init, private_apt: an apt of our own (debian-archive-uri.sh)
. "$(dirname "$0")/debian-archive-uri.sh"

mkdir -p "$destdir"
destdir=$(cd "$destdir" && pwd)
want="$suite $pkgs"
if [ -f "$destdir/.fetched" ] && [ "$(cat "$destdir/.fetched")" = "$want" ]; then
  echo "fetch-debian-deb: $pkgs ($suite) already in $destdir" >&2
  echo "$destdir/root"
  exit 0
fi
private_apt_init fetch-debian-deb deb "$destdir" "$suite" || exit 1
apt_dir=$private_apt_dir
mkdir -p "$apt_dir/debs"
rm -f "$apt_dir/debs/"*.deb
echo "fetch-debian-deb: apt-get download $pkgs ($suite)" >&2
# shellcheck disable=SC2086
(cd "$apt_dir/debs" && private_apt -q download $pkgs) >&2

rm -rf "$destdir/root"
mkdir -p "$destdir/root"
for d in "$apt_dir/debs/"*.deb; do
  echo "fetch-debian-deb: unpacking $(basename "$d")" >&2
  dpkg-deb -x "$d" "$destdir/root"
done
echo "$want" > "$destdir/.fetched"
echo "$destdir/root"
