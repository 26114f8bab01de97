#!/usr/bin/env python3
"""Condenses Chocolate Doom's per-tic trace of every player (P3D_TRACE_ALL, from the
patched build's p3d-multiplayer.patch) into a golden file for tests/play/demo_sync_test.cpp:
each tic's players hashed (H tic fnv1a64, over the tic's player lines joined by newlines),
and every player in full (F line) every EVERY tics and at the last.

usage: netgame_trace.py TRACE_ALL OUT [EVERY]   (EVERY 35 by default; 1 keeps every tic whole)
"""
import sys


def fnv1a64(text):
    h = 0xcbf29ce484222325
    for b in text.encode():
        h = ((h ^ b) * 0x100000001b3) & 0xFFFFFFFFFFFFFFFF
    return h


def main():
    src, out = sys.argv[1], sys.argv[2]
    every = int(sys.argv[3]) if len(sys.argv) > 3 else 35
    tics = {}
    for line in open(src):
        line = line.strip()
        if line:
            tics.setdefault(int(line.split()[0]), []).append(line)
    last = max(tics)
    with open(out, "w") as f:
        f.write("# Chocolate Doom's trace of every player, after each tic: H tic hash, F tic player x y z angle\n")
        f.write("# momx momy health armor frags0..3 prndindex viewz (tools/peers/netgame_trace.py)\n")
        for tic in sorted(tics):
            lines = tics[tic]
            f.write("H %d %016x\n" % (tic, fnv1a64("\n".join(lines))))
            if tic % every == 0 or tic == last:
                for l in lines:
                    f.write("F " + l + "\n")


main()
