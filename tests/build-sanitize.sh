#!/usr/bin/env bash
# Configures and builds build-sanitize: everything (engine, tools, game, tests and the
# libFuzzer targets) with clang under AddressSanitizer + UndefinedBehaviorSanitizer.
# One build serves tests/run.sh's sanitized run and tests/fuzz/run.sh. A unity build (a
# few files compiled as one); the engine and the game's core at -O1 (the tests run
# about twice as fast as at -O0), the tests' own files and the programs' mains at -O0
# (glue around the engine: half the compile time). Linked by LLVM's lld: a sanitized
# test binary links in a third of GNU ld's time.
set -euo pipefail
cd "$(dirname "$0")/.."
CXX=clang++ cmake -S . -B build-sanitize -G Ninja -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -gline-tables-only" \
  -DCMAKE_EXE_LINKER_FLAGS=-fuse-ld=lld -DENGINE_SANITIZE=ON -DENGINE_FUZZ=ON -DCMAKE_UNITY_BUILD=ON >/dev/null
cmake --build build-sanitize
