#!/usr/bin/env bash
# Runs every fuzz target for SECONDS each (default 5: CI's smoke run), one per core at a
# time, under ASan and UBSan, seeded from the bundled files; prints a table of
# executions, coverage and crashes. A long run: tests/fuzz/run.sh 3600. Builds
# build-sanitize first (clang, see tests/build-sanitize.sh). A crash leaves its input in
# build-sanitize/crashes/TARGET/ and fails the script; kept in tests/fuzz/regressions/TARGET/
# once fixed, every run tries it first.
set -euo pipefail
cd "$(dirname "$0")/../.."
seconds=${1:-5}
tests/build-sanitize.sh
build=build-sanitize
work=$build/corpus
rm -rf "$work" && mkdir -p "$work"
seed() {  # seed TARGET FILES...: those and the target's regressions
  local target=$1; shift
  mkdir -p "$work/$target"
  for f in "$@" tests/fuzz/regressions/"$target"/*; do [ -f "$f" ] && cp "$f" "$work/$target/"; done
  return 0
}
seed map tests/fuzz/seeds/room.map tests/bad/*.map
seed grid tests/fuzz/seeds/room.grid tests/bad/*.grid
seed demo tests/fuzz/seeds/walk.demo maps/*.demo
seed cameras maps/*.cameras maps/*.path maps/*.route
seed png maps/textures/lantern.png maps/textures/lamp.png maps/textures/hazard.png tests/bad/fake.png
seed encode maps/textures/lamp.png  # any bytes: its first two choose the image's shape
seed wad tests/fuzz/seeds/map01.wad
seed udmf tests/fuzz/seeds/textmap.udmf
seed lmp tests/fuzz/seeds/walk.lmp tests/fuzz/seeds/old.lmp
seed dmx tests/fuzz/seeds/beep.dmx
seed mus tests/fuzz/seeds/tune.mus tests/fuzz/seeds/tune.mid
seed save tests/fuzz/seeds/room.dsg tests/golden/saves/*.dsg
seed world tests/fuzz/seeds/world.bin
seed net tests/fuzz/seeds/game.net tests/fuzz/seeds/server.net
mkdir -p "$work/bsp"
$build/tools/pseudo3d-mapc tests/fuzz/seeds/room.map -o "$work/bsp/room.bsp" >/dev/null
$build/tools/pseudo3d-mapc tests/fuzz/seeds/room.grid -o "$work/bsp/grid.bsp" >/dev/null
targets=(map grid bsp demo cameras png encode wad udmf lmp dmx mus save world net)
fuzz() {  # fuzz TARGET: runs it, leaves its table row in $build/fuzz_TARGET.row
  local target=$1 log="$build/fuzz_$1.log" crashes=0
  rm -rf "$build/crashes/$target" && mkdir -p "$build/crashes/$target"
  if ! $build/tests/fuzz/fuzz_$target "$work/$target" -max_total_time="$seconds" -timeout=20 -rss_limit_mb=2560 \
      -print_final_stats=1 -artifact_prefix="$build/crashes/$target/" >"$log" 2>&1; then
    crashes=$(ls "$build/crashes/$target" | wc -l)
    [ "$crashes" -gt 0 ] || crashes=1  # failed without leaving an input: still a failure
  fi
  local runs edges
  runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo 0)
  edges=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | grep -o '[0-9]*' || echo 0)
  printf '| %s | %s | %s | %s | %s |\n' "$target" "$seconds" "$runs" "$edges" "$crashes" >"$build/fuzz_$target.row"
}
# One target per core at a time (a libFuzzer process is single-threaded).
for target in "${targets[@]}"; do
  while [ "$(jobs -rp | wc -l)" -ge "$(nproc)" ]; do wait -n || true; done
  fuzz "$target" &
done
wait
printf '| target | seconds | executions | coverage (edges) | crashes |\n|---|---:|---:|---:|---:|\n'
status=0
for target in "${targets[@]}"; do
  cat "$build/fuzz_$target.row"
  [ "$(cut -d'|' -f6 "$build/fuzz_$target.row" | tr -d ' ')" = 0 ] || status=1
done
if [ $status -ne 0 ]; then
  echo "a fuzz target crashed: see $build/fuzz_TARGET.log and $build/crashes/" >&2
fi
exit $status
