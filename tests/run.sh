#!/usr/bin/env bash
# The README's second command: build and run the whole test suite twice, first in a
# Release build, then under AddressSanitizer + UndefinedBehaviorSanitizer; then a
# smoke run of every fuzz target (clang's libFuzzer, 5 s each, also under ASan + UBSan).
set -euo pipefail
cd "$(dirname "$0")/.."
tools/install-deps.sh
jobs=$(nproc)
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build
ctest --test-dir build --output-on-failure -j "$jobs"
# A unity build (the engine's files compiled a few at a time, as one): half the
# sanitized engine's compile time; the Release build stays file by file, as users build it.
cmake -S . -B build-sanitize -G Ninja -DCMAKE_BUILD_TYPE=Debug -DENGINE_SANITIZE=ON -DCMAKE_UNITY_BUILD=ON >/dev/null
cmake --build build-sanitize
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --test-dir build-sanitize --output-on-failure -j "$jobs"
tests/fuzz/run.sh 5
