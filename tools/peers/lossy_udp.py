#!/usr/bin/env python3
"""A UDP relay that loses and delays packets: one client's netgame through a bad network.

The client sends to 127.0.0.1:LISTEN; the relay sends on to the server from a socket of
its own and brings the answers back. Each packet, either way, is dropped with
probability --drop, and otherwise held --delay-ms plus up to --jitter-ms (so packets
also arrive out of order). Seeded: the same seed drops the same packets of the same
stream. Stops after --seconds, or when killed.

  tools/peers/lossy_udp.py --listen 26001 --to 127.0.0.1:26000 --drop 0.1 --delay-ms 40 --jitter-ms 30
"""
import argparse
import heapq
import random
import select
import signal
import socket
import sys
import time


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--listen", type=int, required=True, help="the port the client sends to (on 127.0.0.1)")
    p.add_argument("--to", required=True, help="the server, HOST:PORT")
    p.add_argument("--drop", type=float, default=0.0, help="probability that a packet is lost")
    p.add_argument("--delay-ms", type=float, default=0.0)
    p.add_argument("--jitter-ms", type=float, default=0.0)
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--seconds", type=float, default=600)
    args = p.parse_args()
    host, port = args.to.rsplit(":", 1)
    server = (host, int(port))
    rng = random.Random(args.seed)
    front = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    front.bind(("127.0.0.1", args.listen))
    back = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    end = time.monotonic() + args.seconds
    signal.signal(signal.SIGTERM, lambda *_: sys.exit(0))
    try:
        relay(args, rng, front, back, server, end)
    finally:
        print(f"lossy_udp: {counts['passed']} packets passed, {counts['dropped']} dropped", file=sys.stderr)


counts = {"passed": 0, "dropped": 0}


def relay(args, rng, front, back, server, end):
    client = None
    pending = []  # (due, order, socket, bytes, address)
    order = 0
    while time.monotonic() < end:
        wait = max(0.0, min(0.05, pending[0][0] - time.monotonic())) if pending else 0.05
        ready, _, _ = select.select([front, back], [], [], wait)
        for s in ready:
            data, source = s.recvfrom(65536)
            if s is front:
                client = source
                target = (back, server)
            elif client is None:
                continue
            else:
                target = (front, client)
            if rng.random() < args.drop:
                counts["dropped"] += 1
                continue
            counts["passed"] += 1
            due = time.monotonic() + (args.delay_ms + rng.random() * args.jitter_ms) / 1000
            heapq.heappush(pending, (due, order, target[0], data, target[1]))
            order += 1
        now = time.monotonic()
        while pending and pending[0][0] <= now:
            _, _, s, data, address = heapq.heappop(pending)
            s.sendto(data, address)


if __name__ == "__main__":
    main()
