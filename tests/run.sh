#!/usr/bin/env bash
# The README's second command: build and run the whole test suite twice, first in a
# Release build, then under AddressSanitizer + UndefinedBehaviorSanitizer (clang; heavy
# checks there take a sample); then a smoke run of every fuzz target (libFuzzer, 5 s
# each, in the same sanitized build). Prints where the time went.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc)
times=()
cpu_ticks() {  # prints "busy total": the machine's CPU time so far, in clock ticks
  awk '/^cpu /{print $2 + $3 + $4 + $7 + $8, $2 + $3 + $4 + $5 + $6 + $7 + $8; exit}' /proc/stat
}
phase() {  # phase NAME COMMAND...: runs it, keeps its wall time and how busy the cores were
  local name=$1 start=$SECONDS before after
  shift
  before=$(cpu_ticks)
  "$@"
  after=$(cpu_ticks)
  times+=("$name|$((SECONDS - start))|$(echo "$before $after" | awk '{d = $4 - $2; print d ? int(100 * ($3 - $1) / d) : 0}')")
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
printf '\n| step | seconds | cores busy |\n|---|---:|---:|\n'
total=0
for t in "${times[@]}"; do
  IFS='|' read -r name seconds busy <<<"$t"
  printf '| %s | %s | %s%% |\n' "$name" "$seconds" "$busy"
  total=$((total + seconds))
done
printf '| total | %s | |\n' "$total"
