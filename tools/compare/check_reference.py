#!/usr/bin/python3
"""Check a multi-seed reference against long renders of another integrator,
and expose bias: relMSE of two long renders (different seeds) against the
reference, against each other, and the reference's own expected contribution,
each for the volume as rendered, coarser time bins and the time integral,
where noise is small and a systematic difference (e.g. a kernel's blur) is
what remains. Prints a Markdown table; see docs/design/photon-beams.md
("Performance on the fog Cornell box").

  tools/compare/check_reference.py scenes/cornell-box-fog/scene.xml -D resolution=64 -D bins=1024 \\
      -D bin_width=0.01 -D frames=false --reference-budget spp=8192 --reference-seeds 8 \\
      --check transient_beams:passes=256 --check-seeds 101,102 --factors 1,16,1024

Every render is cached under --cache-dir as in speed_vs_error.py (the key
holds the scene file and overrides, not the code: clear the cache when the
integrators change). The volumes are loaded whole (float64): meant for the
benchmark's 64x64 sizes.
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import error_curves as ec  # noqa: E402
import reference_volume as rv  # noqa: E402
import render_runs  # noqa: E402

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))


def relmse(test, ref, eps=rv.EPSILON):
    """femto compare's relMSE (docs/compare.md)."""
    return float(np.mean((test - ref) ** 2 / (ref * ref + eps)))


def parse_args(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("scene")
    p.add_argument("-D", "--define", action="append", default=[], metavar="NAME=VALUE")
    p.add_argument("--reference-integrator", default="transient_path")
    p.add_argument("--reference-budget", default="spp=8192", metavar="PARAM=N")
    p.add_argument("--reference-seed", type=int, default=7919)
    p.add_argument("--reference-seeds", type=int, default=8, metavar="K")
    p.add_argument("--check", required=True, metavar="NAME:PARAM=N", help="the long renders, e.g. transient_beams:passes=256")
    p.add_argument("--check-seeds", default="101,102", help="two seeds (comma-separated), none among the reference's")
    p.add_argument("--factors", default="1", help="time rebinning factors to report (the number of bins: the time integral)")
    p.add_argument("--threads", type=int, default=0)
    p.add_argument("--femto", default=os.path.join(ROOT, "build", "bin", "femto"))
    p.add_argument("--cache-dir", default=os.path.join(ROOT, "build", "compare-cache"))
    args = p.parse_args(argv)
    try:
        args.defines = [ec.parse_define(d) for d in args.define]
        param, budget = ec.parse_define(args.reference_budget)
        args.reference_param, args.reference_budget = param, int(budget)
        name, cparam, budgets = ec.parse_integrator_spec(args.check)
    except (ec.SpecError, ValueError) as e:
        p.error(str(e))
    if len(budgets) != 1:
        p.error("--check takes one budget")
    args.check_integrator, args.check_param, args.check_budget = name, cparam, budgets[0]
    args.check_seeds = [int(s) for s in args.check_seeds.split(",")]
    args.ref_seeds = list(range(args.reference_seed, args.reference_seed + args.reference_seeds))
    if len(args.check_seeds) != 2 or set(args.check_seeds) & set(args.ref_seeds):
        p.error("--check-seeds takes two seeds, none of them among the reference's")
    args.factors = [int(f) for f in args.factors.split(",")]
    return args


def main(argv):
    args = parse_args(argv)
    log = lambda s: print(s, file=sys.stderr, flush=True)  # noqa: E731
    ref_path, _ = rv.multi_seed_reference(args.femto, args.scene, args.defines, args.reference_integrator,
                                          args.reference_param, args.reference_budget, args.ref_seeds, args.threads,
                                          args.cache_dir, log)
    meta = rv.reference_meta(ref_path)
    ref_error = rv.mean_and_error(meta["renders"], factors=args.factors)
    checks = [render_runs.cached_reference(args.femto, args.scene, args.defines, args.check_integrator,
                                           args.check_param, args.check_budget, s, args.threads, args.cache_dir, log)
              for s in args.check_seeds]
    ref = np.load(ref_path).astype(np.float64)
    a, b = (np.load(c).astype(np.float64) for c in checks)
    bins = ref.shape[2]
    check = f"{args.check_integrator} {args.check_param}={args.check_budget}"
    print(f"reference: mean of {len(args.ref_seeds)} x {args.reference_integrator} "
          f"{args.reference_param}={args.reference_budget}; A, B: {check}, seeds {args.check_seeds[0]}, "
          f"{args.check_seeds[1]}; ε = {rv.EPSILON}")
    print()
    print("| time bins | reference's own (expected) | A vs reference | B vs reference | B vs A | "
          "excess: mean(A, B vs ref) − ref's own − (B vs A)/2 |")
    print("|---|---|---|---|---|---|")
    for f in args.factors:
        r, ra, rb = rv.rebin(ref, f), rv.rebin(a, f), rv.rebin(b, f)
        own, va, vb, ab = ref_error[f], relmse(ra, r), relmse(rb, r), relmse(rb, ra)
        label = "time integral" if f == bins else f"{bins // f}" + (" (as rendered)" if f == 1 else "")
        # E[A vs ref] = bias^2 term + ref's own + A's own; A's own ~ (B vs A) / 2.
        excess = (va + vb) / 2 - own - ab / 2
        print(f"| {label} | {own:.3g} | {va:.3g} | {vb:.3g} | {ab:.3g} | {excess:.3g} |")
    energy = lambda v: float(np.sum(v, dtype=np.float64))  # noqa: E731
    print()
    print(f"total energy of the window, (A + B) / 2 / reference − 1: "
          f"{(energy(a) + energy(b)) / 2 / energy(ref) - 1:+.4f} (A − B: {(energy(a) - energy(b)) / energy(ref):+.4f}; "
          f"spread of the K reference renders' totals / sqrt(K): "
          f"{np.std([energy(np.load(p)) for p in meta['renders']], ddof=1) / np.sqrt(len(meta['renders'])) / energy(ref):.4f})")
    return 0


if __name__ == "__main__":
    render_runs.run_cli(main)
