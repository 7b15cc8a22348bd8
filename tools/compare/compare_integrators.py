#!/usr/bin/python3
"""`femto compare SCENE.xml -i A -i B`: integrators on one scene at equal CPU
budgets. Each integrator renders the scene with `femto render --time-limit B
--time-clock cpu` for every budget B of a ladder; each render is compared with
a reference (given, or a longer render cached under
${XDG_CACHE_HOME:-~/.cache}/femto/compare); the table gives per budget each
integrator's CPU seconds, relMSE and relMSE x CPU, and the equal-CPU
efficiency ratio of every integrator against the first: relMSE_first(t) /
relMSE_other(t) at equal CPU time t, interpolated on log-log between budgets
and, beyond the CPU range an integrator reached, extrapolated with the Monte
Carlo slope -1 (said so by a mark). Also a CSV and a log-log plot. See
docs/compare.md. The CLI front (tools/femto/main.cpp) runs this script with
--femto set to itself.
"""
import argparse
import csv
import datetime
import hashlib
import json
import math
import os
import platform
import re
import shutil
import subprocess
import sys
import textwrap

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import error_curves as ec  # noqa: E402
import render_runs  # noqa: E402

REFERENCE_SEEDS = (7919, 7920)  # the reference's two halves; the budget renders use --seed (default 1)
EPSILON = 0.01  # femto compare's relMSE epsilon (docs/compare.md)
PASSES_LINE = re.compile(r"^(\d+) passes of (\d+) spp \((\d+) spp\), rendering ([0-9.]+) s, ([0-9.]+) s CPU", re.M)


class UsageError(ValueError):
    """A bad command line: one sentence, exit 2."""


def parse_duration(text):
    """'30s', '5m', '1.5h' or '90' (seconds) -> seconds, as femto render --time-limit reads them."""
    m = re.fullmatch(r"([0-9]*\.?[0-9]+)(s|m|min|h)?", text.strip())
    if not m or float(m.group(1)) <= 0:
        raise UsageError(f"expected a duration > 0 such as 30s, 5m or 90 (seconds), got {text!r}")
    return float(m.group(1)) * {None: 1, "s": 1, "m": 60, "min": 60, "h": 3600}[m.group(2)]


class Integrator:
    """One -i: its label in the table, the -D defines and the other femto
    render arguments of its renders."""

    def __init__(self, spec, name, defines, args=()):
        self.spec, self.label, self.defines, self.args = spec, name, list(defines), list(args)


def parse_integrator(text):
    """'transient_beams' or 'transient_beams,photon_count=100000,spp=4': -D
    integrator=NAME plus those -D for this integrator's renders only (the scene
    needs <default name="integrator">). 'FILE.xml[,name=value...]': an
    integrator file, rendered with `femto render --integrator FILE.xml`."""
    name, *rest = text.split(",")
    defines = []
    for item in rest:
        key, sep, value = item.partition("=")
        if not sep or not key:
            raise UsageError(f"-i {text!r}: {item!r} is not name=value")
        defines.append((key, value))
    if name.endswith(".xml"):
        if not os.path.isfile(name):
            raise UsageError(f"-i {text!r}: no such integrator file {name!r}")
        return Integrator(text, os.path.splitext(os.path.basename(name))[0], defines,
                          ["--integrator", os.path.abspath(name)])
    if not re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]*", name):
        raise UsageError(f"-i expects an integrator name or an integrator file (.xml), with optional ,name=value "
                         f"defines (e.g. transient_beams,photon_count=100000), got {text!r}")
    return Integrator(text, name, [("integrator", name)] + defines)


def default_cache_dir():
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return os.path.join(base, "femto", "compare")


def parse_args(argv):
    p = argparse.ArgumentParser(
        prog="femto compare SCENE.xml",
        description="Compare integrators on a scene at equal CPU budgets: relMSE against a reference, "
                    "relMSE x CPU and the equal-CPU efficiency ratio (docs/compare.md).",
        epilog="example: femto compare scenes/cornell-box-fog/scene.xml -i transient_path -i transient_beams "
               "-D resolution=64 -D bins=256 -D bin_width=0.04 -D frames=false")
    p.add_argument("scene", help="the scene (for -i NAME it needs <default name=\"integrator\">)")
    p.add_argument("-i", "--integrator", action="append", default=[], metavar="NAME|FILE.xml[,name=value...]",
                   help="an integrator to compare (2 or more; the first is the baseline of the ratios): a name, "
                        "set with -D integrator=NAME, or an integrator file (femto render --integrator); "
                        "name=value after it are -D defines for its renders only")
    p.add_argument("-D", "--define", action="append", default=[], metavar="NAME=VALUE",
                   help="scene override for every render, the reference's too")
    p.add_argument("--budgets", default="1,2,4,8", metavar="B1,B2,...",
                   help="CPU time budgets of the renders (durations: 2, 2s, 1m; default 1,2,4,8 seconds)")
    p.add_argument("--reference", metavar="FILE", help="compare against this file (.npy volume or image) "
                   "instead of rendering a reference")
    p.add_argument("--reference-integrator", metavar="NAME[,name=value...]",
                   help="integrator of the rendered reference (default: the first -i)")
    p.add_argument("--reference-time", metavar="DURATION",
                   help="CPU time of the rendered reference, two halves with seeds 7919 and 7920 "
                        "(default: 8 x the largest budget)")
    p.add_argument("--bands", type=int, default=0, metavar="K",
                   help="also the relMSE of K arrival bands (K >= 2): the bins split where 1/K, 2/K, ... of the "
                        "reference's light has arrived (2: early and late light)")
    p.add_argument("--seed", type=int, default=1, help="seed of the budget renders (default 1)")
    p.add_argument("-t", "--threads", type=int, default=0, help="femto render -t (default: all cores)")
    p.add_argument("-o", "--out-dir", help="where the table, CSV and plot go (default: compare-<scene name>, "
                                            "or compare-<folder> for a scene.xml)")
    p.add_argument("--cache-dir", default=default_cache_dir(),
                   help="where rendered references are kept (default: ${XDG_CACHE_HOME:-~/.cache}/femto/compare)")
    p.add_argument("--keep-renders", action="store_true", help="keep the budget renders (default: deleted once measured)")
    p.add_argument("--femto", default=shutil.which("femto") or "femto", help="the femto program (set by `femto compare`)")
    args = p.parse_args(argv)
    try:
        if len(args.integrator) < 2:
            raise UsageError("give two or more integrators to compare: -i NAME -i NAME ...")
        args.integrators = [parse_integrator(s) for s in args.integrator]
        if len({i.spec for i in args.integrators}) != len(args.integrators):
            raise UsageError("an integrator is given twice")
        # The table's names: the integrator's, or its whole -i text where two share one.
        names = [i.label for i in args.integrators]
        for i in args.integrators:
            if names.count(i.label) > 1:
                i.label = i.spec
        args.defines = [ec.parse_define(d) for d in args.define]
        args.budget_list = sorted({parse_duration(b) for b in args.budgets.split(",") if b.strip()})
        if not args.budget_list:
            raise UsageError("--budgets needs at least one duration")
        args.reference_spec = parse_integrator(args.reference_integrator) if args.reference_integrator \
            else args.integrators[0]
        args.reference_seconds = parse_duration(args.reference_time) if args.reference_time \
            else 8 * args.budget_list[-1]
        if args.bands == 1 or args.bands < 0:
            raise UsageError("--bands needs K >= 2 (or 0 for none)")
        if args.seed in REFERENCE_SEEDS:
            raise UsageError(f"--seed must differ from the reference's seeds {REFERENCE_SEEDS}")
        if args.threads < 0:
            raise UsageError("--threads must be >= 1")
        scene_text = open(args.scene, encoding="utf-8", errors="replace").read()
    except (UsageError, ec.SpecError) as e:
        p.error(str(e))
    except OSError as e:
        p.error(f"cannot read the scene: {e}")
    by_name = [i for i in args.integrators + [args.reference_spec] if not i.args]
    if by_name and not re.search(r'<default\s+name="integrator"', scene_text):
        p.error(f'{args.scene} has no <default name="integrator">: -i NAME renders it with -D integrator=NAME, '
                f'which would change nothing (see scenes/cornell-box-fog/scene.xml: '
                f'<include filename="integrator-$integrator.xml"/>)')
    # compare-<scene name>, or compare-<its folder> for a scene.xml (as in scenes/).
    stem = os.path.splitext(os.path.basename(args.scene))[0]
    if stem == "scene":
        stem = os.path.basename(os.path.dirname(os.path.abspath(args.scene))) or stem
    args.out_dir = args.out_dir or "compare-" + stem
    return args


def femto_version(femto):
    r = subprocess.run([femto, "--version"], stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    return r.stdout.strip() or "femto (unknown version)"


def machine_caption(args, version):
    """Machine, load, femto version and date: the context any timing needs."""
    cpu = platform.processor() or "unknown CPU"
    try:
        with open("/proc/cpuinfo") as f:
            cpu = next(l.split(":", 1)[1].strip() for l in f if l.startswith("model name"))
    except (OSError, StopIteration):
        pass
    load = " ".join(open("/proc/loadavg").read().split()[:3]) if os.path.exists("/proc/loadavg") else "?"
    date = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    threads = args.threads or os.cpu_count()
    try:  # an installed femto, or a machine without git: no commit in the caption
        commit = subprocess.run(["git", "-C", os.path.dirname(os.path.abspath(__file__)), "rev-parse", "--short", "HEAD"],
                                stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True).stdout.strip()
    except OSError:
        commit = ""
    return (f"{cpu}, {threads} threads, {os.cpu_count()} cores; load average {load}; {version}"
            + (f" (commit {commit})" if commit else "") + f"; {date}")


def render_budget(args, out, integrator, seconds, seed):
    """One time-limited render: (femto's summary numbers, the file to compare)."""
    cmd = integrator.args + ["--time-limit", f"{seconds:g}", "--time-clock", "cpu"]
    r = render_runs.render(args.femto, args.scene, out, list(args.defines) + integrator.defines, seed, args.threads,
                           extra=cmd)
    m = PASSES_LINE.search(r.stdout)
    if not m:
        raise render_runs.RunError(f"femto render printed no 'N passes of K spp' line for {out}:\n{r.stdout}")
    return dict(passes=int(m.group(1)), spp_per_pass=int(m.group(2)), render_seconds=float(m.group(4)),
                cpu=float(m.group(5)), wall=r.wall_seconds), r.file


def scene_digest(scene):
    """The scene's XML and that of every .xml beside it (the files it may
    include, e.g. integrator-$integrator.xml): a changed file renders anew."""
    h = hashlib.sha256()
    folder = os.path.dirname(os.path.abspath(scene))
    for name in sorted(os.listdir(folder)):
        if name.endswith(".xml"):
            h.update(name.encode())
            with open(os.path.join(folder, name), "rb") as f:
                h.update(f.read())
    with open(scene, "rb") as f:
        h.update(f.read())
    return h.hexdigest()


class Reference:
    """The file every render is compared with; its own expected relMSE (total
    and per bin; None when unknown) and a description."""

    def __init__(self, path, text, relmse=None, per_bin=None):
        self.path, self.text, self.relmse, self.per_bin = path, text, relmse, per_bin


def make_reference(args, version, log):
    if args.reference:
        return Reference(args.reference, f"{args.reference} (given; its own error unknown, included in every relMSE)")
    ref = args.reference_spec
    label = ref.spec
    half = args.reference_seconds / 2
    files_hash = [scene_digest(a) for a in ref.args if a.endswith(".xml")]  # an integrator file's content
    spec = dict(scene=scene_digest(args.scene), scene_file=os.path.abspath(args.scene), defines=sorted(args.defines),
                integrator=label, integrator_files=files_hash, cpu_seconds_each=half, seeds=list(REFERENCE_SEEDS),
                femto=version)
    key = hashlib.sha256(json.dumps(spec, sort_keys=True).encode()).hexdigest()[:16]
    folder = os.path.join(args.cache_dir, key)
    meta_path = os.path.join(folder, "meta.json")
    text = (f"{label}, 2 x {half:g} s CPU (seeds {REFERENCE_SEEDS[0]}, {REFERENCE_SEEDS[1]}), "
            f"cached in {folder}")
    if os.path.exists(meta_path):
        with open(meta_path) as f:
            meta = json.load(f)
        path = os.path.join(folder, meta["file"])
        if os.path.exists(path):
            log(f"reference: cached ({text})")
            return Reference(path, text, meta.get("relmse"), meta.get("per_bin"))
    os.makedirs(folder, exist_ok=True)
    log(f"reference: rendering {label} for 2 x {half:g} s CPU into {folder} ...")
    files, runs = [], []
    for seed in REFERENCE_SEEDS:
        run, path = render_budget(args, os.path.join(folder, f"half{seed}.exr"), ref, half, seed)
        files.append(path)
        runs.append(run)
    meta = dict(spec, runs=runs)
    if all(f.endswith(".npy") for f in files):
        import reference_volume  # numpy only when averaging volumes
        estimate = reference_volume.mean_and_error(files, os.path.join(folder, "reference.tmp.npy"), EPSILON,
                                                   per_bin=True)
        os.replace(os.path.join(folder, "reference.tmp.npy"), os.path.join(folder, "reference.npy"))
        shutil.copy(os.path.splitext(files[0])[0] + ".json", os.path.join(folder, "reference.json"))
        for f in files:
            os.remove(f)
        meta.update(file="reference.npy", relmse=estimate[1], per_bin=estimate["per_bin"])
    else:
        # A steady image: the first half alone (no mean of images without
        # an image reader here), its own error unknown.
        meta.update(file=os.path.basename(files[0]))
    with open(meta_path, "w") as f:
        json.dump(meta, f)
    log(f"reference: done ({sum(r['cpu'] for r in runs):.1f} s CPU)")
    return Reference(os.path.join(folder, meta["file"]), text, meta.get("relmse"), meta.get("per_bin"))


def arrival_bands(reference_path, k):
    """K bands of bins [(first, end), ...]: band j holds the bins where the
    reference's light arrived between j/K and (j+1)/K of its total (summed
    over pixels and channels)."""
    import numpy as np
    vol = np.load(reference_path, mmap_mode="r")
    energy = np.zeros(vol.shape[2])
    for y in range(0, vol.shape[0], 16):
        energy += np.asarray(vol[y:y + 16], dtype=np.float64).sum(axis=(0, 1, 3))
    return ec.split_bins_by_share(energy.tolist(), k)


def measure(args, reference, bands, log):
    """Render every integrator at every budget; one row per render."""
    rows = []
    renders = os.path.join(args.out_dir, "renders")
    for integrator in args.integrators:
        label = integrator.label
        for budget in args.budget_list:
            stem = re.sub(r"[^A-Za-z0-9_.=-]", "_", os.path.basename(label))
            out = os.path.join(renders, f"{stem}_{budget:g}s.exr")
            run, path = render_budget(args, out, integrator, budget, args.seed)
            report = render_runs.compare(args.femto, reference.path, path)
            measured = report["metrics"]["relmse"]
            row = dict(integrator=label, budget=budget, cpu_seconds=run["cpu"], wall_seconds=round(run["wall"], 3),
                       passes=run["passes"], spp_per_pass=run["spp_per_pass"], relmse_measured=measured,
                       relmse=net_relmse(measured, reference.relmse))
            per_bin = report.get("per_bin", {}).get("relmse")
            for j, (first, end) in enumerate(bands):
                band = sum(per_bin[first:end]) / (end - first)
                own = sum(reference.per_bin[first:end]) / (end - first) if reference.per_bin else None
                row[f"band{j}_relmse"] = net_relmse(band, own)
            rows.append(row)
            log(f"{label} at {budget:g} s: {run['passes']} passes of {run['spp_per_pass']} spp, "
                f"{run['cpu']:.2f} s CPU, relMSE {row['relmse']:.4g}")
            if budget == args.budget_list[0] and run["passes"] == 1 and run["cpu"] > 1.5 * budget:
                log(f"note: one pass of {label} took {run['cpu']:.2f} s CPU, above the {budget:g} s budget: its "
                    f"points sit at whole passes; fewer samples per pass (-i {label},spp=N) give a finer ladder")
            if not args.keep_renders:
                for f in os.listdir(renders):
                    if f.startswith(f"{stem}_{budget:g}s"):
                        p = os.path.join(renders, f)
                        shutil.rmtree(p) if os.path.isdir(p) else os.remove(p)
    if not args.keep_renders:
        shutil.rmtree(renders, ignore_errors=True)
    return rows


def net_relmse(measured, reference_own):
    """The relMSE with the reference's own expected contribution subtracted
    (errors of independent renders add), when it is known and smaller."""
    if reference_own is None or not measured > reference_own:
        return measured
    return measured - reference_own


def curves_of(rows, key="relmse"):
    curves = {}
    for r in rows:
        curves.setdefault(r["integrator"], []).append((float(r["cpu_seconds"]), float(r[key])))
    return curves


# Beyond a curve's CPU range by more than this factor, a ratio is marked extrapolated.
SLACK = 1.05


def fmt_ratio(ratio, extrapolated):
    if ratio is None:
        return "n/a"
    return f"{ratio:.2f}x" + ("*" if extrapolated else "")


def band_times(rows, args):
    """Per budget, the geometric mean of the CPU seconds its renders took."""
    times = []
    for budget in args.budget_list:
        cpu = [r["cpu_seconds"] for r in rows if r["budget"] == budget]
        times.append(math.exp(sum(math.log(c) for c in cpu) / len(cpu)))
    return times


def report(args, rows, reference, bands, band_names, caption):
    """The table and the ratios as text lines."""
    labels = [i.label for i in args.integrators]
    base = labels[0]
    curves = curves_of(rows)
    any_extrapolated = False
    lines = [caption, f"scene: {args.scene} " + " ".join(f"-D {n}={v}" for n, v in args.defines)]
    lines += [f"{i.label}: -i {i.spec}" for i in args.integrators if i.spec != i.label]
    lines.append(f"reference: {reference.text}")
    if reference.relmse is not None:
        low = min(r["relmse_measured"] for r in rows)
        lines.append(f"  its own relMSE, estimated from its two halves: {reference.relmse:.3g} "
                     f"({100 * reference.relmse / low:.0f} % of the smallest measured); subtracted below")
    lines.append("")
    header = ["budget"]
    for label in labels:
        header += [f"{label}: CPU s", "relMSE", "relMSE x CPU"]
    header += [f"{label} / {base}" for label in labels[1:]]
    table = [header]
    ratios = {label: [] for label in labels[1:]}
    for budget in args.budget_list:
        row = {r["integrator"]: r for r in rows if r["budget"] == budget}
        # Each row's ratio at the geometric mean of the CPU its renders took
        # (whole passes end near, not at, the budget): inside both curves.
        at = math.exp(sum(math.log(row[label]["cpu_seconds"]) for label in labels) / len(labels))
        cells = [f"{budget:g} s"]
        for label in labels:
            r = row[label]
            cells += [f"{r['cpu_seconds']:.2f}", f"{r['relmse']:.4g}", f"{r['relmse'] * r['cpu_seconds']:.4g}"]
        for label in labels[1:]:
            ratio, extra = ec.efficiency_ratio(curves[base], curves[label], at, SLACK)
            any_extrapolated |= extra
            cells.append(fmt_ratio(ratio, extra))
            if ratio is not None:
                ratios[label].append((ratio, extra))
        table.append(cells)
    widths = [max(len(row[i]) for row in table) for i in range(len(header))]
    lines += ["  ".join(c.rjust(w) for c, w in zip(row, widths)) for row in table]
    lines.append("")
    lines.append(f"equal-CPU efficiency ratio, relMSE of {base} / relMSE of the other at equal CPU time "
                 f"(above 1: the other is more efficient; the geometric mean over the budgets):")
    for label in labels[1:]:
        r = [x for x, _ in ratios[label]]
        mean = math.exp(sum(math.log(x) for x in r) / len(r)) if r else None
        lines.append(f"  {label}: {fmt_ratio(mean, any(x for _, x in ratios[label]))}"
                     + (f" ({min(r):.2f}x to {max(r):.2f}x over the budgets)" if len(r) > 1 else ""))
    for j, name in enumerate(band_names):
        band_curves = curves_of(rows, f"band{j}_relmse")
        first, end = bands[j]
        cells = []
        for label in labels[1:]:
            found = [ec.efficiency_ratio(band_curves[base], band_curves[label], t, SLACK) for t in band_times(rows, args)]
            r = [x for x, _ in found if x is not None]
            extra = any(x for _, x in found)
            any_extrapolated |= extra
            mean = math.exp(sum(math.log(x) for x in r) / len(r)) if r else None
            cells.append(f"{label} {fmt_ratio(mean, extra)}")
        lines.append(f"  {name} light only (bins {first}:{end}): " + ", ".join(cells))
    if reference.relmse is not None:
        top = [r for r in rows if r["budget"] == args.budget_list[-1]]
        for r in top:
            share = reference.relmse / r["relmse_measured"]
            if share > 0.2:
                lines.append(f"note: at {r['budget']:g} s the reference's own error is {100 * share:.0f} % of the "
                             f"relMSE measured for {r['integrator']} (subtracted, as an estimate): a longer reference "
                             f"(--reference-time) makes the largest budgets' ratios firmer")
    reach = ec.shared_error_target(curves)
    if reach:
        times = ", ".join(f"{label} {ec.time_to_reach(curves[label], reach):.3g} s" for label in labels)
        lines.append(f"CPU time to reach relMSE {reach:.3g} (an error every integrator reached): {times}")
    if any_extrapolated:
        lines.append("* extrapolated with the Monte Carlo slope -1 (relMSE ~ 1/CPU) beyond the CPU range measured")
    return lines


def plot(args, rows, band_names, caption, reference, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import matplotlib.ticker
    fig, ax = plt.subplots(figsize=(7.0, 4.8), dpi=100)
    labels = [i.label for i in args.integrators]
    for label in labels:
        pts = sorted((r["cpu_seconds"], r["relmse"]) for r in rows if r["integrator"] == label)
        line, = ax.loglog([p[0] for p in pts], [p[1] for p in pts], "o-", label=label)
        for j, name in enumerate(band_names):
            band = sorted((r["cpu_seconds"], r[f"band{j}_relmse"]) for r in rows if r["integrator"] == label)
            ax.loglog([p[0] for p in band], [p[1] for p in band], "--", color=line.get_color(), alpha=0.35 + 0.5 * j / max(len(band_names) - 1, 1), linewidth=1,
                      label=f"{label}, {name} light")
    base = sorted((r["cpu_seconds"], r["relmse"]) for r in rows if r["integrator"] == labels[0])
    (t0, e0), t1 = base[0], base[-1][0]
    ax.loglog([t0, t1], [e0, e0 * t0 / t1], ":", color="0.5", linewidth=1, label="slope -1 (Monte Carlo)")
    ax.set_xlabel("CPU time of the render, all threads (s)")
    ax.xaxis.set_major_formatter(matplotlib.ticker.FormatStrFormatter("%g"))
    ax.xaxis.set_minor_formatter(matplotlib.ticker.FormatStrFormatter("%g"))
    ax.tick_params(axis="x", which="minor", labelsize=7)
    ax.set_ylabel("relMSE" + (" (reference's own subtracted)" if reference.relmse is not None else ""))
    scene = os.path.basename(os.path.dirname(os.path.abspath(args.scene))) + "/" + os.path.basename(args.scene)
    title = f"{scene}: relMSE vs CPU time " + " ".join(f"{n}={v}" for n, v in args.defines)
    ax.set_title("\n".join(textwrap.wrap(title, 70)), fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
    foot = "\n".join(textwrap.wrap(caption, 130) + textwrap.wrap("reference: " + reference.text, 130))
    fig.text(0.01, 0.01, foot, fontsize=6, va="bottom", ha="left")
    fig.tight_layout(rect=(0, 0.03 + 0.022 * foot.count("\n"), 1, 1))
    fig.savefig(path)
    plt.close(fig)


def main(argv):
    args = parse_args(argv)
    os.makedirs(args.out_dir, exist_ok=True)
    log = lambda s: print(s, file=sys.stderr, flush=True)  # noqa: E731
    version = femto_version(args.femto)
    caption = machine_caption(args, version)
    reference = make_reference(args, version, log)
    bands, band_names = [], []
    if args.bands:
        if not reference.path.endswith(".npy"):
            raise UsageError("--bands needs a transient volume (.npy) as the reference")
        bands = arrival_bands(reference.path, args.bands)
        band_names = ["early", "late"] if args.bands == 2 else [f"band {j + 1}/{args.bands}" for j in range(args.bands)]
    rows = measure(args, reference, bands, log)
    csv_path = os.path.join(args.out_dir, "results.csv")
    with open(csv_path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    lines = report(args, rows, reference, bands, band_names, caption)
    png = os.path.join(args.out_dir, "relmse_vs_cpu.png")
    try:
        plot(args, rows, band_names, caption, reference, png)
    except ImportError:
        png = None
        lines.append("(no plot: matplotlib is missing; apt-get install python3-matplotlib)")
    table_path = os.path.join(args.out_dir, "table.txt")
    with open(table_path, "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))
    print(f"wrote {table_path}, {csv_path}" + (f", {png}" if png else ""))
    return 0


if __name__ == "__main__":
    try:
        render_runs.run_cli(main)
    except UsageError as e:
        sys.exit(f"error: {e}")
