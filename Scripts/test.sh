#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test (core, filters, Python, command line);
# then builds again with AddressSanitizer and UndefinedBehaviorSanitizer in build-asan/ and runs
# every test there too (Documentation/Development.md lists the one left out, install.examples).
set -euo pipefail
cd "$(dirname "$0")/.."
bash Scripts/install-deps.sh

start=$SECONDS
bash Scripts/build.sh
echo "test.sh: build $((SECONDS - start)) s"
start=$SECONDS
ctest --test-dir build --output-on-failure -j "$(nproc)"
echo "test.sh: tests $((SECONDS - start)) s"

start=$SECONDS
bash Scripts/build.sh asan
echo "test.sh: sanitizer build $((SECONDS - start)) s"
start=$SECONDS
# Whole stacks in UBSan's reports (ASan prints them anyway).
UBSAN_OPTIONS=print_stacktrace=1 ctest --test-dir build-asan --output-on-failure -j "$(nproc)"
echo "test.sh: sanitizer tests $((SECONDS - start)) s"
