#!/usr/bin/python3
"""Which sampler serves each integrator best: render every integrator at one
budget with each sampler (-D sampler=NAME: the scene must declare
<default name="sampler">) and several seeds, measure the relMSE against a
multi-seed reference (reference_volume.py) and the CPU time, and print a
Markdown table. The figure of merit is the efficiency 1 / (relMSE x CPU
time) (Monte Carlo error falls as 1/time, so it does not depend on the
budget), with the reference's own expected error subtracted from relMSE
first, relative to the `independent` sampler of the same integrator.

  tools/compare/sampler_table.py scenes/cornell-box-fog/scene.xml \\
      --integrator transient_path:spp=256 --integrator transient_beams:passes=4 \\
      --samplers independent,stratified,ldsampler --seeds 1,2,3 -D resolution=64 ... \\
      --reference-budget spp=8192 --reference-seeds 8 --cache-dir build/compare-cache
"""
import argparse
import os
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import error_curves as ec  # noqa: E402
import reference_volume  # noqa: E402
import render_runs  # noqa: E402


def parse_args(argv):
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("scene")
    p.add_argument("--integrator", action="append", required=True, metavar="NAME:PARAM=BUDGET",
                   help="an integrator and ONE budget (repeatable)")
    p.add_argument("--samplers", default="independent,stratified,ldsampler")
    p.add_argument("--seeds", default="1,2,3")
    p.add_argument("-D", "--define", action="append", default=[], metavar="NAME=VALUE")
    p.add_argument("--reference-integrator", default="transient_path")
    p.add_argument("--reference-budget", default="spp=8192", metavar="PARAM=N")
    p.add_argument("--reference-seeds", type=int, default=8, help="renders in the reference (seeds 7919, ...)")
    p.add_argument("--reference-define", action="append", default=[], metavar="NAME=VALUE",
                   help="overrides of the reference only (replacing -D of the same name)")
    p.add_argument("--femto", default="build/bin/femto")
    p.add_argument("--threads", type=int, default=0)
    p.add_argument("--cache-dir", default="build/compare-cache")
    p.add_argument("--out-dir", default="build/compare/samplers")
    args = p.parse_args(argv)
    args.integrators = []
    for spec in args.integrator:
        name, param, budgets = ec.parse_integrator_spec(spec)
        if len(budgets) != 1:
            p.error(f"--integrator {spec}: give one budget")
        args.integrators.append((name, param, budgets[0]))
    args.defines = [ec.parse_define(d) for d in args.define]
    overrides = dict(ec.parse_define(d) for d in args.reference_define)
    args.reference_defines = [(k, v) for k, v in args.defines if k not in overrides] + list(overrides.items())
    args.reference_param, budget = ec.parse_define(args.reference_budget)
    args.reference_budget = int(budget)
    return args


def main(argv):
    args = parse_args(argv)
    log = lambda text: print(text, file=sys.stderr)  # noqa: E731
    reference, _ = reference_volume.multi_seed_reference(
        args.femto, args.scene, args.reference_defines, args.reference_integrator, args.reference_param,
        args.reference_budget, list(range(7919, 7919 + args.reference_seeds)), args.threads, args.cache_dir, log)
    reference_error = reference_volume.reference_meta(reference)["relmse_estimate"]
    os.makedirs(args.out_dir, exist_ok=True)
    print(f"Reference: mean of {args.reference_seeds} x {args.reference_integrator} "
          f"{args.reference_param}={args.reference_budget}; its expected relMSE contribution "
          f"{reference_error:.3g} is subtracted. Medians over seeds {args.seeds}.")
    print()
    print("| integrator | budget | sampler | CPU s | relMSE | relMSE − reference's | efficiency vs independent |")
    print("|---|---|---|---|---|---|---|")
    for name, param, budget in args.integrators:
        merit = {}
        for sampler in args.samplers.split(","):
            cpu, rel = [], []
            for seed in args.seeds.split(","):
                out = os.path.join(args.out_dir, f"{name}-{sampler}-{seed}.exr")
                defines = args.defines + [("integrator", name), (param, str(budget)), ("sampler", sampler)]
                r = render_runs.render(args.femto, args.scene, out, defines, int(seed), args.threads)
                m = render_runs.compare(args.femto, reference, r.file)["metrics"]
                cpu.append(r.cpu_seconds)
                rel.append(m["relmse"])
            c, e = statistics.median(cpu), statistics.median(rel)
            corrected = max(e - reference_error, 1e-30)
            merit[sampler] = 1.0 / (corrected * c)
            relative = merit[sampler] / merit["independent"] if "independent" in merit else float("nan")
            print(f"| {name} | {param}={budget} | {sampler} | {c:.2f} | {e:.3g} | {corrected:.3g} | {relative:.2f} |",
                  flush=True)


if __name__ == "__main__":
    main(sys.argv[1:])
