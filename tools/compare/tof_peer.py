#!/usr/bin/python3
"""femto's transient_beams on ToF-Tungsten's transient fog Cornell box
(../shared/scenes/tof-tungsten-cbox-trans, its README) at its full 128x128,
against ToF-Tungsten's own 8192-spp reference volume: relMSE (the README's
definition, epsilon 0.01), CPU seconds (user + system of the femto process)
and their product per budget, printed as a Markdown table beside the peer's
own measurements (quoted from the README: they were made on the peer's side).

  tools/compare/tof_peer.py [--femto build/bin/femto] [--passes 4,16] [--spp 2]
      [--seeds 1] [-D radius=0.04 ...] [--out build/tof-peer] | tools/bench/benchmarks.py set beams-peer

The budget is the number of passes, each of --spp camera samples per pixel
(ToF-Tungsten's runs took 1 camera sample per pass); everything else is
transient_beams' default (the port's max_depth 64). With --seeds N each
budget is rendered with seeds 1..N and the row gives the median CPU,
relMSE and relMSE x CPU (one render's relMSE scatters by about 2x between
seeds on this scene), with the range of relMSE x CPU.

With --seeds 2 or more a second table splits each budget's relMSE against
the reference into femto's own variance (the seeds' spread) and the floor no
femto sample removes, the reference's error plus femto's squared bias
(tools/compare/reference_floor.py, which also maps both over the image from
the volumes this script leaves in --out).
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "bench"))
import media_suite  # noqa: E402  (the port's scene copy, render(), relmse())
import reference_floor  # noqa: E402  (femto's noise and the reference's floor)
from provenance import header, load_line  # noqa: E402

# ToF-Tungsten's beams as its README reports them: (passes, CPU s, relMSE).
PEER = [(4, 9.8, 24.5), (16, 32.1, 21.2), (64, 103.0, 4.09)]


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--femto", default=os.path.join(media_suite.ROOT, "build", "bin", "femto"))
    p.add_argument("--passes", default="4,16")
    p.add_argument("--spp", type=int, default=2)
    p.add_argument("--seeds", type=int, default=1)
    p.add_argument("-D", "--define", action="append", default=[], metavar="NAME=VALUE")
    p.add_argument("--out", default=os.path.join(media_suite.ROOT, "build", "tof-peer"))
    args = p.parse_args(argv)
    if not os.path.exists(os.path.join(media_suite.TOF, "reference.npy")):
        sys.exit(f"{media_suite.TOF}/reference.npy not found")
    os.makedirs(args.out, exist_ok=True)
    scene = media_suite.tof_scene(args.out)
    ref = np.load(os.path.join(media_suite.TOF, "reference.npy")).astype(np.float64)
    extra = dict(d.split("=", 1) for d in args.define)
    floors = []
    load_start = os.getloadavg()
    header("transient_beams on ToF-Tungsten's scene, against ToF-Tungsten's beams", "tools/compare/tof_peer.py",
           f"tools/compare/tof_peer.py {' '.join(argv)}", ["CPU = user + system seconds of the femto process"])
    print("| renderer | budget | CPU s | relMSE | relMSE × CPU | window sum / ref | radius | candidates / query | pair hits / query |")
    print("|---|---|---|---|---|---|---|---|---|")
    for passes, cpu, e in PEER:
        print(f"| ToF-Tungsten beams (its README) | {passes} passes | {cpu} | {e} | {cpu * e:.0f} | - | - | - | - |")
    for passes in [int(x) for x in args.passes.split(",")]:
        defines = dict(integrator="transient_beams", passes=passes, spp=args.spp, **extra)
        runs, volumes = [], []
        for seed in range(1, args.seeds + 1):
            out = os.path.join(args.out, f"beams-{passes}-{seed}.exr")
            npy, cpu, wall, log = media_suite.render(args.femto, scene, out, defines, seed=seed)
            x = np.load(npy).astype(np.float64)
            runs.append((cpu, media_suite.relmse(x, ref), x.sum() / ref.sum(), log))
            volumes.append(x)
        cpu = float(np.median([r[0] for r in runs]))
        e = float(np.median([r[1] for r in runs]))
        products = [r[0] * r[1] for r in runs]
        log = runs[0][3]
        m, r = media_suite.STATS.search(log), media_suite.RADIUS.search(log)
        note = ", ".join(f"{k}={v}" for k, v in extra.items())
        spread = f" ({min(products):.0f}-{max(products):.0f}, {len(runs)} seeds)" if len(runs) > 1 else ""
        sums = "/".join(f"{r[2]:.3f}" for r in runs)
        print(f"| femto transient_beams{' (' + note + ')' if note else ''} | {passes} passes × {args.spp} spp | "
              f"{cpu:.1f} | {e:.3g} | {float(np.median(products)):.0f}{spread} | {sums} | "
              f"{r.group(1) if r else '-'} | {m.group(1) if m else '-'} | {m.group(2) if m else '-'} |", flush=True)
        if len(volumes) > 1:
            floors.append((passes, reference_floor.split(volumes, ref)[:3], e))
        del volumes
    print("\n" + load_line(load_start, os.getloadavg()))
    if floors:
        print("\nfemto's own noise and the floor (relMSE of the seeds' mean minus its variance):\n")
        print("| budget | relMSE, one render (median) | variance, one render | relMSE of the mean | floor | floor / relMSE |")
        print("|---|---|---|---|---|---|")
        for passes, (variance, of_mean, floor), e in floors:
            print(f"| {passes} passes × {args.spp} spp | {e:.3g} | {variance:.3g} | {of_mean:.3g} | {floor:.3g} | "
                  f"{floor / e:.2f} |")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
