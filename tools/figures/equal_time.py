#!/usr/bin/python3
"""Figure 1's renders: transient_beams at a budget of passes, then
transient_path at the samples per pixel that take the same render time, each
compared with a long multi-seed transient_path reference.

    /usr/bin/python3 tools/figures/equal_time.py scenes/cornell-box-fog/scene.xml \
        --out out/fig1 --passes 16 -D resolution=128 -D bins=512 -D bin_width=0.02

Writes OUT/beams.npy, OUT/path.npy (and their steady EXRs) and
OUT/equal_time.json: each render's time (as femto reports it; wall and CPU
seconds of the whole process), budget and error (`femto compare`: relMSE of
the volume and of its time integral, raw and less the reference's own
expected contribution), and the reference's file and error estimate. The
reference (tools/compare/reference_volume.py) is cached under --cache-dir.

Equal time: by default the render time femto reports, wall clock (photon
passes included for transient_beams; loading the scene and writing outputs
not); --time cpu_seconds makes the femto processes' CPU times (user + system,
all threads, loading and writing included: the same outputs for both) equal
instead.
transient_path's time is close to a + b·spp, so a pilot render at a few spp
gives a first guess of the spp; if the render misses the target by more than
--tolerance, the line through the two measured (spp, time) points gives the
next guess (at most --attempts renders). The machine's load moves times, so
both measured times are reported, never assumed equal.
"""
import argparse
import glob
import json
import os
import sys

import numpy as np

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "tools", "compare"))
import error_curves as ec  # noqa: E402
import reference_volume  # noqa: E402
import render_runs  # noqa: E402


def parse_args(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("scene")
    p.add_argument("--out", required=True, help="output folder")
    p.add_argument("--passes", type=int, default=16, help="transient_beams' budget")
    p.add_argument("--pilot-spp", type=int, default=16, help="transient_path's pilot render")
    p.add_argument("--tolerance", type=float, default=0.05, help="accepted relative time difference")
    p.add_argument("--attempts", type=int, default=4, help="transient_path renders at most")
    p.add_argument("--time", choices=["seconds", "cpu_seconds"], default="seconds",
                   help="what is made equal: the render time femto reports (wall clock, default) or the CPU "
                        "time of the femto process (user + system; steadier on a shared machine)")
    p.add_argument("--seed", type=int, default=1, help="seed of both test renders")
    p.add_argument("--reference-spp", type=int, default=2048, help="spp of each reference run")
    p.add_argument("--reference-runs", type=int, default=8, help="independent reference runs (at least 2)")
    p.add_argument("--reference-seed", type=int, default=7919, help="seed of the first reference run")
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
    if args.seed in range(args.reference_seed, args.reference_seed + args.reference_runs):
        p.error("--seed is one of the reference's seeds: a reference sharing the test's samples hides its error")
    return args


def log(text):
    print(text, flush=True)


def render(args, name, integrator, param, budget):
    """One test render to OUT/NAME.exr: {seconds, wall_seconds, cpu_seconds,
    budget, file}. CPU seconds (the whole process, all threads) show whether
    the machine's load, not the integrator, set a wall time."""
    r = render_runs.render(args.femto, args.scene, os.path.join(args.out, name + ".exr"),
                           args.defines + [("integrator", integrator), (param, str(budget))], args.seed, args.threads)
    log(f"{name}: {integrator} {param}={budget}: {r.seconds:.2f} s render, {r.wall_seconds:.2f} s wall, "
        f"{r.cpu_seconds:.2f} s CPU")
    return dict(integrator=integrator, budget_param=param, budget=budget, seconds=r.seconds,
                wall_seconds=round(r.wall_seconds, 3), cpu_seconds=round(r.cpu_seconds, 3), file=r.file)


def next_spp(points, target):
    """The spp whose time is `target` on the line through the last two
    measured (spp, seconds) points (through the origin with one point)."""
    if len(points) == 1:
        spp, seconds = points[0]
        return max(1, round(spp * target / seconds))
    (s0, t0), (s1, t1) = points[-2:]
    if s1 == s0 or (t1 - t0) / (s1 - s0) <= 0:  # load noise hid the cost per spp: scale the last point
        return max(1, round(s1 * target / t1))
    return max(1, round(s0 + (target - t0) * (s1 - s0) / (t1 - t0)))


def outputs(result):
    """A render's files, from what it compares (STEM.npy or STEM.exr): STEM.*
    and STEM_* (STEM_before.exr, ...)."""
    stem, _ = os.path.splitext(result)
    return stem, glob.glob(glob.escape(stem) + ".*") + glob.glob(glob.escape(stem) + "_*")


def rename_outputs(result, new_stem):
    """Rename a render's files to NEW_STEM...; returns the new name of `result`."""
    stem, files = outputs(result)
    for old in files:
        os.replace(old, new_stem + old[len(stem):])
    return new_stem + os.path.splitext(result)[1]


def remove_outputs(result):
    for old in outputs(result)[1]:
        os.remove(old)


def equal_time_path(args, target):
    """transient_path rendered at the spp that takes `target` seconds."""
    pilot = render(args, "path_pilot", "transient_path", "spp", args.pilot_spp)
    points = [(args.pilot_spp, pilot[args.time])]
    best = None
    for attempt in range(args.attempts):
        spp = next_spp(points, target)
        if best and spp == best["budget"]:
            break  # the line gives the same spp again: nothing to gain
        # Each attempt writes its own files; the closest is renamed path.* at the end.
        run = render(args, f"path_attempt{attempt}", "transient_path", "spp", spp)
        points.append((spp, run[args.time]))
        if best is None or abs(run[args.time] - target) < abs(best[args.time] - target):
            best, worse = run, best
        else:
            worse = run
        if worse:
            remove_outputs(worse["file"])  # ~100 MB each at 128x128x512
        if abs(run[args.time] / target - 1) <= args.tolerance:
            break
    remove_outputs(pilot["file"])
    best["file"] = rename_outputs(best["file"], os.path.join(args.out, "path"))
    best["pilot"] = dict(spp=args.pilot_spp, seconds=pilot[args.time])
    best["attempts"] = [dict(spp=spp, seconds=seconds) for spp, seconds in points[1:]]  # args.time
    return best


def reference(args):
    """The mean of --reference-runs transient_path renders (seeds
    --reference-seed ...), with its own expected relMSE contribution
    (tools/compare/reference_volume.py)."""
    seeds = list(range(args.reference_seed, args.reference_seed + args.reference_runs))
    path, relmse = reference_volume.multi_seed_reference(
        args.femto, args.scene, args.defines, "transient_path", "spp", args.reference_spp, seeds, args.threads,
        args.cache_dir, log)
    meta = reference_volume.reference_meta(path)
    return dict(file=path, runs=len(seeds), spp=args.reference_spp, seeds=seeds, relmse=relmse,
                integral_relmse=meta["integral_relmse_estimate"], seconds=sum(meta["seconds"]))


def errors(args, ref, run):
    """relMSE against the reference, raw and less the reference's own expected
    contribution (the errors of independent renders add)."""
    report = render_runs.compare(args.femto, ref["file"], run["file"])
    volume, integral = report["metrics"]["relmse"], report["time_integral"]["relmse"]
    # Scale-free, as docs/BENCHMARKS.md and the issues score: epsilon 0.01 x
    # mean(reference)^2 (femto compare's epsilon is 0.01 absolute, which on
    # this scene's small values weighs the bright early bins alone).
    r = np.load(ref["file"]).astype(np.float64)
    x = np.load(run["file"]).astype(np.float64).reshape(r.shape)
    scaled = float(np.mean((x - r) ** 2 / (r ** 2 + 0.01 * r.mean() ** 2)))
    return dict(relmse=volume, relmse_corrected=volume - ref["relmse"],
                integral_relmse=integral, integral_relmse_corrected=integral - ref["integral_relmse"],
                relmse_scaled=scaled)


def captions(result):
    """The figure's row labels and the lines under it (fig1_equal_time.sh)."""
    path, beams, ref = result["path"], result["beams"], result["reference"]
    cpu = result["equal"] == "cpu_seconds"

    def label(name, run):
        time = f"{run['cpu_seconds']:.1f} s CPU" if cpu else f"{run['seconds']:.1f} s"
        return f"{name}, {run['budget']} {run['budget_param']}\n{time}, relMSE {run['relmse']:.2e}"

    wall = (f"render time (wall clock) {path['seconds']:.1f} s and {beams['seconds']:.1f} s "
            f"(path / beams {result['time_ratio']:.3f})")
    cpu_time = (f"CPU time (user + system, 2 threads) {path['cpu_seconds']:.1f} s and {beams['cpu_seconds']:.1f} s "
                f"(path / beams {result['cpu_ratio']:.3f})")
    note = [
        f"equal {cpu_time if cpu else wall} for path tracing and photon beams; {wall if cpu else cpu_time}",
        f"relMSE vs the reference, volume (time integral): path {path['relmse']:.2e} ({path['integral_relmse']:.2e}), "
        f"beams {beams['relmse']:.2e} ({beams['integral_relmse']:.2e}); beams / path {beams['relmse'] / path['relmse']:.2f}",
        f"the reference's own expected relMSE {ref['relmse']:.1e} ({ref['integral_relmse']:.1e}); less it: "
        f"path {path['relmse_corrected']:.2e}, beams {beams['relmse_corrected']:.2e}, "
        f"beams / path {beams['relmse_corrected'] / path['relmse_corrected']:.2f}",
        f"relMSE with epsilon 0.01 x mean(reference)^2 (the benchmarks'): path {path['relmse_scaled']:.3g}, "
        f"beams {beams['relmse_scaled']:.3g}; relMSE x CPU, path over beams "
        f"{path['relmse_scaled'] * path['cpu_seconds'] / (beams['relmse_scaled'] * beams['cpu_seconds']):.2f}",
    ]
    return dict(path=label("path tracing", path), beams=label("photon beams", beams),
                reference=f"reference: path tracing\nmean of {ref['runs']} x {ref['spp']} spp", note="\n".join(note))


def main(argv=None):
    args = parse_args(argv or sys.argv[1:])
    os.makedirs(args.out, exist_ok=True)
    ref = reference(args)  # first: cached after the first run, and the timed renders then follow each other
    beams = render(args, "beams", "transient_beams", "passes", args.passes)
    path = equal_time_path(args, beams[args.time])
    for run in (beams, path):
        run.update(errors(args, ref, run))
        log(f"{run['integrator']}: relMSE {run['relmse']:.4g} (volume; {run['relmse_corrected']:.4g} less the "
            f"reference's), {run['integral_relmse']:.4g} (time integral; {run['integral_relmse_corrected']:.4g})")
    result = dict(scene=args.scene, defines=dict(args.defines), seed=args.seed, beams=beams, path=path,
                  equal=args.time, time_ratio=path["seconds"] / beams["seconds"],
                  cpu_ratio=path["cpu_seconds"] / beams["cpu_seconds"], reference=ref)
    result["captions"] = captions(result)
    log(result["captions"]["note"])
    with open(os.path.join(args.out, "equal_time.json"), "w") as f:
        json.dump(result, f, indent=2)
    log(f"wrote {os.path.join(args.out, 'equal_time.json')}")


if __name__ == "__main__":
    main()
