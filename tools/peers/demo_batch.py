#!/usr/bin/env python3
"""Random demos replayed by our game and by Chocolate Doom, tic by tic: where do they part?

For every map of the WADs (or --maps), every skill of --skills and every option set of
--options, --seeds demos are written by random_demo.py (--tics long), replayed headless
by our game (stats.csv with Doom's exact values, every tic) and by Chocolate Doom, and
the player's x, y, z, angle, momentum, health, view height and Doom's random index are
compared exactly, tic by tic. Where a demo parts, both replay it again dumping every
thing after every tic, and the first thing that differs (often tics before the player
shows it) is printed with both states side by side; the demo and the files stay in
OUT/parted/. A demo that parts only after our game said it went beyond Chocolate Doom
(vanilla overran memory further than Chocolate emulates, so Chocolate's own memory
decides) is counted apart, compared up to there. Prints a markdown table, then a line
per parted demo. Exits 1 if any parted.

CHOCOLATE is a chocolate-doom (git 941dd35) built with a small patch that this project
neither holds nor needs to build (tools/peer_saves.sh describes its P3D_TRACE); at the
end of G_Ticker, in a level during a demo's playback, after each tic (0 the first):
  - P3D_TRACE=FILE: "tic x y z angle momx momy health prndindex viewz" of the console
    player (16.16 fixed point, binary angle), one line;
  - P3D_DUMP=FILE: every mobj in thinker order as our --dump-things writes it
    (engine/play/thing_dump.h): "T tic prndindex", then "M type x y z angle momx momy
    momz state tics health flags movedir movecount reactiontime threshold target tracer",
    target and tracer as indices in that tic's list, -1 for none.

  tools/peers/demo_batch.py --chocolate CHOCOLATE --iwad /usr/share/games/doom/freedoom2.wad \\
      --maps MAP01,MAP02 --skills 3,4 --options none,fast --seeds 2 --out out/batch
"""
import argparse
import concurrent.futures
import csv
import os
import re
import shutil
import struct
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
FIELDS = ["x", "y", "z", "angle", "momx", "momy", "health", "random", "viewz"]
OPTION_FLAGS = {"none": [], "fast": ["fast"], "respawn": ["respawn"], "nomonsters": ["nomonsters"],
                "fast+respawn": ["fast", "respawn"]}


def wad_maps(path):
    """The map names in a WAD's directory (MAPxx, ExMy), in order."""
    with open(path, "rb") as f:
        data = f.read()
    if len(data) < 12 or data[:4] not in (b"IWAD", b"PWAD"):
        raise ValueError(f"{path}: not a WAD")
    count, offset = struct.unpack_from("<ii", data, 4)
    if count < 0 or offset < 0 or offset + 16 * count > len(data):
        raise ValueError(f"{path}: its directory lies outside the file")
    names = []
    for i in range(count):
        name = data[offset + 16 * i + 8:offset + 16 * i + 16].rstrip(b"\0").decode("latin-1").upper()
        if (len(name) == 5 and name.startswith("MAP") and name[3:].isdigit()) or \
           (len(name) == 4 and name[0] == "E" and name[2] == "M" and name[1].isdigit() and name[3].isdigit()):
            names.append(name)
    return names


def replay(args, demo, *options):
    """Our game replaying the demo headless, without frames."""
    command = [args.game, "--iwad", args.iwad, *sum((["--file", f] for f in args.file), []), "--play", demo,
               "--headless", "--stats-only", *options]
    return subprocess.run(command, capture_output=True, timeout=args.timeout)


def ours_trace(args, demo, work):
    """Our replay's rows (tic k's values after k tics, as Chocolate's trace line k - 1),
    and the demo tic from which Chocolate's memory is undefined (vanilla overran more
    than it emulates), or None."""
    out = os.path.join(work, "ours")
    done = replay(args, demo, "--raw-stats", "--capture-every", "1", "--out", out)
    done.check_returncode()
    beyond = re.search(rb"beyond Chocolate Doom from demo tic (\d+)", done.stderr)
    rows = []
    with open(os.path.join(out, "stats.csv")) as f:
        for r in csv.DictReader(f):
            if int(r["tic"]) == 0:
                continue
            rows.append([int(r[k]) for k in ("x_raw", "y_raw", "z_raw", "angle_raw", "momx_raw", "momy_raw")] +
                        [int(r["health"]), int(r["random"]), int(r["viewz_raw"])])
    return rows, int(beyond.group(1)) if beyond else None


def chocolate_trace(args, demo, work, dump=None):
    trace = os.path.join(work, "chocolate.trace")
    env = dict(os.environ, SDL_VIDEODRIVER="dummy", SDL_AUDIODRIVER="dummy", P3D_TRACE=trace, HOME=work)
    if dump:
        env["P3D_DUMP"] = dump
    command = [args.chocolate, "-iwad", args.iwad, *(["-file", *args.file] if args.file else []), "-timedemo", demo,
               "-nodraw", "-nosound", "-nogui"]
    # -timedemo ends in I_Error's "timed N gametics": a non-zero status, whatever happened.
    done = subprocess.run(command, capture_output=True, text=True, timeout=args.timeout, env=env, cwd=work)
    if "timed " not in done.stdout + done.stderr:
        raise OSError("Chocolate Doom stopped: " + (done.stdout + done.stderr).strip().splitlines()[-1])
    rows = []
    with open(trace) as f:
        for line in f:
            values = [int(v) for v in line.split()]
            rows.append(values[1:])  # tic x y z angle momx momy health prndindex viewz
    return rows


def first_thing_difference(args, demo, work):
    """Both replays again, dumping every thing after every tic: the first that differs,
    which may be tics before the player shows it."""
    theirs, ours = os.path.join(work, "chocolate.things"), os.path.join(work, "ours.things")
    chocolate_trace(args, demo, work, dump=theirs)
    if replay(args, demo, "--dump-things", ours, "--out", os.path.join(work, "dump")).returncode != 0:
        return "our game could not dump its things (--dump-things)"
    tic, index = None, 0
    with open(ours) as a, open(theirs) as b:
        for x, y in zip(a, b):
            if x.startswith("T ") and y.startswith("T "):
                tic, index = x.split()[1], 0
                if x.split()[2] != y.split()[2]:
                    return f"tic {tic}: random index {x.split()[2]} / {y.split()[2]}"
                continue
            if x != y:
                return f"tic {tic}, thing {index} (thinker order), first:\n    ours       {x.rstrip()}\n    chocolate  {y.rstrip()}"
            index += 1
    return "the things agree wherever both dumps reach"


def run_one(args, job):
    map_name, skill, option, seed = job
    name = f"{map_name}_s{skill}_{option.replace('+', '_')}_{seed}"
    work = os.path.join(args.out, "work", name)
    os.makedirs(work, exist_ok=True)
    demo = os.path.join(work, name + ".lmp")
    flags = [f"--{o}" for o in OPTION_FLAGS[option]]
    subprocess.run([sys.executable, os.path.join(HERE, "random_demo.py"), "--map", map_name, "--skill", str(skill),
                    *flags, "--tics", str(args.tics), "--seed", str(seed), "-o", demo], check=True)
    result = {"name": name, "map": map_name, "skill": skill, "option": option, "tics": args.tics}
    try:
        (ours, beyond), theirs = ours_trace(args, demo, work), chocolate_trace(args, demo, work)
    except (subprocess.CalledProcessError, subprocess.TimeoutExpired, OSError) as e:
        result["error"] = str(e)
        return result
    compared = min(len(ours), len(theirs))
    parted = next((t for t in range(compared) if ours[t] != theirs[t]), None)
    result["compared"] = compared
    result["parted"] = parted
    if parted is not None and beyond is not None and parted >= beyond:
        # Chocolate's own memory decides from there: not a difference anyone can fix.
        result["compared"], result["parted"], result["beyond"] = beyond, None, beyond
    if result["parted"] is None:
        shutil.rmtree(work)
        return result
    differing = [f"{f} {o} / {c}" for f, o, c in zip(FIELDS, ours[parted], theirs[parted]) if o != c]
    result["fields"] = ", ".join(differing)
    result["things"] = first_thing_difference(args, demo, work)
    kept = os.path.join(args.out, "parted", name)
    shutil.rmtree(kept, ignore_errors=True)
    shutil.move(work, kept)
    return result


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--chocolate", required=True, help="a chocolate-doom with the trace patch described above")
    p.add_argument("--game", default=os.path.join(HERE, "..", "..", "build", "game", "pseudo3d"))
    p.add_argument("--iwad", required=True)
    p.add_argument("--file", action="append", default=[], help="a PWAD (its maps are played)")
    p.add_argument("--maps", help="MAP01,MAP02 (default: every map of the last WAD holding maps)")
    p.add_argument("--skills", default="1,2,3,4,5")
    p.add_argument("--options", default="none", help="of " + ", ".join(OPTION_FLAGS))
    p.add_argument("--seeds", type=int, default=1, help="demos for each map, skill and option set")
    p.add_argument("--first-seed", type=int, default=1)
    p.add_argument("--tics", type=int, default=5000)
    p.add_argument("--jobs", type=int, default=os.cpu_count())
    p.add_argument("--timeout", type=float, default=600)
    p.add_argument("--out", default="out/demo_batch")
    args = p.parse_args()
    try:
        maps = args.maps.split(",") if args.maps else next(m for m in map(wad_maps, [*reversed(args.file), args.iwad]) if m)
    except (ValueError, OSError, StopIteration) as e:
        sys.exit(f"demo_batch.py: {e or 'no maps in the WADs'}")
    options = args.options.split(",")
    if unknown := [o for o in options if o not in OPTION_FLAGS]:
        sys.exit(f"demo_batch.py: unknown option set {unknown[0]} (of {', '.join(OPTION_FLAGS)})")
    jobs = [(m, int(s), o, seed) for m in maps for s in args.skills.split(",") for o in options
            for seed in range(args.first_seed, args.first_seed + args.seeds)]
    with concurrent.futures.ProcessPoolExecutor(max_workers=args.jobs) as pool:
        results = list(pool.map(run_one, [args] * len(jobs), jobs))

    stack = " + ".join(os.path.basename(w) for w in [args.iwad, *args.file])
    failed = [r for r in results if "error" in r]
    parted = [r for r in results if r.get("parted") is not None]
    played = [r for r in results if "compared" in r]
    beyond = [r for r in results if "beyond" in r]
    print(f"| WADs | demos | maps | skills | options | tics compared | tics in sync | parted | "
          f"parted beyond Chocolate | failed to run |")
    print(f"|---|---:|---:|---|---|---:|---:|---:|---:|---:|")
    print(f"| {stack} | {len(results)} | {len(maps)} | {args.skills} | {args.options} | "
          f"{sum(r['compared'] for r in played)} | "
          f"{sum(r['compared'] if r['parted'] is None else r['parted'] for r in played)} | {len(parted)} | "
          f"{len(beyond)} | {len(failed)} |")
    for r in beyond:
        print(f"\nbeyond Chocolate: {r['name']} from tic {r['beyond']}, where vanilla overran more memory than "
              f"Chocolate emulates (compared up to there)")
    for r in parted:
        print(f"\nparted: {r['name']} at tic {r['parted']} of {r['compared']}: {r['fields']}\n  {r['things']}")
    for r in failed:
        print(f"\nfailed: {r['name']}: {r['error']}")
    return 1 if parted or failed else 0


if __name__ == "__main__":
    sys.exit(main())
