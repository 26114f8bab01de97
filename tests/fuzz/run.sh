#!/usr/bin/env bash
# Runs every fuzz target for SECONDS each (default 5: CI's smoke run), under ASan and
# UBSan, seeded from the bundled files; prints a table of executions, coverage and
# crashes. A long run: tests/fuzz/run.sh 3600. Builds build-fuzz with clang first.
# A crash leaves its input in build-fuzz/crashes/TARGET/ and fails the script.
set -euo pipefail
cd "$(dirname "$0")/../.."
seconds=${1:-5}
CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DENGINE_FUZZ=ON -DCMAKE_UNITY_BUILD=ON >/dev/null
cmake --build build-fuzz
work=build-fuzz/corpus
rm -rf "$work" && mkdir -p "$work"
seed() {  # seed TARGET FILES...
  local target=$1; shift
  mkdir -p "$work/$target"
  for f in "$@"; do [ -f "$f" ] && cp "$f" "$work/$target/"; done
  return 0
}
seed map tests/fuzz/seeds/room.map tests/bad/*.map
seed grid tests/fuzz/seeds/room.grid tests/bad/*.grid
seed demo tests/fuzz/seeds/walk.demo maps/*.demo
seed cameras maps/*.cameras maps/*.path maps/*.route
seed png maps/textures/lantern.png maps/textures/lamp.png maps/textures/hazard.png tests/bad/fake.png
seed wad tests/fuzz/seeds/map01.wad
seed udmf tests/fuzz/seeds/textmap.udmf
seed lmp tests/fuzz/seeds/walk.lmp tests/fuzz/seeds/old.lmp
seed dmx tests/fuzz/seeds/beep.dmx
seed mus tests/fuzz/seeds/tune.mus tests/fuzz/seeds/tune.mid
seed save tests/fuzz/seeds/room.dsg tests/golden/saves/*.dsg
mkdir -p "$work/bsp"
if [ -x build/tools/mapc ]; then
  build/tools/mapc tests/fuzz/seeds/room.map -o "$work/bsp/room.bsp" >/dev/null
  build/tools/mapc tests/fuzz/seeds/room.grid -o "$work/bsp/grid.bsp" >/dev/null
fi
printf '| target | seconds | executions | coverage (edges) | crashes |\n|---|---:|---:|---:|---:|\n'
status=0
for target in map grid bsp demo cameras png wad udmf lmp dmx mus save; do
  mkdir -p "build-fuzz/crashes/$target"
  log="build-fuzz/fuzz_$target.log"
  if build-fuzz/tests/fuzz/fuzz_$target "$work/$target" -max_total_time="$seconds" -timeout=20 -rss_limit_mb=2560 \
      -print_final_stats=1 -artifact_prefix="build-fuzz/crashes/$target/" >"$log" 2>&1; then
    crashes=0
  else
    crashes=$(ls "build-fuzz/crashes/$target" | wc -l)
    status=1
  fi
  runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo 0)
  edges=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | grep -o '[0-9]*' || echo 0)
  printf '| %s | %s | %s | %s | %s |\n' "$target" "$seconds" "$runs" "$edges" "$crashes"
done
if [ $status -ne 0 ]; then
  echo "a fuzz target crashed: see build-fuzz/fuzz_TARGET.log and build-fuzz/crashes/" >&2
fi
exit $status
