#!/bin/bash
# Installs every Debian package POLYDEM needs (idempotent; run as root).
# Only apt-get is used. nvcc (for the CUDA compile check) is not a Debian
# package here: it is used from /usr/local/cuda when present.
set -euo pipefail

PKGS=(
  build-essential cmake ccache git xz-utils debian-archive-keyring
  libtrilinos-kokkos-dev            # Kokkos 3.4.01 (Serial) for the KOKKOS package
  libcgal-dev libgmp-dev libmpfr-dev libboost-dev libeigen3-dev
  libopenmpi-dev openmpi-bin
  libgtest-dev libbenchmark-dev
  libjpeg-dev libpng-dev zlib1g-dev # LAMMPS dump image
  python3 python3-numpy python3-matplotlib
)

missing=()
for p in "${PKGS[@]}"; do
  [[ $p == \#* ]] && continue
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#PKGS[@]} packages present"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
echo "install-deps: installing ${missing[*]}"
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
