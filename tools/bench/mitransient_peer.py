#!/usr/bin/python3
"""Issue 34 part 1: femto's transient_path against mitransient on mitransient's own
volumetric Cornell box (../shared/scenes/mitransient-cbox-volumetric, its README).
Prints the "mitransient-peer" section of docs/BENCHMARKS.md:

  tools/bench/mitransient_peer.py [--spp 16,64,256,1024] [--repeats 3] | tools/bench/benchmarks.py set mitransient-peer

femto reads cbox_volumetric.xml unchanged (its transient_hdr_film counts OPL from
each camera ray's near-clip point, as mitransient does). 64x64, 400 bins. relMSE = mean over unmasked
cells of (x - ref)^2 / (ref^2 + 0.01 m^2), m the mean of ref over those cells,
against reference-mitransient.npy,
mask = bins 8-24 of rows 7-10, columns 26-37 (the directly seen emitter). CPU = user +
system of the femto process, median of --repeats runs (one seed per run, relMSE the
mean over runs). mitransient's CPU seconds are the README's, scaled by this machine's
reading of ../shared/tools/cpu_calibration.py (median of 3 before and 3 after) over the README's 0.345.

The reference is itself 8192 spp of Monte Carlo: the part of femto's relMSE that no
number of femto samples removes (the reference's error plus femto's squared bias) is
split off as tools/compare/reference_floor.py does, from the --repeats renders of each
budget. Where femto's relMSE is within ~3x of that floor, efficiencies are also given
with the floor taken off both sides (mitransient's figures were scored against the
same reference and contain the same floor). mitransient at spp beyond the README's
largest budget is extrapolated from its two largest: CPU linearly, relMSE above the
floor as 1/spp; the row says so.
"""
import argparse
import os
import shutil
import statistics
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import provenance  # noqa: E402
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "compare"))
import reference_floor  # noqa: E402  (femto's noise and the reference's floor)
from media_suite import ROOT, cpu_of_children  # noqa: E402

SHARED = os.path.join(os.path.dirname(ROOT.rstrip("/")), "shared")
SCENE_DIR = os.path.join(SHARED, "scenes", "mitransient-cbox-volumetric")
CALIBRATION = os.path.join(SHARED, "tools", "cpu_calibration.py")
README_CALIBRATION = 0.345
# mitransient's README table (2026-12-03): spp -> (CPU s, relMSE).
MITRANSIENT = {16: (1.24, 41.5), 64: (1.56, 9.92), 256: (3.33, 2.67)}


def render(femto, scene, out, spp, seed, threads):
    """One femto render; returns (its volume, CPU seconds of the process)."""
    cmd = [femto, "render", scene, "-o", out, "--seed", str(seed), "--no-progress", "-t", str(threads),
           "-D", f"spp={spp}", "-D", "res=64"]
    cpu0 = cpu_of_children()
    proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    cpu = cpu_of_children() - cpu0
    if proc.returncode != 0:
        sys.exit(f"`{' '.join(cmd)}` exited {proc.returncode}:\n{proc.stdout}")
    return os.path.splitext(out)[0] + ".npy", cpu


def calibration(runs):
    """`runs` readings of ../shared/tools/cpu_calibration.py (CPU s of its fixed workload)."""
    return [float(subprocess.run([sys.executable, CALIBRATION], stdout=subprocess.PIPE, text=True,
                                 check=True).stdout.strip()) for _ in range(runs)]


def mask(shape):
    keep = np.ones(shape[:3], dtype=bool)
    keep[7:11, 26:38, 8:25] = False
    return keep


def weights(ref, keep):
    # mean(ref) over the unmasked cells, as the README's mitransient figures
    # were scored (the emitter's masked bins would double it and halve the
    # floor-dominated errors: femto's 64-spp relMSE reads 5.5 that way, 11.7 this).
    m = ref[keep].mean()
    return 1.0 / (ref ** 2 + 0.01 * m * m)


def relmse(x, ref, keep):
    return float(((x - ref) ** 2 * weights(ref, keep))[keep].mean())


def mitransient_at(spp, floor):
    """(CPU s, relMSE, extrapolated?) of mitransient at `spp` from its README
    table; beyond its largest budget its noise above `floor` falls as 1/spp
    and its CPU grows at its last marginal cost; None below it."""
    if spp in MITRANSIENT:
        return MITRANSIENT[spp] + (False,)
    (s0, (c0, _)), (s1, (c1, e1)) = sorted(MITRANSIENT.items())[-2:]
    if spp < s1:
        return None
    return c1 + (spp - s1) * (c1 - c0) / (s1 - s0), floor + (e1 - floor) * s1 / spp, True


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--femto", default=os.path.join(ROOT, "build", "bin", "femto"))
    p.add_argument("--spp", default="16,64,256,1024")
    p.add_argument("--repeats", type=int, default=3)
    p.add_argument("--threads", type=int, default=2)
    args = p.parse_args(argv)
    ref = np.load(os.path.join(SCENE_DIR, "reference-mitransient.npy")).astype(np.float64)
    keep = mask(ref.shape)
    readings = calibration(3)
    start = os.getloadavg()
    tmp = tempfile.mkdtemp(prefix="mitransient-peer-")
    rows = []
    try:
        scene = os.path.join(SCENE_DIR, "cbox_volumetric.xml")
        for spp in [int(s) for s in args.spp.split(",")]:
            cpus, errors, volumes = [], [], []
            for seed in range(1, args.repeats + 1):
                npy, cpu = render(args.femto, scene, os.path.join(tmp, "run.exr"), spp, seed, args.threads)
                x = np.load(npy).astype(np.float64).reshape(ref.shape)
                cpus.append(cpu)
                errors.append(relmse(x, ref, keep))
                volumes.append(x)
            c, e = statistics.median(cpus), float(np.mean(errors))
            floor = reference_floor.split(volumes, ref, weights(ref, keep), keep)[2] if len(volumes) > 1 else 0.0
            rows.append((spp, c, e, floor))
            print(f"  {spp} spp: CPU {c:.2f} relMSE {e:.4g} floor {floor:.3g}", file=sys.stderr, flush=True)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    # The machine's speed drifts on a shared host: read it before and after, take the median.
    readings += calibration(3)
    calib = statistics.median(readings)
    scale = calib / README_CALIBRATION
    provenance.header("mitransient's volumetric Cornell box: transient_path against mitransient",
                      "tools/bench/mitransient_peer.py", "tools/bench/mitransient_peer.py " + " ".join(argv),
                      notes=[f"64x64, 400 bins, the scene unchanged, emitter's bins masked; CPU the median of "
                             f"{args.repeats} runs, relMSE the mean over them; {args.threads} render threads",
                             f"mitransient's CPU from its README scaled by cpu_calibration {calib:.3f} (median of "
                             f"{', '.join(f'{r:.3f}' for r in readings)}) / {README_CALIBRATION} = {scale:.2f}"])
    print("| spp | femto CPU s | femto relMSE | reference floor | mitransient CPU s (scaled) | mitransient relMSE | "
          "femto's efficiency / mitransient's | the same, floor taken off both |")
    print("|---|---|---|---|---|---|---|---|")
    for spp, c, e, floor in rows:
        peer = mitransient_at(spp, floor)
        if peer is None:
            print(f"| {spp} | {c:.2f} | {e:.4g} | {floor:.3g} | – | – | – | – |")
            continue
        mc, me, extrapolated = peer
        mc *= scale
        net = mc * (me - floor) / (c * (e - floor)) if e > floor and me > floor else float("nan")
        mark = " (extrapolated)" if extrapolated else ""
        print(f"| {spp} | {c:.2f} | {e:.4g} | {floor:.3g} | {mc:.2f}{mark} | {me:.4g}{mark} | "
              f"{mc * me / (c * e):.2f} | {net:.2f} |")
    print()
    print(provenance.load_line(start, os.getloadavg()))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
