#!/usr/bin/python3
"""How transient_beams splits a budget on the fog Cornell box: camera samples
per pass, the share of camera segments that gather beams, and passes (each
with fresh photons), at about equal CPU, against transient_path; prints the
Markdown of docs/BENCHMARKS.md's "beams-pass-split" section.

  tools/bench/beams_pass_split.py [--resolution 64] [--seeds 2] \
      | tools/bench/benchmarks.py set beams-pass-split

relMSE (epsilon 0.01) against the mean of two transient_path renders of
--reference-spp (cached under build/beams-pass-split; their own error
subtracted, as tools/bench/media_suite.py does), mean over --seeds renders;
CPU = user + system seconds of the femto process.
"""
import argparse
import contextlib
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import media_suite as ms  # noqa: E402
from provenance import ROOT, header, load_line  # noqa: E402

FOG = os.path.join(ROOT, "scenes", "cornell-box-fog", "scene.xml")
# (label, integrator, parameters): transient_path's budget, then
# transient_beams' splits of passes x camera samples per pass x gather share.
ROWS = [
    ("transient_path", "transient_path", dict(spp=256)),
    ("4 passes x 32 spp, gather 1/4 (before)", "transient_beams", dict(passes=4, spp=32, gather_fraction=0.25)),
    ("4 passes x 32 spp, gather 1/8", "transient_beams", dict(passes=4, spp=32, gather_fraction=0.125)),
    ("8 passes x 16 spp, gather 1/4", "transient_beams", dict(passes=8, spp=16, gather_fraction=0.25)),
    ("8 passes x 16 spp, gather 1/8", "transient_beams", dict(passes=8, spp=16, gather_fraction=0.125)),
    ("16 passes x 8 spp, gather 1/4", "transient_beams", dict(passes=16, spp=8, gather_fraction=0.25)),
    ("16 passes x 8 spp, gather 1/8 (now)", "transient_beams", dict(passes=16, spp=8, gather_fraction=0.125)),
    ("16 passes x 8 spp, gather 1/16", "transient_beams", dict(passes=16, spp=8, gather_fraction=0.0625)),
    ("32 passes x 4 spp, gather 1/8", "transient_beams", dict(passes=32, spp=4, gather_fraction=0.125)),
]


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--femto", default=os.path.join(ROOT, "build", "bin", "femto"))
    p.add_argument("--resolution", type=int, default=64)
    p.add_argument("--seeds", type=int, default=2)
    p.add_argument("--reference-spp", type=int, default=1024)
    args = p.parse_args()
    out_dir = os.path.join(ROOT, "build", "beams-pass-split")
    os.makedirs(out_dir, exist_ok=True)
    load_start = os.getloadavg()
    header("transient_beams on the fog box: splitting a budget", "tools/bench/beams_pass_split.py",
           f"tools/bench/beams_pass_split.py --resolution {args.resolution} --seeds {args.seeds}",
           ["CPU = user + system seconds of the femto process"])
    print(f"{args.resolution}×{args.resolution} pixels, the window OPL 3 to 13.24; relMSE (ε = 0.01) against the mean "
          f"of two {args.reference_spp}-spp transient_path renders, their own error subtracted; mean over "
          f"{args.seeds} seeds. Photons per pass: the scene file's (30000, 3000 leave beams). Ratio: "
          "transient_path's relMSE × CPU over the row's (> 1: the row is more efficient).\n")
    for bins in (256, 1024):
        case = dict(name=f"fog box {args.resolution}px {bins} bins", scene=FOG,
                    defines=dict(resolution=args.resolution, bins=bins, bin_width=10.24 / bins, frames="false"),
                    reference_spp=args.reference_spp)
        with contextlib.redirect_stdout(sys.stderr):  # its progress lines
            ref, own = ms.cached_path_reference(femto=args.femto, case=case, out_dir=out_dir)
        print(f"### Splitting a budget at {bins} bins\n")
        print("| split | CPU s | relMSE | relMSE × CPU | ratio |")
        print("|---|---|---|---|---|")
        path = None
        for label, integrator, params in ROWS:
            if bins == 1024 and not (integrator == "transient_path" or "(before)" in label or "(now)" in label):
                continue
            errors, cpus = [], []
            for seed in range(1, args.seeds + 1):
                defines = dict(case["defines"], integrator=integrator, **params)
                out = os.path.join(out_dir, f"split-{bins}-{seed}.exr")
                npy, cpu, _, _ = ms.render(args.femto, FOG, out, defines, seed=seed)
                errors.append(max(ms.relmse(np.load(npy).astype(np.float64), ref) - own, 0.0))
                cpus.append(cpu)
            e, cpu = float(np.mean(errors)), float(np.mean(cpus))
            path = path or e * cpu
            print(f"| {label} | {cpu:.2f} | {e:.3g} | {e * cpu:.3g} | {path / (e * cpu):.2f} |", flush=True)
        print()
    print(load_line(load_start, os.getloadavg()))


if __name__ == "__main__":
    main()
