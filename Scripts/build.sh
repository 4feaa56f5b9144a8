#!/usr/bin/env bash
# Configures and builds QuadCover (Debian's Python for the wrapping):
#   build.sh        Release, in build/
#   build.sh asan   with AddressSanitizer and UndefinedBehaviorSanitizer, in build-asan/
#                   (QUADCOVER_SANITIZE, Documentation/Development.md)
set -euo pipefail
cd "$(dirname "$0")/.."
case "${1:-}" in
  "")
    cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DPython3_EXECUTABLE=/usr/bin/python3
    cmake --build build -j "$(nproc)"
    ;;
  asan)
    # -O2 with line tables only (-g1): the reports name file and line, for a fifth less compile
    # time than -g. No benchmark program: no test runs it.
    cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG" \
      -DPython3_EXECUTABLE=/usr/bin/python3 -DQUADCOVER_SANITIZE=address,undefined \
      -DQUADCOVER_BUILD_BENCHMARKS=OFF
    cmake --build build-asan -j "$(nproc)"
    ;;
  *)
    echo "usage: $0 [asan]" >&2
    exit 2
    ;;
esac
