#!/usr/bin/env python3
"""Render-only ms/frame of Crispy Doom (or Chocolate Doom) on one of an IWAD's demos.

  tools/peers/doom_render_ms.py [--port crispy|chocolate] [--iwad PATH] [--demo demo3|FILE.lmp] [--res 640|320] [--reps 3]
                                [--instructions]

Prints one line: `port iwad demo res frames render_ms_per_frame`. Needs the port's
Debian package, the IWAD and a C compiler; no display (SDL's dummy driver).
--instructions counts instead (valgrind's callgrind, once: the counts do not vary) and
prints `render_instructions_per_frame`, by the same subtractions.

Method: `-timedemo` reports gametics and realtics (1/35 s). tick_dilate.c makes the
port's clock run 100x fast, so a realtic is 0.286 ms. A timedemo starts with a screen
melt of tens of realtics: a 2-tic demo with the same header (same map, no input) is
timed too and subtracted. Render time = (-noblit) - (-nodraw): the frame drawn but not
shown, less the game without drawing. Medians of interleaved repetitions. Crispy draws
640x400 with crispy_hires 1 and 320x200 with 0; Chocolate draws 320x200 only.
"""
import argparse, os, re, shutil, statistics, struct, subprocess, tempfile

DILATION = 100
MS_PER_REALTIC = 1000.0 / 35 / DILATION


def lump(iwad, name):
    data = open(iwad, "rb").read()
    _, count, directory = struct.unpack_from("<4sii", data, 0)
    for i in range(count):
        pos, size, lump_name = struct.unpack_from("<ii8s", data, directory + 16 * i)
        if lump_name.rstrip(b"\0").decode("latin-1").lower() == name.lower():
            return data[pos:pos + size]
    raise SystemExit(f"{iwad}: no lump {name.upper()}")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--port", default="crispy", choices=["crispy", "chocolate"])
    ap.add_argument("--iwad", default="/usr/share/games/doom/freedoom2.wad")
    ap.add_argument("--demo", default="demo3", help="a demo lump of the IWAD, or a demo file")
    ap.add_argument("--res", default="640", choices=["640", "320"])
    ap.add_argument("--reps", type=int, default=3)
    ap.add_argument("--instructions", action="store_true", help="count instructions (callgrind) instead of timing")
    a = ap.parse_args()
    if a.instructions:
        a.reps = 1
    if a.port == "chocolate" and a.res == "640":
        raise SystemExit("Chocolate Doom draws 320x200 only")
    binary = shutil.which(f"{a.port}-doom") or f"/usr/games/{a.port}-doom"
    work = tempfile.mkdtemp(prefix="p3d-peer.")
    try:
        shim = os.path.join(work, "tick_dilate.so")
        subprocess.run(["cc", "-O2", "-shared", "-fPIC", "-o", shim,
                        os.path.join(os.path.dirname(os.path.abspath(__file__)), "tick_dilate.c")], check=True)
        demo = open(a.demo, "rb").read() if os.path.isfile(a.demo) else lump(a.iwad, a.demo)
        header = 13 if demo[0] >= 104 else 7  # Doom 1.4+ demos have the longer header
        calibration = os.path.join(work, "calibration.lmp")
        open(calibration, "wb").write(bytes(demo[:header]) + bytes(8) + b"\x80")  # two idle tics, end marker

        def timedemo(demo_arg, mode):
            run = tempfile.mkdtemp(dir=work)
            os.makedirs(os.path.join(run, "home"))
            open(os.path.join(run, "base.cfg"), "w").write("screenblocks 11\ndetaillevel 0\nusegamma 0\n")
            open(os.path.join(run, "extra.cfg"), "w").write(
                "fullscreen 0\nstartup_delay 0\naspect_ratio_correct 1\nshow_endoom 0\n"
                f"crispy_hires {1 if a.res == '640' else 0}\n")
            env = {k: v for k, v in os.environ.items() if k != "DISPLAY"}
            env.update(HOME=os.path.join(run, "home"), SDL_VIDEODRIVER="dummy", LD_PRELOAD=shim,
                       TICKS_DILATE=str(DILATION))
            counter = ["valgrind", "--tool=callgrind", "--callgrind-out-file=/dev/null"] if a.instructions else []
            p = subprocess.run(counter + [binary, "-iwad", a.iwad, "-timedemo", demo_arg, "-nosound", "-nograbmouse", "-nogui",
                                "-config", os.path.join(run, "base.cfg"), "-extraconfig",
                                os.path.join(run, "extra.cfg"), "-window", "-geometry", "640x480", "-" + mode],
                               cwd=run, env=env, capture_output=True, text=True, timeout=3600)
            m = re.search(r"timed (\d+) gametics in (\d+) realtics", p.stdout + p.stderr)
            if not m:
                raise SystemExit(f"{binary}: no 'timed' line: {(p.stdout + p.stderr)[-300:]}")
            if a.instructions:
                counted = re.search(r"Collected : (\d+)", p.stderr)
                if not counted:
                    raise SystemExit(f"valgrind: no instruction count: {p.stderr[-300:]}")
                return int(m.group(1)), int(counted.group(1))
            return int(m.group(1)), int(m.group(2))

        measured = {}  # realtics, or instructions
        tics = 0
        for _ in range(a.reps):
            for kind, arg in (("demo", os.path.abspath(a.demo) if os.path.isfile(a.demo) else a.demo),
                              ("calibration", calibration)):
                for mode in ("noblit", "nodraw"):
                    gametics, r = timedemo(arg, mode)
                    tics = gametics if kind == "demo" else tics
                    measured.setdefault((kind, mode), []).append(r)
        med = {k: statistics.median(v) for k, v in measured.items()}
        frames = tics - 2
        drawn = med[("demo", "noblit")] - med[("calibration", "noblit")]
        undrawn = med[("demo", "nodraw")] - med[("calibration", "nodraw")]
        result = (f"render_instructions_per_frame={(drawn - undrawn) / frames:.0f}" if a.instructions else
                  f"render_ms_per_frame={(drawn - undrawn) * MS_PER_REALTIC / frames:.4f}")
        print(f"{a.port} {os.path.basename(a.iwad)} {os.path.basename(a.demo)} {a.res} frames={frames} {result}")
    finally:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
