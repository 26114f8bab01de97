#!/usr/bin/env bash
# The README's first command: install what is missing, build (Release), compile the
# default map, capture its showcase views into out/, and start the game when a
# display is present.
set -euo pipefail
cd "$(dirname "$0")/.."
tools/install-deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build
mkdir -p out
build/tools/pseudo3d-mapc maps/outpost.map -o out/outpost.bsp --stats
build/tools/pseudo3d-capture out/outpost.bsp --cameras maps/outpost.cameras -o out --stats
echo "wrote out/outpost.bsp and the captures out/*.png"
if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]; then
  echo "starting the game: W/S/A/D and the mouse to move, Space opens doors, F1 for the keys, Esc for the menu"
  build/game/pseudo3d out/outpost.bsp
fi
