#!/usr/bin/python3
"""femto's transient_beams on ToF-Tungsten's transient fog Cornell box
(../shared/scenes/tof-tungsten-cbox-trans, its README) at its full 128x128,
judged as issue 33 asks: against `reference-independent.npy` (a ToF-Tungsten
8192-spp render sharing no samples with any render compared), at equal
passes, with ToF-Tungsten's CPU seconds from its README (measured beside
femto on one machine) scaled to this machine by
../shared/tools/cpu_calibration.py (median of 3 readings before and 3 after,
over the README's 0.345). relMSE is the README's (epsilon 0.01 x mean^2);
CPU = user + system of the femto process; efficiency = the peer's relMSE x
scaled CPU over femto's. Printed as a Markdown table:

  tools/compare/tof_peer.py [--femto build/bin/femto] [--passes 4,16,64] [--spp 1]
      [--seeds 1] [-D radius=0.04 ...] [--out build/tof-peer] | tools/bench/benchmarks.py set beams-peer

The budget is the number of passes, each of --spp camera samples per pixel
(1, as ToF-Tungsten's runs); everything else is transient_beams' default
(the port's max_depth 64). With --seeds N each budget is rendered with seeds
1..N and the row gives the median CPU, relMSE and relMSE x CPU.

With --seeds 2 or more a second table splits each budget's relMSE against
the reference into femto's own variance (the seeds' spread) and the floor no
femto sample removes, the reference's error plus femto's squared bias
(tools/compare/reference_floor.py): where femto's relMSE is within ~3x of
that floor, the ratio says more about the reference than about femto.
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "bench"))
import media_suite  # noqa: E402  (the port's scene copy, render(), relmse())
import reference_floor  # noqa: E402  (femto's noise and the reference's floor)
from mitransient_peer import README_CALIBRATION, calibration  # noqa: E402  (the shared CPU calibration)
from provenance import header, load_line  # noqa: E402

# ToF-Tungsten's beams as its README reports them (2026-12-03, against
# reference-independent.npy): passes -> (CPU s, relMSE), at calibration 0.345.
PEER = {4: (7.6, 29.5), 16: (25.9, 7.11), 64: (94.5, 3.81)}


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--femto", default=os.path.join(media_suite.ROOT, "build", "bin", "femto"))
    p.add_argument("--passes", default="4,16,64")
    p.add_argument("--spp", type=int, default=1)
    p.add_argument("--seeds", type=int, default=1)
    p.add_argument("-D", "--define", action="append", default=[], metavar="NAME=VALUE")
    p.add_argument("--out", default=os.path.join(media_suite.ROOT, "build", "tof-peer"))
    args = p.parse_args(argv)
    reference = os.path.join(media_suite.TOF, "reference-independent.npy")
    if not os.path.exists(reference):
        sys.exit(f"{reference} not found")
    os.makedirs(args.out, exist_ok=True)
    scene = media_suite.tof_scene(args.out)
    ref = np.load(reference).astype(np.float64)
    extra = dict(d.split("=", 1) for d in args.define)
    floors, rows = [], []
    load_start = os.getloadavg()
    readings = calibration(3)
    for passes in [int(x) for x in args.passes.split(",")]:
        defines = dict(integrator="transient_beams", passes=passes, spp=args.spp, **extra)
        runs, volumes = [], []
        for seed in range(1, args.seeds + 1):
            out = os.path.join(args.out, f"beams-{passes}-{seed}.exr")
            npy, cpu, wall, log = media_suite.render(args.femto, scene, out, defines, seed=seed)
            x = np.load(npy).astype(np.float64)
            runs.append((cpu, media_suite.relmse(x, ref), x.sum() / ref.sum(), log))
            volumes.append(x)
            print(f"  {passes} passes seed {seed}: CPU {cpu:.1f} relMSE {runs[-1][1]:.3g}", file=sys.stderr, flush=True)
        rows.append((passes, runs))
        if len(volumes) > 1:
            floors.append((passes, reference_floor.split(volumes, ref)[:3], float(np.median([r[1] for r in runs]))))
        del volumes
    readings += calibration(3)
    calib = float(np.median(readings))
    scale = calib / README_CALIBRATION
    header("transient_beams on ToF-Tungsten's scene, against ToF-Tungsten's beams", "tools/compare/tof_peer.py",
           f"tools/compare/tof_peer.py {' '.join(argv)}",
           ["CPU = user + system seconds; relMSE against reference-independent.npy; ToF-Tungsten's CPU from its "
            f"README scaled by cpu_calibration {calib:.3f} (median of {len(readings)} readings: "
            f"{min(readings):.3f}-{max(readings):.3f}) / {README_CALIBRATION}"])
    print("| passes × spp | ToF-Tungsten CPU s (scaled) | its relMSE | femto CPU s | femto relMSE | window sum / ref | "
          "radius | pair hits / query | femto's efficiency / ToF-Tungsten's |")
    print("|---|---|---|---|---|---|---|---|---|")
    for passes, runs in rows:
        cpu = float(np.median([r[0] for r in runs]))
        e = float(np.median([r[1] for r in runs]))
        m, r = media_suite.STATS.search(runs[0][3]), media_suite.RADIUS.search(runs[0][3])
        sums = "/".join(f"{x[2]:.3f}" for x in runs)
        peer = PEER.get(passes)
        pc, pe = (peer[0] * scale, peer[1]) if peer else (None, None)
        ratio = f"**{pc * pe / (cpu * e):.2f}**" if peer else "-"
        note = ", ".join(f"{k}={v}" for k, v in extra.items())
        print(f"| {passes} × {args.spp}{' (' + note + ')' if note else ''} | {f'{pc:.1f}' if peer else '-'} | "
              f"{pe if peer else '-'} | {cpu:.1f} | {e:.3g} | {sums} | {r.group(1) if r else '-'} | "
              f"{m.group(2) if m else '-'} | {ratio} |", flush=True)
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
