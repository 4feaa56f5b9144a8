#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test (core, filters, Python, command line).
set -euo pipefail
cd "$(dirname "$0")/.."
bash Scripts/install-deps.sh
bash Scripts/build.sh
ctest --test-dir build --output-on-failure -j "$(nproc)"
