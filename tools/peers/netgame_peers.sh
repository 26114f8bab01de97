#!/usr/bin/env bash
# A netgame of Chocolate Doom and our game: chocolate-server, one Chocolate Doom client
# (the controller: its settings start the game, and it records the game as a Doom demo),
# and PLAYERS - 1 of our clients, each through tools/peers/lossy_udp.py (packets lost
# and delayed), their input from random demos (tools/peers/random_demo.py). Our clients
# leave after TICS tics, which ends Chocolate's recording. Then:
#   - Chocolate's demo and each of ours (they record too) hold the same commands;
#   - each of our clients' live game (every thing after every tic, --dump-things) equals
#     our replay of Chocolate's demo, and Chocolate Doom's replay of it (P3D_DUMP, the
#     patched build that tools/peers/demo_batch.py describes), tic for tic.
#
#   tools/peers/netgame_peers.sh [--players 2..4] [--deathmatch|--altdeath] [--tics N]
#       [--timer MINUTES] [--drop P] [--delay-ms MS] [--iwad WAD] [--map N]
#       [--build DIR | --game PROGRAM] [--patched CHOCOLATE] [--save-at TIC]
#
# With --timer the level ends after that many minutes and the game goes on through the
# tally (every player's press hurries it) into the next map: the demos then hold both
# levels, and the replays follow them there as the live games did.
# With --save-at our first client's command at that tic asks for a save (Doom's
# BT_SPECIAL | BTS_SAVEGAME, slot 0): every node saves. Loaded after that tic into our
# replay of the demo, Chocolate Doom's save and the Doom part of each of ours must give
# the same game to the end (Doom's load is not exact: neither goes on as the demo did),
# and each of ours whole (with our extension) must go on exactly as the demo.
#
# Needs Debian's chocolate-doom (chocolate-doom, chocolate-server) and freedoom; prints
# one line of results and exits 1 if anything differs. Without --patched, Chocolate's
# replay is not compared.
set -euo pipefail
cd "$(dirname "$0")/../.."
players=2 mode="" timer="" save_at="" tics=350 drop=0.05 delay=30 iwad=/usr/share/games/doom/freedoom2.wad map=1 game=build/game/pseudo3d
patched=""
while [ $# -gt 0 ]; do
  case $1 in
    --players) players=$2; shift 2 ;;
    --deathmatch|--altdeath) mode=${1#-}; shift ;;  # Chocolate spells it -deathmatch
    --tics) tics=$2; shift 2 ;;
    --save-at) save_at=$2; shift 2 ;;
    --timer) timer="-timer $2"; shift 2 ;;
    --drop) drop=$2; shift 2 ;;
    --delay-ms) delay=$2; shift 2 ;;
    --iwad) iwad=$2; shift 2 ;;
    --map) map=$2; shift 2 ;;
    --build) game=$2/game/pseudo3d; shift 2 ;;
    --game) game=$2; shift 2 ;;
    --patched) patched=$2; shift 2 ;;
    -h|--help) sed -n '2,22p' "$0"; exit 0 ;;
    *) echo "$0: unknown option $1" >&2; exit 2 ;;
  esac
done
choc=/usr/games/chocolate-doom server=/usr/games/chocolate-server
for f in "$choc" "$server" "$game"; do [ -x "$f" ] || { echo "$0: $f is missing" >&2; exit 2; }; done
game=$(realpath "$game")
[ "$players" -ge 2 ] && [ "$players" -le 4 ] || { echo "$0: --players is 2 to 4" >&2; exit 2; }
work=$(mktemp -d /tmp/netgame-peers.XXXXXX)
pids=()
cleanup() { for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done; wait 2>/dev/null || true; [ -n "${KEEP:-}" ] || rm -rf "$work"; }
trap cleanup EXIT

# Free ports: the server's, then one a relay.
read -r -a ports < <(python3 -c "
import socket
ss = [socket.socket(socket.AF_INET, socket.SOCK_DGRAM) for _ in range($players)]
for s in ss: s.bind(('127.0.0.1', 0))
print(' '.join(str(s.getsockname()[1]) for s in ss))")
commercial=$(python3 -c "import sys; sys.path.insert(0, 'tools/peers'); from demo_batch import wad_maps
print(1 if 'MAP01' in wad_maps('$iwad') else 0)")
warp=$([ "$commercial" = 1 ] && echo "$map" || echo "1 $map")
map_name=$([ "$commercial" = 1 ] && printf 'MAP%02d' "$map" || echo "E1M$map")

"$server" -port "${ports[0]}" >"$work/server.log" 2>&1 &
pids+=($!)
sleep 0.5
(cd "$work" && HOME="$work" SDL_VIDEODRIVER=dummy SDL_AUDIODRIVER=dummy \
  "$choc" -iwad "$iwad" -connect "127.0.0.1:${ports[0]}" -nodes "$players" -warp $warp -skill 3 $mode $timer \
  -record choc -nosound -nomusic >"$work/chocolate.log" 2>&1) &
pids+=($!)
sleep 1.5
ours=()
for ((k = 1; k < players; ++k)); do
  python3 tools/peers/lossy_udp.py --listen "${ports[$k]}" --to "127.0.0.1:${ports[0]}" --drop "$drop" \
    --delay-ms "$delay" --jitter-ms "$delay" --seed "$k" 2>"$work/relay$k.log" &
  pids+=($!)
  python3 tools/peers/random_demo.py --map "$map_name" --skill 3 --tics "$tics" --seed "$((k + 10))" -o "$work/input$k.lmp"
  if [ -n "$save_at" ] && [ "$k" = 1 ]; then  # the tic's buttons: BT_SPECIAL | BTS_SAVEGAME, slot 0
    python3 -c "
import sys; p = sys.argv[1]; d = bytearray(open(p, 'rb').read()); d[13 + 4 * int(sys.argv[2]) + 3] = 0x82
open(p, 'wb').write(d)" "$work/input$k.lmp" "$save_at"
  fi
  "$game" --iwad "$iwad" --headless --connect "127.0.0.1:${ports[$k]}" --net-input "$work/input$k.lmp" \
    --quit-after-tics "$tics" --dump-things "$work/live$k.things" --record "$work/ours$k.lmp" --out "$work/out$k" \
    >"$work/ours$k.log" 2>&1 &
  ours+=($!)
done
status=0
for p in "${ours[@]}"; do wait "$p" || status=1; done
for _ in $(seq 50); do [ -s "$work/choc.lmp" ] && break; sleep 0.2; done  # Chocolate writes it as it quits
if [ $status -ne 0 ] || [ ! -s "$work/choc.lmp" ]; then
  echo "netgame failed:"; tail -n 3 "$work"/ours*.log "$work/chocolate.log" "$work/server.log"; exit 1
fi
replay_timer=()  # our replay of a demo ends its level at the timer too (a demo holds no timer)
[ -n "$timer" ] && replay_timer=(--timer "${timer#-timer }" "-$mode")
"$game" --iwad "$iwad" --play "$work/choc.lmp" "${replay_timer[@]}" --headless --stats-only --dump-things "$work/replay.things" \
  --out "$work/replay" >/dev/null
if [ -n "$patched" ]; then
  (cd "$work" && env HOME="$work" SDL_VIDEODRIVER=dummy SDL_AUDIODRIVER=dummy P3D_DUMP="$work/chocolate.things" \
    "$patched" -iwad "$iwad" -timedemo "$work/choc.lmp" $timer -nodraw -nosound -nomusic >/dev/null 2>&1) || true
fi
if [ -n "$save_at" ]; then
  load_into_replay() {  # SAVE THINGS [--load-doom-only]
    "$game" --iwad "$iwad" --play "$work/choc.lmp" "${replay_timer[@]}" --headless --stats-only \
      --load-at "$save_at" "$1" ${3:-} --dump-things "$2" --out "$work/load" >/dev/null 2>&1 || true
  }
  choc_save=$(find "$work/.local" -name doomsav0.dsg | head -n 1)
  [ -n "$choc_save" ] && load_into_replay "$choc_save" "$work/load_choc.things" --load-doom-only
  for ((k = 1; k < players; ++k)); do
    load_into_replay "$work/out$k/savegames/doomsav0.dsg" "$work/load_doom$k.things" --load-doom-only
    load_into_replay "$work/out$k/savegames/doomsav0.dsg" "$work/load_ours$k.things"
  done
fi
python3 - "$work" "$players" "$tics" "$drop" "$delay" "${mode:-coop}" "$timer" "$save_at" <<'PY'
import glob, os, sys
work, players, tics, drop, delay, mode = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), sys.argv[4], sys.argv[5], sys.argv[6]
levels = bool(sys.argv[7])  # --timer: the game and the replays go on through the tally into the next map
save_at = sys.argv[8]
def blocks(path):
    out, cur = [], None
    for line in open(path):
        if line.startswith("T "):
            cur = [line]; out.append(cur)
        elif cur is not None:
            cur.append(line)
    return out
choc = open(os.path.join(work, "choc.lmp"), "rb").read()
replay = blocks(os.path.join(work, "replay.things"))
results, bad = [], False
for k in range(1, players):
    mine = open(os.path.join(work, f"ours{k}.lmp"), "rb").read()
    same_demo = len(mine) == len(choc) and all(a == b for i, (a, b) in enumerate(zip(mine, choc)) if i != 8)
    live = blocks(os.path.join(work, f"live{k}.things"))
    n = min(len(live), len(replay))
    parted = next((t for t in range(n) if live[t] != replay[t]), None)
    need = len(live) if levels else tics  # the level tics of a game that crossed levels, not its tally's
    bad |= not same_demo or parted is not None or n < need
    results.append(f"client {k}: demo {'= Chocolate' if same_demo else 'DIFFERS'}, live = replay "
                   f"{n if parted is None else parted} of {len(live)} tics")
chocolate = os.path.join(work, "chocolate.things")
if os.path.exists(chocolate):
    theirs = blocks(chocolate)
    n = min(len(theirs), len(replay))
    parted = next((t for t in range(n) if theirs[t] != replay[t]), None)
    bad |= parted is not None or n < (len(replay) if levels else tics)
    results.append(f"Chocolate's replay = ours {n if parted is None else parted} of {len(replay)} tics")
    if levels:  # Chocolate's replay goes on through the levels, as our live games did
        for k in range(1, players):
            live = blocks(os.path.join(work, f"live{k}.things"))
            n = min(len(live), len(theirs))
            parted = next((t for t in range(n) if live[t] != theirs[t]), None)
            bad |= parted is not None or n < len(live)
            results.append(f"client {k}'s live = Chocolate's replay {n if parted is None else parted} of {len(live)} level tics")
if save_at:
    def loaded(name):
        path = os.path.join(work, name)
        return blocks(path) if os.path.exists(path) else []
    theirs = loaded("load_choc.things")
    for k in range(1, players):
        doom, whole = loaded(f"load_doom{k}.things"), loaded(f"load_ours{k}.things")
        same_load = bool(theirs) and doom == theirs
        exact = len(whole) == len(replay) and whole == replay
        bad |= not same_load or not exact
        results.append(f"client {k}'s save at tic {save_at}: loads as Chocolate's "
                       f"{'does' if same_load else 'DOES NOT'}, goes on as the demo {'yes' if exact else 'NO'}")
print(f"{players} players, {mode}, {tics} tics, {float(drop):.0%} lost, {delay}-{2 * int(delay)} ms: " + "; ".join(results))
sys.exit(1 if bad else 0)
PY
