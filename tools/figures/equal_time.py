#!/usr/bin/python3
"""Figure 1's renders: transient_beams at a budget of passes, then
transient_path at the samples per pixel that take the same render time, each
compared with a long multi-seed transient_path reference.

    /usr/bin/python3 tools/figures/equal_time.py scenes/cornell-box-fog/scene.xml \
        --out out/fig1 --passes 16 -D resolution=128 -D bins=512

Writes OUT/beams.npy, OUT/path.npy (and their steady EXRs), the reference,
and OUT/equal_time.json: each render's time (as femto reports it, and the
whole process), budget and error (`femto compare`: relMSE of the volume and
of its time integral), and the reference's own estimated error.

Equal time: the time is the render time femto reports (photon passes
included for transient_beams; loading the scene and writing outputs not).
transient_path's time is close to a + b·spp, so a pilot render at a few spp
gives a first guess of the spp; if the render misses the target by more than
--tolerance, the line through the two measured (spp, time) points gives the
next guess (at most --attempts renders). The machine's load moves times, so
both measured times are reported, never assumed equal.
"""
import argparse
import json
import os
import resource
import sys

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "tools", "compare"))
import error_curves as ec  # noqa: E402
import render_runs  # noqa: E402


def parse_args(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("scene")
    p.add_argument("--out", required=True, help="output folder")
    p.add_argument("--passes", type=int, default=16, help="transient_beams' budget")
    p.add_argument("--pilot-spp", type=int, default=16, help="transient_path's pilot render")
    p.add_argument("--tolerance", type=float, default=0.05, help="accepted relative time difference")
    p.add_argument("--attempts", type=int, default=3, help="transient_path renders at most")
    p.add_argument("--seed", type=int, default=1, help="seed of both test renders")
    p.add_argument("--reference-spp", type=int, default=4096, help="spp of each reference run")
    p.add_argument("--reference-runs", type=int, default=4, help="independent reference runs (seeds)")
    p.add_argument("--threads", type=int, default=0, help="femto -t (default: all cores)")
    p.add_argument("--femto", default=os.path.join(ROOT, "build", "bin", "femto"))
    p.add_argument("--cache-dir", default=os.path.join(ROOT, "build", "compare-cache"))
    p.add_argument("-D", "--define", action="append", default=[], metavar="NAME=VALUE",
                   help="scene override for every render, reference included (repeatable)")
    args = p.parse_args(argv)
    try:
        args.defines = [ec.parse_define(d) for d in args.define]
    except ec.SpecError as e:
        p.error(str(e))
    return args


def log(text):
    print(text, flush=True)


def cpu_seconds_of_children():
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def render(args, name, integrator, param, budget):
    """One test render to OUT/NAME.exr: {seconds, wall_seconds, cpu_seconds,
    budget, file}. CPU seconds (the whole process, all threads) show whether
    the machine's load, not the integrator, set a wall time."""
    cpu_before = cpu_seconds_of_children()
    seconds, wall, result = render_runs.render(
        args.femto, args.scene, os.path.join(args.out, name + ".exr"),
        args.defines + [("integrator", integrator), (param, str(budget))], args.seed, args.threads)
    cpu = cpu_seconds_of_children() - cpu_before
    log(f"{name}: {integrator} {param}={budget}: {seconds:.2f} s render, {wall:.2f} s wall, {cpu:.2f} s CPU")
    return dict(integrator=integrator, budget_param=param, budget=budget, seconds=seconds,
                wall_seconds=round(wall, 3), cpu_seconds=round(cpu, 3), file=result)


def next_spp(points, target):
    """The spp whose time is `target` on the line through the last two
    measured (spp, seconds) points (through the origin with one point)."""
    if len(points) == 1:
        spp, seconds = points[0]
        return max(1, round(spp * target / seconds))
    (s0, t0), (s1, t1) = points[-2:]
    if s1 == s0 or t1 <= t0:
        return max(1, round(s1 * target / t1))
    return max(1, round(s0 + (target - t0) * (s1 - s0) / (t1 - t0)))


def equal_time_path(args, target):
    """transient_path rendered at the spp that takes `target` seconds."""
    pilot = render(args, "path_pilot", "transient_path", "spp", args.pilot_spp)
    points = [(args.pilot_spp, pilot["seconds"])]
    best = None
    for _ in range(args.attempts):
        spp = next_spp(points, target)
        run = render(args, "path", "transient_path", "spp", spp)
        points.append((spp, run["seconds"]))
        best = run
        if abs(run["seconds"] / target - 1) <= args.tolerance:
            break
    best["pilot"] = dict(spp=args.pilot_spp, seconds=pilot["seconds"])
    return best


def reference_volume(args):
    # TEMPORARY until the multi-seed reference lands in tools/compare.
    path = render_runs.cached_reference(args.femto, args.scene, args.defines, "transient_path", "spp",
                                        args.reference_spp, 7919, args.threads, args.cache_dir, log)
    return dict(file=path, runs=1, spp=args.reference_spp, relmse=float("nan"))


def errors(args, reference, run):
    report = render_runs.compare(args.femto, reference, run["file"])
    return dict(relmse=report["metrics"]["relmse"], integral_relmse=report["time_integral"]["relmse"])


def main(argv=None):
    args = parse_args(argv or sys.argv[1:])
    os.makedirs(args.out, exist_ok=True)
    beams = render(args, "beams", "transient_beams", "passes", args.passes)
    path = equal_time_path(args, beams["seconds"])
    reference = reference_volume(args)
    for run in (beams, path):
        run.update(errors(args, reference["file"], run))
        log(f"{run['integrator']}: relMSE {run['relmse']:.4g} (volume), {run['integral_relmse']:.4g} (time integral)")
    result = dict(scene=args.scene, defines=dict(args.defines), seed=args.seed, beams=beams, path=path,
                  time_ratio=path["seconds"] / beams["seconds"], reference=reference)
    with open(os.path.join(args.out, "equal_time.json"), "w") as f:
        json.dump(result, f, indent=2)
    log(f"wrote {os.path.join(args.out, 'equal_time.json')}")


if __name__ == "__main__":
    main()
