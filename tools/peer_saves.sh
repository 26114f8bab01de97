#!/usr/bin/env bash
# Our savegames beside Chocolate Doom's: saved and loaded at tics of demos, each side
# loading the other's save, and the rest of the demo played by both from the same file.
#
#   tools/peer_saves.sh CHOCOLATE_DOOM [--out DIR] [--build DIR] [WAD:DEMO:TIC,TIC... ...]
#
# CHOCOLATE_DOOM is a chocolate-doom binary built from its source (git 941dd35) with a
# small patch that neither this project holds nor needs to build. At the end of G_Ticker,
# during a demo's playback, the patch counts the tics played (0 the first) and after each:
#   - writes the console player as tests/golden/doom_demos/*.trace has it (tic x y z angle
#     momx momy health prndindex viewz) to the file named by P3D_TRACE;
#   - if the tic is in P3D_SAVE_AT (tics separated by commas), saves the game to the
#     matching file of P3D_SAVE_FILE (files separated by commas, or one name with %d for
#     the tic) as G_DoSaveGame does (header, P_ArchivePlayers, P_ArchiveWorld,
#     P_ArchiveThinkers, P_ArchiveSpecials, the end marker), then plays on;
#   - if the tic is in P3D_LOAD_AT, loads the matching file of P3D_LOAD_FILE with
#     G_DoLoadGame and puts back demoplayback (and usergame), which its G_InitNew clears,
#     so that the demo's input goes on.
# Run headless: SDL_VIDEODRIVER=dummy, -timedemo demoN (or a .lmp) -nodraw.
#
# For each demo (default: DEMO1..DEMO4 of freedoom1 and freedoom2 at a quarter, half and
# three quarters of their tics, and tests/golden/doom_demos/recorded_freedoom2_map01.lmp)
# and tic N, both save after tic N; then
#   ours -> choc:  Chocolate Doom loads our save after tic N, our game loads it as Doom
#                  would (--load-doom-only);
#   choc -> ours:  Chocolate Doom loads its own save, our game loads Chocolate's;
#   exact:         our game loads its own save with our extension, against its replay
#                  that never saved;
# and the player (position, angle, momentum, health, view height, random index) is
# compared tic by tic from N + 1 to the demo's end. Two more columns: Chocolate Doom's
# play after loading our save beside its play after loading its own (the two saves hold
# the same game), and the first tic where Chocolate Doom's play after loading its save
# parts from its play that never loaded (Doom's load resets the random index and more,
# so the rest of the demo plays another game: what the columns before follow). Prints a
# Markdown table (tics in sync after the load, of as many compared) and writes
# DIR/table.md. Needs freedoom and a Release build of game.
set -euo pipefail
cd "$(dirname "$0")/.."
[ $# -ge 1 ] || { sed -n '2,36p' "$0"; exit 2; }
choc=$1; shift
out=out/peer_saves build=build
while [ $# -gt 0 ]; do
  case $1 in
    --out) out=$2; shift 2 ;;
    --build) build=$2; shift 2 ;;
    --help|-h) sed -n '2,36p' "$0"; exit 0 ;;
    --*) echo "$0: unknown option $1" >&2; exit 2 ;;
    *) break ;;
  esac
done
[ -x "$choc" ] || { echo "$0: $choc is not an executable" >&2; exit 1; }
game=$build/game/pseudo3d
[ -x "$game" ] || { echo "$0: $game is missing (build first)" >&2; exit 1; }
iwads=/usr/share/games/doom
specs=("$@")
recorded=$PWD/tests/golden/doom_demos/recorded_freedoom2_map01.lmp
mkdir -p "$out"
work=$(mktemp -d /tmp/peer-saves.XXXXXX)
trap 'rm -rf "$work"' EXIT

# chocolate WAD DEMO TRACE [VAR=VALUE...]: Chocolate Doom plays the demo headless.
chocolate() {
  local wad=$1 demo=$2 trace=$3; shift 3
  (cd "$work" && env HOME="$work" SDL_VIDEODRIVER=dummy SDL_AUDIODRIVER=dummy P3D_TRACE="$trace" "$@" \
    "$choc" -iwad "$iwads/$wad.wad" -timedemo "$demo" -nodraw -nosound -nomusic >/dev/null 2>&1) || true
}
# ours WAD DEMO CSV [OPTIONS...]: our game replays it headless, one stats row a tic.
ours() {
  local wad=$1 demo=$2 csv=$3; shift 3
  rm -rf "$work/ours"
  "$game" --iwad "$iwads/$wad.wad" --headless --play "$demo" --stats-only --raw-stats --capture-every 1 \
    --out "$work/ours" "$@" >/dev/null
  # Row t is the player after t tics: Chocolate Doom's trace line t - 1.
  awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
           $c["tic"] > 0 { print $c["tic"] - 1, $c["x_raw"], $c["y_raw"], $c["z_raw"], $c["angle_raw"], $c["momx_raw"],
                           $c["momy_raw"], $c["health"], $c["random"], $c["viewz_raw"] }' "$work/ours/stats.csv" > "$csv"
}
# parts A B N: the first tic after N where the traces differ ("never" if none).
parts() {
  awk -v n="$3" 'NR == FNR { a[$1] = $0; next }
                 $1 > n && !found && a[$1] != $0 { found = $1 }
                 END { print found ? found : "never" }' "$1" "$2"
}
# synced A B N: "in sync of compared" over the tics after N (from the first).
synced() {
  awk -v n="$3" 'NR == FNR { if ($1 > n) a[$1] = $0; next }
                 $1 > n { b[$1] = $0 }
                 END { total = 0; for (t in a) if (t in b) ++total
                       for (t = n + 1; (t in a) && (t in b) && a[t] == b[t]; ++t) ++ok
                       printf "%d of %d", ok, total }' "$1" "$2"
}

if [ ${#specs[@]} -eq 0 ]; then
  for wad in freedoom1 freedoom2; do for d in 1 2 3 4; do specs+=("$wad:demo$d:"); done; done
  specs+=("freedoom2:recorded:")
fi
table="| demo | map | saved after tic | ours -> Chocolate Doom | Chocolate Doom -> ours | ours, exact | Chocolate Doom: our save as its own | Doom's load parts from the unsaved play at tic |
|---|---|---:|---:|---:|---:|---:|---:|"
echo "$table"
for spec in "${specs[@]}"; do
  IFS=: read -r wad demo tics <<< "$spec"
  demo_file=$demo
  [ "$demo" = recorded ] && demo_file=$recorded
  ours "$wad" "$demo_file" "$work/plain.trace"
  length=$(wc -l < "$work/plain.trace")
  if [ -z "$tics" ]; then tics="$((length / 4)),$((length / 2)),$((3 * length / 4))"; fi
  for tic in ${tics//,/ }; do
    chocolate "$wad" "$demo_file" "$work/c_plain.trace" P3D_SAVE_AT="$tic" P3D_SAVE_FILE="$work/choc.dsg"
    ours "$wad" "$demo_file" "$work/o_plain.trace" --save-at "$tic" "$work/ours.dsg"
    chocolate "$wad" "$demo_file" "$work/c_ours.trace" P3D_LOAD_AT="$tic" P3D_LOAD_FILE="$work/ours.dsg"
    ours "$wad" "$demo_file" "$work/o_ours.trace" --load-at "$tic" "$work/ours.dsg" --load-doom-only
    chocolate "$wad" "$demo_file" "$work/c_choc.trace" P3D_LOAD_AT="$tic" P3D_LOAD_FILE="$work/choc.dsg"
    ours "$wad" "$demo_file" "$work/o_choc.trace" --load-at "$tic" "$work/choc.dsg"
    ours "$wad" "$demo_file" "$work/o_exact.trace" --load-at "$tic" "$work/ours.dsg"
    # The map, from the save's header: episode and map at bytes 41 and 42.
    read -r episode number <<< "$(od -An -tu1 -j41 -N2 "$work/ours.dsg")"
    if [ "$wad" = freedoom2 ]; then map=$(printf 'MAP%02d' "$number"); else map="E${episode}M$number"; fi
    name=$wad\ $(echo "$demo" | tr a-z A-Z)
    [ "$demo" = recorded ] && name="$wad recorded_freedoom2_map01.lmp"
    row="| $name | $map | $tic | $(synced "$work/c_ours.trace" "$work/o_ours.trace" "$tic") | $(synced "$work/c_choc.trace" "$work/o_choc.trace" "$tic") | $(synced "$work/o_plain.trace" "$work/o_exact.trace" "$tic") | $(synced "$work/c_choc.trace" "$work/c_ours.trace" "$tic") | $(parts "$work/c_plain.trace" "$work/c_choc.trace" "$tic") |"
    echo "$row"
    table+=$'\n'"$row"
  done
done
echo "$table" > "$out/table.md"
