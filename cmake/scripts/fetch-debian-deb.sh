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

# debian_mirror: POLYDEM_DEBIAN_MIRROR or the system's own archive URI
. "$(dirname "$0")/debian-archive-uri.sh"
mirror=$(debian_mirror fetch-debian-deb) || exit 1
keyring=/usr/share/keyrings/debian-archive-keyring.gpg

mkdir -p "$destdir"
destdir=$(cd "$destdir" && pwd)
want="$suite $pkgs"
if [ -f "$destdir/.fetched" ] && [ "$(cat "$destdir/.fetched")" = "$want" ]; then
  echo "fetch-debian-deb: $pkgs ($suite) already in $destdir" >&2
  echo "$destdir/root"
  exit 0
fi
if [ ! -r "$keyring" ]; then
  echo "fetch-debian-deb: $keyring missing (apt-get install debian-archive-keyring)" >&2
  exit 1
fi

apt_dir="$destdir/.apt"
mkdir -p "$apt_dir/sources.list.d" "$apt_dir/lists/partial" "$apt_dir/cache/archives/partial" "$apt_dir/debs"
cat > "$apt_dir/sources.list.d/polydem.sources" << EOF
Types: deb
URIs: $mirror
Suites: $suite
Components: main
Signed-By: $keyring
EOF
# Dir::State::status=/dev/null: resolve against an empty dpkg database, so
# the system's installed packages play no part
set -- -o Dir::Etc::SourceList=/dev/null \
  -o Dir::Etc::SourceParts="$apt_dir/sources.list.d" \
  -o Dir::State::Lists="$apt_dir/lists" \
  -o Dir::State::status=/dev/null \
  -o Dir::Cache="$apt_dir/cache" \
  -o Dir::Cache::pkgcache= -o Dir::Cache::srcpkgcache=
if [ "$(id -u)" = 0 ]; then
  set -- "$@" -o APT::Sandbox::User=root
fi

echo "fetch-debian-deb: apt-get update (private deb list: $mirror $suite)" >&2
apt-get "$@" -q update >&2
rm -f "$apt_dir/debs/"*.deb
echo "fetch-debian-deb: apt-get download $pkgs ($suite)" >&2
# shellcheck disable=SC2086
(cd "$apt_dir/debs" && apt-get "$@" -q download $pkgs) >&2

rm -rf "$destdir/root"
mkdir -p "$destdir/root"
for d in "$apt_dir/debs/"*.deb; do
  echo "fetch-debian-deb: unpacking $(basename "$d")" >&2
  dpkg-deb -x "$d" "$destdir/root"
done
echo "$want" > "$destdir/.fetched"
echo "$destdir/root"
