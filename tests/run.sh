#!/usr/bin/env bash
# The README's second command: build and run the whole test suite twice, first in a
# Release build, then under AddressSanitizer + UndefinedBehaviorSanitizer (clang; heavy
# checks there take a sample); then a smoke run of every fuzz target (libFuzzer, 5 s
# each, in the same sanitized build). Prints where the time went.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc)
times=()
phase() {  # phase NAME COMMAND...: runs it, keeps its wall time
  local name=$1 start=$SECONDS
  shift
  "$@"
  times+=("$name $((SECONDS - start))")
}
sanitized_ctest() {
  ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    ctest --test-dir build-sanitize --output-on-failure -j "$jobs"
}
phase "install what is missing" tools/install-deps.sh
phase "configure Release" cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_UNITY_BUILD=ON >/dev/null
phase "build Release" cmake --build build
phase "test Release" ctest --test-dir build --output-on-failure -j "$jobs"
phase "configure and build sanitized" tests/build-sanitize.sh
phase "test sanitized" sanitized_ctest
phase "fuzz smoke" tests/fuzz/run.sh 5
printf '\n| step | seconds |\n|---|---:|\n'
total=0
for t in "${times[@]}"; do
  printf '| %s | %s |\n' "${t% *}" "${t##* }"
  total=$((total + ${t##* }))
done
printf '| total | %s |\n' "$total"
