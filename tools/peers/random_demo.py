#!/usr/bin/env python3
"""Writes a random but plausible Doom v1.9 demo (single player), seeded.

The player runs, walks, backs off, strafes, turns, fires, presses use and switches
weapons in stretches of 8 to 70 tics, as a person at the keyboard might; a use press
after death starts the level again, so a long demo lives through many deaths. The same
seed, map, skill and options give the same bytes. Only the demo is written: play it on
any WAD stack holding the map (an IWAD's map or a PWAD's).

  tools/peers/random_demo.py --map MAP01 --skill 4 --fast --tics 5000 --seed 7 -o out/r.lmp
"""
import argparse
import os
import random
import re
import sys

BT_ATTACK, BT_USE, BT_CHANGE, BT_WEAPONSHIFT = 1, 2, 4, 3
WALK, RUN = (25, 24), (50, 40)  # Doom's forward and side moves (forwardmove[], sidemove[])


def map_numbers(name):
    """(episode, map) of MAPxx or ExMy, as a demo's header stores them."""
    m = re.fullmatch(r"MAP(\d\d)", name.upper())
    if m:
        return 1, int(m.group(1))
    m = re.fullmatch(r"E(\d)M(\d)", name.upper())
    if m:
        return int(m.group(1)), int(m.group(2))
    raise ValueError(f"{name}: not a map name (MAP01 or E1M1)")


def stretch(rng):
    """One stretch of play: its length and a function giving each tic's command."""
    tics = rng.randint(8, 70)
    speed = RUN if rng.random() < 0.6 else WALK
    forward = rng.choice([speed[0], speed[0], speed[0], 0, -speed[0]])
    side = rng.choice([0, 0, 0, speed[1], -speed[1]])
    turn = rng.choice([0, 0, rng.randint(-5, 5), rng.randint(-2, 2)])  # angleturn's high byte
    firing = rng.random() < 0.35
    use_every = rng.choice([0, 0, 0, 9, 17])
    weapon = rng.randrange(7) if rng.random() < 0.2 else None

    def command(i):
        buttons = 0
        if firing:
            buttons |= BT_ATTACK
        if use_every and i % use_every == 0:
            buttons |= BT_USE
        if weapon is not None and i == 0:
            buttons |= BT_CHANGE | (weapon << BT_WEAPONSHIFT)
        return forward, side, turn, buttons

    return tics, command


def demo_bytes(args):
    rng = random.Random(f"{args.seed}:{args.map}:{args.skill}:{args.fast}:{args.respawn}:{args.nomonsters}")
    episode, number = map_numbers(args.map)
    version = 111 if args.longtics else 109
    out = bytearray([version, args.skill - 1, episode, number, 0, int(args.respawn), int(args.fast),
                     int(args.nomonsters), 0, 1, 0, 0, 0])
    written = 0
    while written < args.tics:
        tics, command = stretch(rng)
        for i in range(min(tics, args.tics - written)):
            forward, side, turn, buttons = command(i)
            out += bytes([forward & 0xFF, side & 0xFF])
            out += ((turn << 8) & 0xFFFF).to_bytes(2, "little") if args.longtics else bytes([turn & 0xFF])
            out.append(buttons)
            written += 1
    out.append(0x80)  # DEMOMARKER
    return bytes(out)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--map", required=True, help="MAP01 or E1M1")
    p.add_argument("--skill", type=int, default=3, choices=range(1, 6))
    p.add_argument("--fast", action="store_true")
    p.add_argument("--respawn", action="store_true")
    p.add_argument("--nomonsters", action="store_true")
    p.add_argument("--longtics", action="store_true", help="v1.91's long tics (Chocolate's -longtics)")
    p.add_argument("--tics", type=int, default=5000)
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("-o", "--output", required=True)
    args = p.parse_args()
    if args.tics < 1:
        p.error("--tics must be at least 1")
    try:
        data = demo_bytes(args)
    except ValueError as e:
        sys.exit(f"random_demo.py: {e}")
    os.makedirs(os.path.dirname(args.output) or ".", exist_ok=True)
    with open(args.output + ".tmp", "wb") as f:  # no partial demo: written whole, then renamed
        f.write(data)
    os.replace(args.output + ".tmp", args.output)


if __name__ == "__main__":
    main()
