#!/usr/bin/python3
"""Speed vs error: render one scene with several integrators at increasing
budgets, measure each render's time and its error against a reference, and
write a CSV, a log-log plot of error vs time and a summary (time to reach an
error, equal-time error ratios, convergence slopes). See docs/compare.md.

  tools/compare/speed_vs_error.py scenes/cornell-box-fog/scene.xml \\
      --integrator transient_path:spp=1,2,4,8,16 -D resolution=64 --out-dir out/fog

The reference is a long render with another seed (cached under --cache-dir,
keyed by the scene file's content and the overrides), or the mean of
--reference-seeds K such renders, whose spread also estimates the reference's
own error (reference_volume.py): the summary then gives every relMSE both as
measured and with that contribution subtracted. Or --reference FILE (e.g. an
analytic solution). Budgets are passed as -D PARAM=B, so the scene
needs a <default name="PARAM">; each integrator names its own budget
parameter (transient_path:spp=..., transient_beams:passes=...).
"""
import argparse
import csv
import datetime
import os
import platform
import re
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import error_curves as ec  # noqa: E402
import reference_volume  # noqa: E402
import render_runs  # noqa: E402

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
CSV_COLUMNS = ["integrator", "budget_param", "budget", "seconds", "wall_seconds", "cpu_seconds", "relmse",
               "relmse_corrected", "mse", "mae", "max_error", "integral_relmse", "integral_relmse_corrected"]


def parse_args(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0], formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("scene")
    p.add_argument("--integrator", action="append", default=[], metavar="NAME:PARAM=B1,B2,...",
                   help="an integrator and its budgets (repeatable); default transient_path:spp=1,2,4,8,16")
    p.add_argument("-D", "--define", action="append", default=[], metavar="NAME=VALUE",
                   help="scene override for every render, reference included (repeatable)")
    p.add_argument("--reference", metavar="FILE", help="use this reference instead of rendering one")
    p.add_argument("--reference-integrator", help="integrator of the reference render (default: the first)")
    p.add_argument("--reference-budget", default="spp=1024", metavar="PARAM=N",
                   help="budget of the reference render (default spp=1024)")
    p.add_argument("--seed", type=int, default=1, help="seed of the budget renders")
    p.add_argument("--reference-seed", type=int, default=7919,
                   help="seed of the reference, the first of them with --reference-seeds (must differ from --seed)")
    p.add_argument("--reference-seeds", type=int, default=1, metavar="K",
                   help="reference = mean of K renders, seeds --reference-seed ... +K-1; K >= 2 also estimates "
                        "its own error and reports relMSE with it subtracted (default 1)")
    p.add_argument("--reference-define", action="append", default=[], metavar="NAME=VALUE",
                   help="override for the reference renders only (repeatable), e.g. a finer time grid "
                        "with --reference-rebin")
    p.add_argument("--reference-rebin", type=int, default=1, metavar="F",
                   help="sum the reference renders' time bins in runs of F (renders F times finer in time; "
                        "needs --reference-seeds >= 2)")
    p.add_argument("--threads", type=int, default=0, help="femto -t (default: all cores)")
    p.add_argument("--femto", default=os.path.join(ROOT, "build", "bin", "femto"))
    p.add_argument("--cache-dir", default=os.path.join(ROOT, "build", "compare-cache"))
    p.add_argument("--out-dir", required=True)
    p.add_argument("--target", type=float, help="relMSE for time-to-reach (default: the largest all curves reach)")
    p.add_argument("--time", choices=["seconds", "wall_seconds", "cpu_seconds"], default="seconds",
                   help="time axis: the render time femto reports (default), or the whole process's wall "
                        "or CPU (user + system) time; CPU time is the stable one on a loaded machine")
    p.add_argument("--title", help="plot title (default: the scene and overrides)")
    p.add_argument("--plot", help="plot file, .png or .svg (default OUT_DIR/relmse_vs_time.png)")
    args = p.parse_args(argv)
    try:
        args.integrators = [ec.parse_integrator_spec(s) for s in args.integrator or ["transient_path:spp=1,2,4,8,16"]]
        args.defines = [ec.parse_define(d) for d in args.define]
        overrides = dict(ec.parse_define(d) for d in args.reference_define)
        ref_param, ref_budget = ec.parse_define(args.reference_budget)
        args.reference_param, args.reference_budget = ref_param, int(ref_budget)
    except (ec.SpecError, ValueError) as e:
        p.error(str(e))
    if args.reference_seeds < 1 or args.reference_rebin < 1:
        p.error("--reference-seeds and --reference-rebin must be >= 1")
    if args.reference_rebin > 1 and args.reference_seeds < 2:
        p.error("--reference-rebin needs --reference-seeds >= 2 (the multi-seed reference)")
    args.reference_seed_list = [args.reference_seed + i for i in range(args.reference_seeds)]
    if args.seed in args.reference_seed_list:
        p.error("--seed must differ from the reference's seeds: a reference sharing the test's samples hides its error")
    # The reference renders' overrides: the budget renders' with --reference-define replacing or adding names.
    args.reference_defines = [(n, overrides.pop(n, v)) for n, v in args.defines] + list(overrides.items())
    args.reference_integrator = args.reference_integrator or args.integrators[0][0]
    try:
        scene_text = open(args.scene).read()
    except OSError as e:
        p.error(f"cannot read the scene: {e}")
    params = {"integrator"} | {param for _, param, _ in args.integrators}
    if not args.reference:
        params.add(args.reference_param)
    for param in sorted(params):
        # Without it, -D PARAM=... would change nothing and every budget would render the same.
        if not re.search(r'<default\s+name="%s"' % re.escape(param), scene_text):
            p.error(f'{args.scene} has no <default name="{param}">: -D {param}=... would change nothing')
    return args


def machine_caption(args):
    """Machine, commit, date and load: the context any timing needs."""
    cpu = platform.processor() or "unknown CPU"
    try:
        with open("/proc/cpuinfo") as f:
            cpu = next(l.split(":", 1)[1].strip() for l in f if l.startswith("model name"))
    except (OSError, StopIteration):
        pass
    def git(*a):
        try:  # a machine without git: no commit in the caption
            r = subprocess.run(["git", "-C", ROOT, *a], stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
        except OSError:
            return ""
        return r.stdout.strip() if r.returncode == 0 else ""
    commit = git("rev-parse", "--short", "HEAD") or "unknown commit"
    if git("status", "--porcelain", "--", "src", "tools"):
        commit += " (modified)"
    load = " ".join(open("/proc/loadavg").read().split()[:3]) if os.path.exists("/proc/loadavg") else "?"
    date = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    threads = args.threads or os.cpu_count()
    return f"{cpu}, {threads} threads; commit {commit}; {date}; load average {load}"


class Reference:
    """The file every render is compared with, and its own expected relMSE
    contribution (volume and time integral; 0 when unknown: a single render
    or a given file)."""

    def __init__(self, path, relmse=0.0, integral_relmse=0.0, text=""):
        self.path, self.relmse, self.integral_relmse, self.text = path, relmse, integral_relmse, text


def make_reference(args, log):
    if args.reference:
        return Reference(args.reference, text=args.reference)
    what = f"{args.reference_integrator} {args.reference_param}={args.reference_budget}"
    if args.reference_seeds == 1:
        path = render_runs.cached_reference(
            args.femto, args.scene, args.reference_defines, args.reference_integrator, args.reference_param,
            args.reference_budget, args.reference_seed, args.threads, args.cache_dir, log)
        return Reference(path, text=f"{what}, seed {args.reference_seed}")
    path, relmse = reference_volume.multi_seed_reference(
        args.femto, args.scene, args.reference_defines, args.reference_integrator, args.reference_param,
        args.reference_budget, args.reference_seed_list, args.threads, args.cache_dir, log,
        rebin_factor=args.reference_rebin)
    meta = reference_volume.reference_meta(path)
    seeds = args.reference_seed_list
    text = f"mean of {len(seeds)} x {what} (seeds {seeds[0]}-{seeds[-1]})"
    if args.reference_rebin > 1:
        text += f", rendered with {args.reference_rebin}x finer time bins and summed"
    return Reference(path, relmse, meta["integral_relmse_estimate"], text)


def run_budgets(args, reference, log):
    rows = []
    for name, param, budgets in args.integrators:
        for budget in budgets:
            out = os.path.join(args.out_dir, "renders", f"{name}_{param}{budget}.exr")
            r = render_runs.render(args.femto, args.scene, out,
                                   args.defines + [("integrator", name), (param, str(budget))], args.seed,
                                   args.threads)
            report = render_runs.compare(args.femto, reference.path, r.file)
            m = report["metrics"]
            integral = report.get("time_integral", m)
            row = dict(integrator=name, budget_param=param, budget=budget, seconds=r.seconds,
                       wall_seconds=round(r.wall_seconds, 3), cpu_seconds=round(r.cpu_seconds, 3),
                       relmse=m["relmse"], relmse_corrected=m["relmse"] - reference.relmse,
                       mse=m["mse"], mae=m["mae"], max_error=m["max_error"], integral_relmse=integral["relmse"],
                       integral_relmse_corrected=integral["relmse"] - reference.integral_relmse)
            log(f"{name} {param}={budget}: {r.seconds:.3f} s ({r.cpu_seconds:.3f} s CPU), "
                f"relMSE {m['relmse']:.4g} (corrected {row['relmse_corrected']:.4g}), MSE {m['mse']:.4g}")
            rows.append(row)
    return rows


def summarize(rows, args, reference):
    """Time to reach a relMSE, slopes and equal-time ratios, as text lines:
    of the relMSE as measured and, when the reference's own error is known,
    with it subtracted."""
    lines = []
    if reference.relmse:
        low = min(float(r["relmse"]) for r in rows)
        lines += [f"reference: {reference.text}",
                  f"  its expected relMSE contribution (variance of the mean): {reference.relmse:.3g} "
                  f"({100 * reference.relmse / low:.0f} % of the lowest measured relMSE, {low:.3g}); "
                  f"time integral {reference.integral_relmse:.3g}",
                  f"relMSE as measured (time: {args.time}):"]
        lines += ["  " + l for l in summarize_metric(rows, args, "relmse")]
        lines.append("relMSE with the reference's contribution subtracted:")
        lines += ["  " + l for l in summarize_metric(rows, args, "relmse_corrected")]
        return lines
    lines.append(f"reference: {reference.text} (its own error unknown: included in every relMSE)")
    return lines + summarize_metric(rows, args, "relmse")


def summarize_metric(rows, args, metric):
    """Time to reach the target `metric` and equal-time ratios, as text lines."""
    curves = {}
    for r in rows:
        curves.setdefault(r["integrator"], []).append((float(r[args.time]), float(r[metric])))
    lines = []
    if any(e <= 0 for pts in curves.values() for _, e in pts):
        lines.append("(values <= 0, i.e. within the reference's error estimate, are left out)")
    # A relMSE inside every curve's measured range: each time to reach it is
    # interpolated, never a bound (a curve already below it at its cheapest
    # budget would read "<= t", which says nothing about who is faster).
    target = args.target or ec.shared_error_target(curves)
    if target:
        lines.append(f"time to reach relMSE {target:.4g}:")
        for name, pts in curves.items():
            t = ec.time_to_reach(pts, target)
            first = t is not None and t == min(s for s, _ in pts) and min(e for _, e in pts) < target
            lines.append(f"  {name}: " + ("not reached" if t is None else
                                          (f"below it already at its cheapest budget, {t:.3g} s" if first
                                           else f"{t:.3g} s")))
    else:
        lines.append("time to reach: no relMSE lies in every curve's measured range (left out)")
    for name, pts in curves.items():
        slope = ec.convergence_slope(pts)
        if slope is not None:
            lines.append(f"convergence slope of {name}: relMSE ~ time^{slope:.2f} (Monte Carlo: -1)")
    names = list(curves)
    span = ec.common_time_range(curves)
    if len(names) > 1:
        # At both ends of the common range (at the latest time the reference's
        # own noise, added to every measured error, compresses ratios most);
        # without one, at the first curve's latest time, the others
        # extrapolated with the Monte Carlo slope -1.
        times = sorted(set(span), reverse=True) if span else [max(t for t, _ in curves[names[0]])]
        for when in times:
            lines.append(f"equal-time relMSE ratio at {when:.3g} s (vs {names[0]}):")
            for name in names[1:]:
                r, extrapolated = ec.efficiency_ratio(curves[name], curves[names[0]], when)
                lines.append(f"  {name} / {names[0]}: " + (f"{r:.3g}" if r is not None else "n/a")
                             + (" (extrapolated with slope -1 beyond a curve's time range)" if extrapolated else ""))
    return lines


def main(argv):
    args = parse_args(argv)
    os.makedirs(args.out_dir, exist_ok=True)
    log = lambda s: print(s, flush=True)  # noqa: E731
    caption = machine_caption(args)
    reference = make_reference(args, log)
    rows = run_budgets(args, reference, log)
    csv_path = os.path.join(args.out_dir, "results.csv")
    with open(csv_path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=CSV_COLUMNS)
        w.writeheader()
        w.writerows(rows)
    lines = summarize(rows, args, reference)
    with open(os.path.join(args.out_dir, "summary.txt"), "w") as f:
        f.write(caption + "\n" + "\n".join(lines) + "\n")
    print("\n".join(lines))

    import plot_curves  # matplotlib only when plotting
    scene = os.path.relpath(os.path.abspath(args.scene), ROOT)
    title = args.title or scene + " " + " ".join(f"{n}={v}" for n, v in args.defines)
    plot = args.plot or os.path.join(args.out_dir, "relmse_vs_time.png")
    plot_curves.plot_error_vs_time(rows, plot, title, f"{caption}\nreference: {reference.text}", time_key=args.time,
                                   corrected_metric="relmse_corrected" if reference.relmse else None)
    print(f"wrote {csv_path}, {plot}")
    return 0


if __name__ == "__main__":
    render_runs.run_cli(main)
