#!/usr/bin/env bash
# The README's first command: install what is missing, build (Release), compile the
# default map and capture its showcase views into out/.
set -euo pipefail
cd "$(dirname "$0")/.."
tools/install-deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build
mkdir -p out
build/tools/mapc maps/outpost.map -o out/outpost.bsp --stats
build/tools/capture out/outpost.bsp --cameras maps/outpost.cameras -o out --stats
echo "wrote out/outpost.bsp and the captures out/*.png"
