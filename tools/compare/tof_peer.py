#!/usr/bin/python3
"""femto's transient_beams on ToF-Tungsten's transient fog Cornell box
(../shared/scenes/tof-tungsten-cbox-trans, its README) at its full 128x128,
against ToF-Tungsten's own 8192-spp reference volume: relMSE (the README's
definition, epsilon 0.01), CPU seconds (user + system of the femto process)
and their product per budget, printed as a Markdown table beside the peer's
own measurements (quoted from the README: they were made on the peer's side).

  tools/compare/tof_peer.py [--femto build/bin/femto] [--passes 4,16] [--spp 2]
      [-D radius=0.04 ...] [--out build/tof-peer]

The budget is the number of passes, each of --spp camera samples per pixel;
everything else is transient_beams' default (the port's max_depth 64).
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "bench"))
import media_suite  # noqa: E402  (the port's scene copy, render(), relmse())

# ToF-Tungsten's beams as its README reports them: (passes, CPU s, relMSE).
PEER = [(4, 9.8, 24.5), (16, 32.1, 21.2), (64, 103.0, 4.09)]


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--femto", default=os.path.join(media_suite.ROOT, "build", "bin", "femto"))
    p.add_argument("--passes", default="4,16")
    p.add_argument("--spp", type=int, default=2)
    p.add_argument("-D", "--define", action="append", default=[], metavar="NAME=VALUE")
    p.add_argument("--out", default=os.path.join(media_suite.ROOT, "build", "tof-peer"))
    args = p.parse_args(argv)
    if not os.path.exists(os.path.join(media_suite.TOF, "reference.npy")):
        sys.exit(f"{media_suite.TOF}/reference.npy not found")
    os.makedirs(args.out, exist_ok=True)
    scene = media_suite.tof_scene(args.out)
    ref = np.load(os.path.join(media_suite.TOF, "reference.npy")).astype(np.float64)
    extra = dict(d.split("=", 1) for d in args.define)
    print("| renderer | budget | CPU s | relMSE | relMSE × CPU | window sum / ref | radius | candidates / query | pair hits / query |")
    print("|---|---|---|---|---|---|---|---|---|")
    for passes, cpu, e in PEER:
        print(f"| ToF-Tungsten beams (its README) | {passes} passes | {cpu} | {e} | {cpu * e:.0f} | - | - | - | - |")
    for passes in [int(x) for x in args.passes.split(",")]:
        defines = dict(integrator="transient_beams", passes=passes, spp=args.spp, **extra)
        out = os.path.join(args.out, f"beams-{passes}.exr")
        npy, cpu, wall, log = media_suite.render(args.femto, scene, out, defines, seed=1)
        x = np.load(npy).astype(np.float64)
        e = media_suite.relmse(x, ref)
        m, r = media_suite.STATS.search(log), media_suite.RADIUS.search(log)
        note = ", ".join(f"{k}={v}" for k, v in extra.items())
        print(f"| femto transient_beams{' (' + note + ')' if note else ''} | {passes} passes × {args.spp} spp | "
              f"{cpu:.1f} | {e:.3g} | {cpu * e:.0f} | {x.sum() / ref.sum():.3f} | {r.group(1) if r else '-'} | "
              f"{m.group(1) if m else '-'} | {m.group(2) if m else '-'} |", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
