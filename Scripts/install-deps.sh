#!/usr/bin/env bash
# Installs the Debian (bookworm) packages QuadCover needs, if any are missing.
# Runs apt-get as root, or through sudo for another user.
set -euo pipefail

packages=(
  cmake g++ make pkg-config
  libvtk9-dev python3-vtk9 python3-dev python3-numpy   # VTK 9.1 with its Python wrapping
  libeigen3-dev                                        # Eigen 3.4
  libsuitesparse-dev                                   # CHOLMOD for the sparse solves
  libopenblas0-pthread                                 # its BLAS: 3x faster factorizations
  libgtest-dev                                         # GoogleTest
  xvfb xauth                                           # off-screen pictures without a display
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if ((${#missing[@]} == 0)); then
  exit 0
fi

sudo=""
if [ "$(id -u)" -ne 0 ]; then
  sudo="sudo"
fi
echo "install-deps: installing ${missing[*]}"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
