#!/usr/bin/env bash
# Our front end's screens against Chocolate Doom's, pixel by pixel, at 320x200: the
# title, the main menu, episodes and skills, options, sound volumes, Read This!, load,
# a game, save with a typed description, the save's slot when loading, quit.
#
#   tools/peer_menus.sh [--out DIR] [--build DIR] [IWAD ...]
#
# For each IWAD (default: freedoom1 and freedoom2) one walk through the menus, written
# once as steps at seconds: Chocolate Doom plays it in a window under Xvfb, driven by
# xdotool, each screen taken with its own screenshot key (a 320x200 PCX of its screen);
# our game plays the same keys headless from a key script (game --headless --script) at
# the same tics. Per screen: the share of pixels exactly Chocolate's colour. What timing
# decides is taken as it comes: the skull blinks every 8 tics, the status bar's face
# glances every half second, so ours is drawn at each of 24 tics around and the
# closest counted (Chocolate's skull and face); Doom picks the quit message by the tic
# F10 is pressed at, so ours asks at each of 8 tics. Writes DIR/results.txt and, per
# screen, DIR/<iwad>_<screen>.png (ours | Chocolate's | differences in red).
# Chocolate's side is timed by the clock: on a busy machine its keys may arrive late
# enough to leave it on another screen (the title's demo instead of the game), which
# the pictures show; run it on a quiet machine. Needs chocolate-doom, freedoom, xvfb,
# xdotool, imagemagick (Debian packages) and a build of the game.
set -euo pipefail
cd "$(dirname "$0")/.."
out=out/peer_menus build=build
while [ $# -gt 0 ]; do
  case $1 in
    --out) out=$2; shift 2 ;;
    --build) build=$2; shift 2 ;;
    --help|-h) sed -n '2,18p' "$0"; exit 0 ;;
    --*) echo "$0: unknown option $1" >&2; exit 2 ;;
    *) break ;;
  esac
done
for tool in /usr/games/chocolate-doom Xvfb xdotool convert compare "$build/game/pseudo3d"; do
  command -v "$tool" >/dev/null || { echo "$0: $tool is missing" >&2; exit 1; }
done
iwads=("$@")
[ ${#iwads[@]} -gt 0 ] || iwads=(freedoom1 freedoom2)
mkdir -p "$out"
out=$(cd "$out" && pwd)
game=$(cd "$build/game" && pwd)/game
work=$(mktemp -d /tmp/peer-menus.XXXXXX)
display=:$((90 + RANDOM % 100))
Xvfb "$display" -screen 0 1024x768x24 >/dev/null 2>&1 &
xvfb=$!
trap 'kill $xvfb 2>/dev/null; rm -rf "$work"' EXIT
sleep 1

# Chocolate's settings: Doom's defaults, PrintScreen (its scan code 126) for screenshots
# as 320x200 PCX files, no sound.
printf 'screenblocks 9\ndetaillevel 0\nshow_messages 1\nusegamma 0\nmouse_sensitivity 5\n' > "$work/default.cfg"
printf 'sfx_volume 8\nmusic_volume 8\n' >> "$work/default.cfg"
printf 'png_screenshots 0\nkey_menu_screenshot 126\nfullscreen 0\nwindow_width 320\nwindow_height 200\n' \
  > "$work/extra.cfg"
printf 'aspect_ratio_correct 0\n' >> "$work/extra.cfg"
printf 'vanilla_keyboard_mapping 1\ngrabmouse 0\nstartup_delay 0\n' >> "$work/extra.cfg"

# The walk: "SECONDS key NAME", "SECONDS type TEXT", "SECONDS shot NAME". The title and
# the main menu over it first, then a game (Hurt Me Plenty) whose world waits while the
# menus are open over it, so that the picture under them holds still. Doom II's New
# Game asks the skill at once (MAP01); Doom's asks the episode first (the second:
# E2M1's start, where our view is closer to Chocolate's than E1M1's, docs/pixels.md).
walk() {
  echo "1.0 shot title"
  echo "1.4 key escape"; echo "1.8 shot main"
  echo "2.2 key enter"
  if [ "$1" = freedoom1 ]; then echo "2.6 shot episode"; echo "2.8 key down"; echo "3.0 key enter"; fi
  echo "3.4 shot skill"; echo "3.8 key enter"
  echo "7.0 shot game"
  echo "7.4 key escape"; echo "7.8 key down"; echo "8.2 key enter"; echo "8.6 shot options"
  for s in 9.0 9.2 9.4 9.6 9.8; do echo "$s key down"; done
  echo "10.2 key enter"; echo "10.6 shot sound"
  echo "11.0 key escape"; echo "11.4 key f1"; echo "11.8 shot help"
  echo "12.2 key escape"; echo "12.6 key escape"; echo "13.0 key down"; echo "13.4 key enter"; echo "13.8 shot load_empty"
  echo "14.2 key escape"; echo "14.6 key escape"; echo "15.0 key down"; echo "15.4 key enter"; echo "15.8 key enter"
  echo "16.2 type hello"; echo "17.0 window save_typed"; echo "17.4 key enter"
  echo "18.6 key escape"; echo "19.0 key up"; echo "19.4 key enter"; echo "19.8 shot load_saved"
  echo "20.2 key escape"; echo "23.0 quit quit"  # after the message line has cleared (4 s)
}

# Then each loads the other's save from the first slot (Load Game, the slot, and the
# melt): Chocolate Doom the one our game wrote, ours Chocolate's.
walk_load() {
  echo "1.4 key escape"; echo "1.8 key down"; echo "2.2 key down"; echo "2.6 key enter"; echo "3.0 key enter"
  echo "6.0 shot loaded"
}

xkey() {  # Doom's key names as X's
  case $1 in
    escape) echo Escape ;; enter) echo Return ;; up) echo Up ;; down) echo Down ;; f1) echo F1 ;; f10) echo F10 ;;
    *) echo "$1" ;;
  esac
}

run_chocolate() {  # iwad dir walk
  local iwad=$1 dir=$2 walk=$3
  mkdir -p "$dir/home"
  (cd "$dir" && HOME="$dir/home" DISPLAY=$display exec /usr/games/chocolate-doom -iwad "/usr/share/games/doom/$iwad.wad" \
     -nosound -config "$work/default.cfg" -extraconfig "$work/extra.cfg" >"$dir/log.txt" 2>&1) &
  local pid=$! wid=""
  for _ in $(seq 300); do wid=$(DISPLAY=$display xdotool search --class chocolate 2>/dev/null | tail -1 || true); [ -n "$wid" ] && break; sleep 0.1; done
  [ -n "$wid" ] || { echo "$0: Chocolate Doom's window did not open (see $dir/log.txt)" >&2; exit 1; }
  sleep 1  # its first frames
  DISPLAY=$display xdotool windowfocus "$wid"
  local start; start=$(date +%s.%N) shots=0
  while read -r at what arg; do
    sleep "$(echo "$start + $at - $(date +%s.%N)" | bc | sed 's/^-.*/0/')"
    case $what in
      key) DISPLAY=$display xdotool key "$(xkey "$arg")" ;;
      type) DISPLAY=$display xdotool type --delay 60 "$arg" ;;
      shot)  # Chocolate's own screenshot, DOOMnn.pcx, numbered from 00
        DISPLAY=$display xdotool key Print; sleep 0.3
        local pcx; pcx=$(printf '%s/DOOM%02d.pcx' "$dir" $shots)
        if [ -f "$pcx" ]; then convert "$pcx" "$dir/$arg.png"; shots=$((shots + 1)); fi ;;
      quit)  # F10 and its question, taken from the window (the screenshot key would answer it)
        DISPLAY=$display xdotool key F10; sleep 0.4
        DISPLAY=$display import -window "$wid" "$dir/$arg.png"; echo "$arg" >> "$dir/window_shots" ;;
      window)  # the window itself (its screenshot key would type into a save's slot), 320x200 at 1:1
        DISPLAY=$display import -window "$wid" "$dir/$arg.png"; echo "$arg" >> "$dir/window_shots" ;;
    esac
  done < <($walk "$iwad")
  kill $pid 2>/dev/null || true
  wait $pid 2>/dev/null || true
}

# Ours: the same walk as a key script, each shot taken at the 24 tics around its time
# (Chocolate's keys arrive a few tics late, or early).
run_ours() {  # iwad dir walk
  local iwad=$1 dir=$2 walk=$3
  mkdir -p "$dir"
  $walk "$iwad" | while read -r at what arg; do
    local tic; tic=$(echo "$at * 35 / 1" | bc)
    case $what in
      shot|window) for k in $(seq 0 23); do echo "$((tic - 4 + k)) shot ${arg}_$k.png"; done ;;
      quit)  # Doom picks the message by the tic F10 is pressed at: each of the 8
        for k in $(seq 0 7); do
          echo "$((tic + k)) key f10"; echo "$((tic + k)) shot ${arg}_$k.png"; echo "$((tic + k)) key escape"
        done ;;
      *) echo "$tic $what $arg" ;;
    esac
  done | sort -n -s -k1,1 > "$dir/script.txt"
  XDG_DATA_HOME="$dir/data" XDG_CONFIG_HOME="$dir/config" \
    "$game" --iwad "/usr/share/games/doom/$iwad.wad" --headless --script "$dir/script.txt" --out "$dir" >/dev/null
}

: > "$out/results.txt"
printf '%-10s %-18s %s\n' iwad screen "equal pixels" >> "$out/results.txt"
compare_screens() {  # iwad chocolate-dir ours-dir [label-prefix]
  local iwad=$1 theirs_dir=$2 ours_dir=$3 prefix=${4:-}
  for theirs in "$theirs_dir"/*.png; do
    screen=$(basename "$theirs" .png)
    best=-1 best_k=0 fuzz=0
    # The window's colours are the palette's to 6 bits (Chocolate's VGA rounding).
    grep -qx "$screen" "$theirs_dir/window_shots" 2>/dev/null && fuzz=2.5%
    for k in $(seq 0 23); do
      ours="$ours_dir/${screen}_$k.png"
      [ -f "$ours" ] || continue
      differ=$(compare -metric AE -fuzz $fuzz "$ours" "$theirs" null: 2>&1 || true)
      equal=$((64000 - ${differ%% *}))
      if [ "$equal" -gt "$best" ]; then best=$equal best_k=$k; fi
    done
    ours="$ours_dir/${screen}_$best_k.png"
    printf '%-10s %-18s %6.2f%%\n' "$iwad" "$prefix$screen" "$(echo "$best * 100 / 64000" | bc -l)" >> "$out/results.txt"
    compare -fuzz $fuzz -highlight-color red -lowlight-color none "$ours" "$theirs" "$work/diff.png" 2>/dev/null || true
    convert "$ours" "$theirs" "$work/diff.png" +append "$out/${iwad}_$prefix$screen.png"
  done
}
for iwad in "${iwads[@]}"; do
  w=$work/$iwad
  run_chocolate "$iwad" "$w/chocolate" walk
  run_ours "$iwad" "$w/ours" walk
  compare_screens "$iwad" "$w/chocolate" "$w/ours"
  # Each side's save into the other's first slot.
  theirs_saves=$w/chocolate_loads/home/.local/share/chocolate-doom/savegames/$iwad.wad
  ours_saves=$w/ours_loads/data/pseudo3d/savegames/$iwad.wad
  mkdir -p "$theirs_saves" "$ours_saves"
  cp "$w/ours/data/pseudo3d/savegames/$iwad.wad/doomsav0.dsg" "$theirs_saves/"
  cp "$w/chocolate/home/.local/share/chocolate-doom/savegames/$iwad.wad/doomsav0.dsg" "$ours_saves/"
  run_chocolate "$iwad" "$w/chocolate_loads" walk_load
  run_ours "$iwad" "$w/ours_loads" walk_load
  compare_screens "$iwad" "$w/chocolate_loads" "$w/ours_loads" "each_loads_"
done
cat "$out/results.txt"
