#!/usr/bin/env bash
# Our frame beside Chocolate Doom's, from the player start of WAD maps, at 320x200
# (Doom's focal length of 160 pixels: a 90-degree field of view), one row per map:
#
#   tools/peer_frames.sh OUT.png freedoom2:MAP01 freedoom2:MAP02 freedoom1:E1M1 ...
#
# Chocolate Doom runs headless: a demo of a few empty tics (skill 3; NOMONSTERS=1 leaves monsters out) is
# played with -timedemo under SDL's dummy video driver, which saves every presented
# frame when SDL_VIDEO_DUMMY_SAVE_FRAMES=1; the last one is the view after the tics.
# Needs chocolate-doom, freedoom and imagemagick (Debian packages) and a Release build.
set -euo pipefail
cd "$(dirname "$0")/.."
[ $# -ge 2 ] || { echo "usage: $0 OUT.png WAD:MAP [WAD:MAP...]" >&2; exit 2; }
out=$1
shift
work=$(mktemp -d /tmp/peer-frames.XXXXXX)
trap 'rm -rf "$work"' EXIT
rows=()
for spec in "$@"; do
  wad=${spec%%:*} map=${spec#*:}
  iwad=/usr/share/games/doom/$wad.wad
  if [[ $map =~ ^E([1-4])M([1-9])$ ]]; then episode=${BASH_REMATCH[1]} number=${BASH_REMATCH[2]};
  else episode=1 number=$((10#${map#MAP})); fi
  # Demo v1.9: version, skill, episode, map, deathmatch, respawn, fast, nomonsters, player,
  # four players present; then 4 bytes per tic; 0x80 ends it.
  printf "$(printf '\\x%02x' 109 2 "$episode" "$number" 0 0 0 "${NOMONSTERS:-0}" 0 1 0 0 0)" > "$work/start.lmp"
  head -c 8 /dev/zero >> "$work/start.lmp"
  printf '\x80' >> "$work/start.lmp"
  mkdir -p "$work/frames" "$work/home"
  rm -f "$work/frames"/*
  printf 'screenblocks 11\ndetaillevel 0\nusegamma 0\n' > "$work/base.cfg"
  printf 'fullscreen 0\naspect_ratio_correct 0\nstartup_delay 0\n' > "$work/extra.cfg"
  (cd "$work/frames" && HOME="$work/home" SDL_VIDEODRIVER=dummy SDL_VIDEO_DUMMY_SAVE_FRAMES=1 \
    timeout 60 /usr/games/chocolate-doom -iwad "$iwad" -timedemo "$work/start.lmp" -nosound -nogui -window \
    -geometry 320x200 -config "$work/base.cfg" -extraconfig "$work/extra.cfg" >/dev/null 2>&1) || true
  last=$(ls "$work/frames"/*.bmp | sort | tail -1)
  convert "$last" "$work/$spec-chocolate.png"
  build/tools/pseudo3d-capture --iwad "$iwad" --map "$map" --size 320x200 -o "$work/$spec-ours.png" 2>/dev/null
  convert "$work/$spec-ours.png" "$work/$spec-chocolate.png" -background '#202028' -splice 4x0 +append \
    "$work/$spec-row.png"
  rows+=("$work/$spec-row.png")
done
convert "${rows[@]}" -background '#202028' -splice 0x4 -append "$out"
echo "wrote $out: ours on the left, Chocolate Doom on the right"
