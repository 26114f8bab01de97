#!/usr/bin/env bash
# Our frames against Chocolate Doom's (or Crispy Doom's hires), pixel by pixel, from the
# player starts of WAD maps: the issue-25 proof.
#
#   tools/peer_pixels.sh [--port chocolate|crispy] [--out DIR] [--build DIR] [WAD:MAP ...]
#
# For each map (default: Freedoom's 68, freedoom1 E1M1..E4M9 and freedoom2 MAP01..MAP32) a
# demo of five tics is written: two standing, then three quarter turns to the left, one a
# tic (skill 3, monsters in). The port plays it headless (-timedemo under SDL's dummy video
# driver, which saves every presented frame when SDL_VIDEO_DUMMY_SAVE_FRAMES=1: the last
# five are the views after each tic) and so does our game (--play, --capture-every 1), both
# with the view over the whole screen (Doom's screenblocks 11; our --no-status-bar). The
# four views after tics 1 to 4 (the start angle, then each quarter turn) are compared by
# tools/peer_pixels.cpp: per view the share of pixels exactly the port's colour and the
# share within one pixel of it (one of the port's 3x3 neighbourhood).
#
# Chocolate Doom draws at 320x200, Crispy Doom (crispy_hires 1) at 640x400, ours at the
# same size. Writes DIR/results.txt (one line a view), DIR/maps.txt (one line a map: mean
# exact, worst within-one), DIR/summary.txt, and DIR/worst/ with the pictures of the
# eight worst views (ours | the port's | differences: red not within one pixel, yellow
# within one but not equal). Needs chocolate-doom or crispy-doom and freedoom (Debian
# packages) and a Release build (game, peer_pixels).
set -euo pipefail
cd "$(dirname "$0")/.."
port=chocolate out=out/peer_pixels build=build
while [ $# -gt 0 ]; do
  case $1 in
    --port) port=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --build) build=$2; shift 2 ;;
    --help|-h) sed -n '2,22p' "$0"; exit 0 ;;
    --*) echo "$0: unknown option $1" >&2; exit 2 ;;
    *) break ;;
  esac
done
case $port in
  chocolate) bin=/usr/games/chocolate-doom size=320x200 hires=0 ;;
  crispy) bin=/usr/games/crispy-doom size=640x400 hires=1 ;;
  *) echo "$0: --port is chocolate or crispy" >&2; exit 2 ;;
esac
[ -x "$bin" ] || { echo "$0: $bin is missing (apt-get install $port-doom)" >&2; exit 1; }
for tool in "$build/game/pseudo3d" "$build/tools/peer_pixels"; do
  [ -x "$tool" ] || { echo "$0: $tool is missing (build first)" >&2; exit 1; }
done
maps=("$@")
if [ ${#maps[@]} -eq 0 ]; then
  for e in 1 2 3 4; do for m in 1 2 3 4 5 6 7 8 9; do maps+=("freedoom1:E${e}M$m"); done; done
  for m in $(seq -w 1 32); do maps+=("freedoom2:MAP$m"); done
fi
mkdir -p "$out"
work=$(mktemp -d /tmp/peer-pixels.XXXXXX)
trap 'rm -rf "$work"' EXIT
printf 'screenblocks 11\ndetaillevel 0\nusegamma 0\n' > "$work/base.cfg"
# Crispy's own options at Doom's look (its defaults, written out), hires as asked.
printf 'fullscreen 0\naspect_ratio_correct 0\nstartup_delay 0\ncrispy_hires %d\ncrispy_uncapped 0\n' $hires \
  > "$work/extra.cfg"
printf 'crispy_smoothlight 0\ncrispy_brightmaps 0\ncrispy_coloredblood 0\ncrispy_translucency 0\n' >> "$work/extra.cfg"
printf 'crispy_flipcorpses 0\ncrispy_freeaim 0\ncrispy_freelook 0\ncrispy_smoothscaling 0\n' >> "$work/extra.cfg"
: > "$out/results.txt"
for spec in "${maps[@]}"; do
  wad=${spec%%:*} map=${spec#*:}
  iwad=/usr/share/games/doom/$wad.wad
  if [[ $map =~ ^E([1-4])M([1-9])$ ]]; then episode=${BASH_REMATCH[1]} number=${BASH_REMATCH[2]};
  else episode=1 number=$((10#${map#MAP})); fi
  dir=$work/$wad-$map
  mkdir -p "$dir/port" "$dir/ours" "$dir/home"
  # Demo v1.9: version, skill, episode, map, deathmatch, respawn, fast, nomonsters, player,
  # four players present; then per tic forward, side, angle turn (<< 8), buttons; 0x80 ends it.
  printf "$(printf '\\x%02x' 109 2 "$episode" "$number" 0 0 0 0 0 1 0 0 0)" > "$dir/turn.lmp"
  printf '\x00\x00\x00\x00\x00\x00\x00\x00' >> "$dir/turn.lmp"
  printf '\x00\x00\x40\x00\x00\x00\x40\x00\x00\x00\x40\x00\x80' >> "$dir/turn.lmp"
  (cd "$dir/port" && HOME="$dir/home" SDL_VIDEODRIVER=dummy SDL_AUDIODRIVER=dummy SDL_VIDEO_DUMMY_SAVE_FRAMES=1 \
    timeout 120 "$bin" -iwad "$iwad" -timedemo "$dir/turn.lmp" -nosound -nogui -window -geometry "$size" \
    -config "$work/base.cfg" -extraconfig "$work/extra.cfg" >"$dir/port.log" 2>&1) || true
  mapfile -t theirs < <(ls "$dir/port"/*.bmp 2>/dev/null | sort | tail -4)
  "$build/game/pseudo3d" --iwad "$iwad" --play "$dir/turn.lmp" --headless --size "$size" --no-status-bar \
    --capture-every 1 --out "$dir/ours" >"$dir/ours.log" 2>&1 || { echo "$spec: our replay failed" >&2; continue; }
  # Our frame k is the view after k tics.
  ours=("$dir/ours/frame00002.png" "$dir/ours/frame00003.png" "$dir/ours/frame00004.png" "$dir/ours/frame00005.png")
  if [ ${#theirs[@]} -ne 4 ]; then echo "$spec: $port saved no frames" >&2; continue; fi
  args=()
  for k in 0 1 2 3; do args+=("${ours[$k]}" "${theirs[$k]}"); done
  "$build/tools/peer_pixels" --iwad "$iwad" --label "$wad-$map" --pictures "$work/pictures" "${args[@]}" \
    | tee -a "$out/results.txt"
  rm -rf "$dir"
done
# Per map: the mean of its views' exact shares, its worst view's within-one share.
awk '{ m = $1; e[m] += $4; n[m]++; if (!(m in w) || $6 < w[m]) w[m] = $6; if (!(m in order)) { order[m] = ++k; name[k] = m } }
     END { for (i = 1; i <= k; i++) { m = name[i]; printf "%s %.4f %.4f\n", m, e[m] / n[m], w[m] } }' \
  "$out/results.txt" > "$out/maps.txt"
{
  awk '{ s += $4; n++; if ($6 < 0.99) low++; if (n == 1 || $6 < worst) worst = $6 }
       END { printf "views %d, mean exact %.4f, worst within-one %.4f, views under 0.99 within-one %d\n", n, s / n, worst, low }' \
    "$out/results.txt"
  sort -k2 -n "$out/maps.txt" | head -1 | awk '{ printf "worst map (mean exact) %s %.4f\n", $1, $2 }'
} | tee "$out/summary.txt"
rm -rf "$out/worst"
mkdir -p "$out/worst"
sort -k4 -n "$out/results.txt" | head -8 | while read -r label view _; do
  cp "$work/pictures/$label-$view.png" "$out/worst/" 2>/dev/null || true
done
echo "wrote $out/results.txt, maps.txt, summary.txt and worst/"
