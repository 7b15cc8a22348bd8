#!/usr/bin/python3
"""transient_beams' surface photon kernel on the fog Cornell box: relMSE, CPU
and the window sum against the surface radius, for this build and optionally
an earlier one (the kernel before a change); prints the Markdown of
docs/BENCHMARKS.md's "surface-radius" section.

  tools/bench/surface_radius_sweep.py [--radii 0,0.0346,0.07,0.1,0.15] [--seeds 2] \
      [--before /path/to/earlier/bin/femto --before-label "..."] \
      | tools/bench/benchmarks.py set surface-radius
  (with --medium none: set surface-radius-no-medium)

32x32 pixels, 1024 bins of 0.01 OPL, 8 passes of the scene file's split
(scenes/cornell-box-fog/integrator-transient_beams.xml: 8 camera samples
per pass, an eighth gathering beams); radius 0 is the integrator's default. relMSE (epsilon 0.01) against
the media suite's fog-box reference (the mean of two 2048-spp transient_path
renders, cached under build/media-suite; its own error subtracted); the
window sum is the volume's sum over the reference's. Means over --seeds.
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


def rows(femto, label, radii, seeds, ref, own, out_dir, medium, path_spp=0):
    for radius in ([None] if path_spp else radii):
        errors, cpus, sums = [], [], []
        for seed in range(1, seeds + 1):
            defines = dict(resolution=32, bins=1024, bin_width=0.01, frames="false", medium=medium)
            if path_spp:
                defines.update(integrator="transient_path", spp=path_spp)
            else:
                defines.update(integrator="transient_beams", passes=8, surface_radius=radius)
            npy, cpu, _, _ = ms.render(femto, FOG, os.path.join(out_dir, f"surface-radius-{seed}.exr"), defines, seed)
            x = np.load(npy).astype(np.float64)
            errors.append(ms.relmse(x, ref) - own)
            cpus.append(cpu)
            sums.append(x.sum() / ref.sum())
        e, cpu = float(np.mean(errors)), float(np.mean(cpus))
        name = "-" if radius is None else ("default" if radius == 0 else f"{radius:g}")
        print(f"| {label} | {name} | {cpu:.2f} | {e:.3g} | {e * cpu:.3g} | "
              f"{' / '.join(f'{s:.4f}' for s in sums)} |", flush=True)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--femto", default=os.path.join(ROOT, "build", "bin", "femto"))
    p.add_argument("--radii", default="0,0.0346,0.07,0.1,0.15")
    p.add_argument("--seeds", type=int, default=2)
    p.add_argument("--before", help="an earlier build's femto, rendered first")
    p.add_argument("--before-label", default="before")
    p.add_argument("--medium", default="fog", help="the scene's -D medium: fog, or none (the box's walls alone)")
    p.add_argument("--path-spp", type=int, default=128, help="transient_path's row, for the ratio (0: none)")
    args = p.parse_args()
    radii = [float(r) for r in args.radii.split(",")]
    out_dir = os.path.join(ROOT, "build", "surface-radius")
    os.makedirs(out_dir, exist_ok=True)
    case = [c for c in ms.cases(os.path.join(ROOT, "build", "media-suite"), quick=False)
            if c["name"] == "fog box, 1024 bins"][0]
    if args.medium != "fog":
        case = dict(case, name=f"fog box, 1024 bins, medium {args.medium}",
                    defines=dict(case["defines"], medium=args.medium))
    with contextlib.redirect_stdout(sys.stderr):  # its progress lines
        ref, own = ms.cached_path_reference(femto=args.femto, case=case,
                                            out_dir=os.path.join(ROOT, "build", "media-suite"))
    load_start = os.getloadavg()
    command = (f"tools/bench/surface_radius_sweep.py --radii {args.radii} --seeds {args.seeds} "
               f"--medium {args.medium} --path-spp {args.path_spp}")
    if args.before:
        command += f" --before <{args.before_label}> --before-label \"{args.before_label}\""
    header("transient_beams' surface kernel on the fog box" + ("" if args.medium == "fog" else f", medium {args.medium}"), "tools/bench/surface_radius_sweep.py", command,
           ["CPU = user + system seconds of the femto process"])
    print(f"`-D medium={args.medium}`; 32×32 pixels, 1024 bins of 0.01 OPL, 8 passes of the scene file's split; "
          "relMSE (ε = 0.01) against the mean of two 2048-spp transient_path renders (the media suite's for the fog, "
          "cached under build/media-suite), their own error subtracted; "
          f"means over {args.seeds} seeds; window sum: the volume's sum over the reference's, per seed. "
          "Radius `default`: the integrator's own.\n")
    print("| build | surface radius | CPU s | relMSE | relMSE × CPU | window sum / reference |")
    print("|---|---|---|---|---|---|")
    if args.path_spp:
        rows(args.femto, f"transient_path, {args.path_spp} spp", radii, args.seeds, ref, own, out_dir, args.medium,
             args.path_spp)
    if args.before:
        rows(args.before, args.before_label, radii, args.seeds, ref, own, out_dir, args.medium)
    rows(args.femto, "this commit", radii, args.seeds, ref, own, out_dir, args.medium)
    print()
    print(load_line(load_start, os.getloadavg()))


if __name__ == "__main__":
    main()
