#!/usr/bin/env bash
# Installs the Debian (bookworm) packages QuadCover needs, if any are missing.
# Runs apt-get as root, or through sudo for another user.
set -euo pipefail

packages=(
  cmake g++ make pkg-config
  # ParaView 5.11 and its own VTK 9.2, which builds everything (C++, Python, the plugin);
  # python3-paraview replaces python3-vtk9 and libvtk9-dev (apt removes them: they conflict)
  paraview paraview-dev python3-paraview python3-dev python3-numpy
  openmpi-bin                                          # mpiexec, for pvbatch on several ranks
  libopenmpi-dev libdouble-conversion-dev              # found by ParaView's CMake package (MPI::MPI_C)
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
