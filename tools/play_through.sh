#!/usr/bin/env bash
# The game played as a new user plays it, in a real window under Xvfb, driven by
# xdotool: the title, the menu, New Game at Hurt Me Plenty, a walk, a save typed into
# its slot, quit with Doom's question; then the game started again, the save loaded:
# the player where it stood. Screenshots of each step, and how much of the view
# after the load is the view before the quit.
#
#   tools/play_through.sh [--out DIR] [--build DIR] [--iwad WAD]
#
# Writes DIR/NN_step.png (the window) and DIR/play_through.png (the steps side by
# side), and prints the share of the view's pixels equal after the load. The settings
# and saves go to DIR/xdg (XDG_CONFIG_HOME, XDG_DATA_HOME), never the user's own.
# Needs xvfb, xdotool, imagemagick and a build of the game.
set -euo pipefail
cd "$(dirname "$0")/.."
out=out/play_through build=build iwad=/usr/share/games/doom/freedoom2.wad
while [ $# -gt 0 ]; do
  case $1 in
    --out) out=$2; shift 2 ;;
    --build) build=$2; shift 2 ;;
    --iwad) iwad=$2; shift 2 ;;
    --help|-h) sed -n '2,14p' "$0"; exit 0 ;;
    *) echo "$0: unknown argument $1" >&2; exit 2 ;;
  esac
done
for tool in Xvfb xdotool import convert compare "$build/game/pseudo3d"; do
  command -v "$tool" >/dev/null || { echo "$0: $tool is missing" >&2; exit 1; }
done
mkdir -p "$out"
out=$(cd "$out" && pwd)
rm -rf "$out/xdg" "$out"/[0-9][0-9]_*.png
game=$(cd "$build/game" && pwd)/game
display=:$((90 + RANDOM % 100))
Xvfb "$display" -screen 0 800x600x24 >/dev/null 2>&1 &
xvfb=$!
trap 'kill $xvfb 2>/dev/null' EXIT
sleep 1
export DISPLAY=$display XDG_CONFIG_HOME=$out/xdg/config XDG_DATA_HOME=$out/xdg/data

step=0
shot() {  # the game's window, named
  step=$((step + 1))
  import -window "$wid" "$out/$(printf '%02d' $step)_$1.png"
}
start_game() {
  "$game" --iwad "$iwad" --window 640x400 --nosound >>"$out/game.log" 2>&1 &
  pid=$!
  wid=""
  for _ in $(seq 300); do wid=$(xdotool search --name pseudo3d 2>/dev/null | tail -1 || true); [ -n "$wid" ] && break; sleep 0.1; done
  [ -n "$wid" ] || { echo "$0: the game's window did not open (see $out/game.log)" >&2; exit 1; }
  xdotool windowfocus "$wid"
  sleep 2
}
hold() { xdotool keydown "$1"; sleep "$2"; xdotool keyup "$1"; }

: > "$out/game.log"
start_game
shot title
xdotool key Escape; sleep 0.5; shot menu
xdotool key Return; sleep 0.5; shot skill
xdotool key Return; sleep 2.5; shot start
hold w 1.2; hold Right 0.3; sleep 1.5; shot walked
xdotool key F2; sleep 0.4; xdotool key Return; sleep 0.3; xdotool type --delay 80 pseudo; sleep 0.3; shot save
xdotool key Return; sleep 1; shot saved
xdotool key F10; sleep 0.5; shot quit
xdotool key y
for _ in $(seq 50); do kill -0 $pid 2>/dev/null || break; sleep 0.1; done
if kill -0 $pid 2>/dev/null; then echo "$0: the game did not quit" >&2; exit 1; fi

start_game
shot again
xdotool key Escape; sleep 0.4; xdotool key Down; sleep 0.2; xdotool key Down; sleep 0.2; xdotool key Return; sleep 0.5
shot load
xdotool key Return; sleep 2.5; shot loaded
xdotool key F10; sleep 0.3; xdotool key y
wait $pid 2>/dev/null || true

# The view (above the status bar, below the message line) before the quit and after the load.
geometry=$(identify -format '%wx%h' "$out"/*_walked.png)
w=${geometry%x*} h=${geometry#*x}
crop="${w}x$((h * 130 / 200))+0+$((h * 20 / 200))"
convert "$out"/*_walked.png -crop "$crop" +repage "$out/xdg/before.png"
convert "$out"/*_loaded.png -crop "$crop" +repage "$out/xdg/after.png"
differ=$(compare -metric AE "$out/xdg/before.png" "$out/xdg/after.png" null: 2>&1 || true)
total=$((w * h * 130 / 200))
printf 'the view after the load: %.2f%% of its pixels as before the quit\n' \
  "$(echo "(${total} - ${differ%% *}) * 100 / ${total}" | bc -l)"
montage "$out"/[0-9][0-9]_*.png -tile 4x -geometry 320x200+2+2 "$out/play_through.png" 2>/dev/null ||
  convert "$out"/[0-9][0-9]_*.png -resize 320x200 +append "$out/play_through.png"
echo "wrote $out/play_through.png"
