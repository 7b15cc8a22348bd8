#!/usr/bin/python3
"""Issue 33's headline: transient_beams against transient_path on the seed's
scene (scenes/cornell-box-fog) at 256 and 1024 bins, at equal CPU. Prints the
"fog-box-beams" section of docs/BENCHMARKS.md:

  tools/bench/fog_box_beams.py [--resolution 64] [--seeds 2] [--repeats 3] | tools/bench/benchmarks.py set fog-box-beams

Per bin count: a reference independent of every render scored (the mean of
two transient_path renders at --reference-spp with seeds no render below
uses, cached in build/fog-box-beams); its own relMSE (from its two halves) is
the floor subtracted from every score ("corrected"). Then path at 64 and 256
spp against beams at 4 and 16 passes (the scene's own integrator files, so
its defaults), each over --seeds seeds: relMSE (epsilon 0.01, as tools/compare)
the mean over seeds, CPU (user + system of the femto process) the median of
--repeats runs per seed. relMSE x CPU is about constant in the budget for a
Monte Carlo estimator, so path's product over beams' is the ratio of their
errors at equal CPU time.
"""
import argparse
import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import provenance  # noqa: E402
from media_suite import ROOT, relmse, render  # noqa: E402

SCENE = os.path.join(ROOT, "scenes", "cornell-box-fog", "scene.xml")
WINDOW = 10.24  # the scene's window, OPL 3 to 13.24


def reference(femto, out, base, spp):
    """Mean of two path renders (seeds 7919, 7920) and its own relMSE against the truth."""
    key = f"ref-{base['resolution']}-{base['bins']}-{spp}"
    path = os.path.join(out, key + ".npz")
    if os.path.exists(path):
        z = np.load(path)
        return z["ref"], float(z["own"])
    runs = []
    for seed in (7919, 7920):
        print(f"  reference seed {seed} ({spp} spp) ...", file=sys.stderr, flush=True)
        npy, _, _, _ = render(femto, SCENE, os.path.join(out, f"{key}-{seed}.exr"),
                              dict(base, integrator="transient_path", spp=spp), seed)
        runs.append(np.load(npy).astype(np.float64))
    ref = 0.5 * (runs[0] + runs[1])
    m = ref.mean()
    own = float(np.mean((runs[0] - runs[1]) ** 2 / 4.0 / (ref ** 2 + 0.01 * m * m)))
    np.savez(path, ref=ref, own=own)
    return ref, own


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--femto", default=os.path.join(ROOT, "build", "bin", "femto"))
    p.add_argument("--out", default=os.path.join(ROOT, "build", "fog-box-beams"))
    p.add_argument("--resolution", type=int, default=64)
    p.add_argument("--bins", default="256,1024")
    p.add_argument("--seeds", type=int, default=2)
    p.add_argument("--repeats", type=int, default=3)
    p.add_argument("--reference-spp", type=int, default=2048, help="per reference render (two are averaged)")
    args = p.parse_args(argv)
    os.makedirs(args.out, exist_ok=True)
    start = os.getloadavg()
    budgets = [("transient_path", dict(spp=64)), ("transient_path", dict(spp=256)),
               ("transient_beams", dict(passes=4)), ("transient_beams", dict(passes=16))]
    rows = []
    for bins in [int(b) for b in args.bins.split(",")]:
        base = dict(resolution=args.resolution, bins=bins, bin_width=WINDOW / bins, frames="false")
        ref, own = reference(args.femto, args.out, base, args.reference_spp)
        for integrator, budget in budgets:
            errors, cpus = [], []
            for seed in range(1, args.seeds + 1):
                for _ in range(args.repeats):
                    npy, cpu, _, _ = render(args.femto, SCENE, os.path.join(args.out, "run.exr"),
                                            dict(base, integrator=integrator, **budget), seed)
                    cpus.append(cpu)
                errors.append(relmse(np.load(npy).astype(np.float64), ref))
            e, c = float(np.mean(errors)), float(np.median(cpus))
            rows.append(dict(bins=bins, integrator=integrator, budget=budget, relmse=e, corrected=max(e - own, 1e-12),
                             cpu=c, own=own))
            print(f"  {bins} bins {integrator} {budget}: relMSE {e:.4g} CPU {c:.2f}", file=sys.stderr, flush=True)
    provenance.header("Fog box: beams against path at 256 and 1024 bins", "tools/bench/fog_box_beams.py",
                      "tools/bench/fog_box_beams.py " + " ".join(argv),
                      notes=[f"{args.resolution}x{args.resolution} pixels, the scene's defaults (its integrator files), "
                             f"{args.seeds} seeds, CPU the median of {args.repeats} runs per seed; reference: 2 x "
                             f"{args.reference_spp} spp transient_path, its own relMSE subtracted"])
    print("| bins | integrator | budget | CPU s | relMSE | corrected | corrected relMSE × CPU |")
    print("|---|---|---|---|---|---|---|")
    for r in rows:
        budget = ", ".join(f"{k} {v}" for k, v in r["budget"].items())
        print(f"| {r['bins']} | {r['integrator']} | {budget} | {r['cpu']:.2f} | {r['relmse']:.4g} | "
              f"{r['corrected']:.4g} | {r['corrected'] * r['cpu']:.4g} |")
    print()
    print("| bins | path budget | beams budget | path's relMSE × CPU over beams' (> 1: beams better) |")
    print("|---|---|---|---|")
    for bins in sorted({r["bins"] for r in rows}):
        path = [r for r in rows if r["bins"] == bins and r["integrator"] == "transient_path"]
        beams = [r for r in rows if r["bins"] == bins and r["integrator"] == "transient_beams"]
        for a, b in zip(path, beams):
            ratio = a["corrected"] * a["cpu"] / (b["corrected"] * b["cpu"])
            print(f"| {bins} | {a['budget']['spp']} spp | {b['budget']['passes']} passes | {ratio:.2f} |")
    print()
    print(provenance.load_line(start, os.getloadavg()))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
