#!/usr/bin/python3
"""transient_beams' efficiency against an explicit first-pass radius, on the
media suite's scenes (tools/bench/media_suite.py: same scenes, budgets and
references): what the derived radius (radius_rule.h) should produce.

  tools/bench/beams_radius_sweep.py [--femto build/bin/femto] [--out build/media-suite]
      [--only NAME] [--radii 0,0.003,0.006,...] [--seeds 1,2] [--define name=value ...]

Per scene and radius (0: derived), one render per seed: relMSE (epsilon 0.01)
against the suite's reference, less the reference's own error; CPU seconds
(user + system of the femto process); relMSE x CPU (lower is better; the
table gives the median over seeds); the window sum over the reference's;
the first pass's radius and candidates / pair hits per beam query from the
log. One transient_path render at the suite's budget gives path's relMSE x CPU
for the ratio column (> 1: beams better).
"""
import argparse
import os
import statistics
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import media_suite as suite  # noqa: E402


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--femto", default=os.path.join(suite.ROOT, "build", "bin", "femto"))
    p.add_argument("--out", default=os.path.join(suite.ROOT, "build", "media-suite"))
    p.add_argument("--only", help="only the cases whose name contains this")
    p.add_argument("--radii", default="0,0.003,0.006,0.012,0.024,0.048,0.096")
    p.add_argument("--seeds", default="1,2")
    p.add_argument("--define", action="append", default=[], help="name=value for every beams render")
    p.add_argument("--no-path", action="store_true", help="skip the transient_path render")
    args = p.parse_args(argv)
    os.makedirs(args.out, exist_ok=True)
    extra = dict(d.split("=", 1) for d in args.define)
    seeds = [int(s) for s in args.seeds.split(",")]
    for case in suite.cases(args.out, quick=False):
        if args.only and args.only not in case["name"]:
            continue
        ref, own = (suite.tof_reference() if case.get("reference") == "tof"
                    else suite.cached_path_reference(femto=args.femto, case=case, out_dir=args.out))
        tag = suite.slug(case["name"])
        path_eff = None
        if not args.no_path:
            defines = dict(case["defines"], integrator="transient_path", **case["path"])
            npy, cpu, _, _ = suite.render(args.femto, case["scene"], os.path.join(args.out, f"sweep-{tag}-path.exr"),
                                          defines, seed=1)
            e = max(suite.relmse(np.load(npy).astype(np.float64), ref) - own, 0.0)
            path_eff = e * cpu
            print(f"{case['name']}: path {case['path']} CPU {cpu:.1f} s relMSE {e:.4g} relMSE x CPU {path_eff:.4g}",
                  flush=True)
        print(f"| {case['name']} radius | CPU s | relMSE | relMSE x CPU (median) | path / beams | window sum | "
              "first-pass radius | candidates / query | hits / query | hits / candidate |")
        print("|---|---|---|---|---|---|---|---|---|---|")
        for radius in args.radii.split(","):
            runs = []
            for seed in seeds:
                defines = dict(case["defines"], integrator="transient_beams", radius=radius, **case["beams"], **extra)
                npy, cpu, _, log = suite.render(args.femto, case["scene"],
                                                os.path.join(args.out, f"sweep-{tag}-beams.exr"), defines, seed)
                x = np.load(npy).astype(np.float64)
                e = max(suite.relmse(x, ref) - own, 0.0)
                m, r = suite.STATS.search(log), suite.RADIUS.search(log)
                runs.append(dict(cpu=cpu, e=e, eff=e * cpu, sum=float(x.sum() / ref.sum()),
                                 r=float(r.group(1)) if r else 0.0,
                                 cand=float(m.group(1)) if m else 0.0, hits=float(m.group(2)) if m else 0.0))
            med = lambda k: statistics.median(run[k] for run in runs)  # noqa: E731
            eff = med("eff")
            ratio = f"{path_eff / eff:.2f}" if path_eff is not None and eff > 0 else "-"
            print(f"| {radius} | {med('cpu'):.1f} | {med('e'):.4g} | {eff:.4g} | {ratio} | {med('sum'):.3f} | "
                  f"{med('r'):.4g} | {med('cand'):.0f} | {med('hits'):.1f} | "
                  f"{med('hits') / max(med('cand'), 1e-30):.2f} |", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
