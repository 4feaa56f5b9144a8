#!/usr/bin/env bash
# Configures and builds QuadCover in build/ (Release, Debian's Python for the wrapping).
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DPython3_EXECUTABLE=/usr/bin/python3
cmake --build build -j "$(nproc)"
