#!/usr/bin/python3
"""Russian roulette along camera segments' gathers (transient_beams'
gather_roulette, beam_roulette.h): what it saves and what it costs, per
arrival band, on the media suite's scenes where camera segments are long in
mean free paths. Writes the "gather-roulette" section of docs/BENCHMARKS.md.

  tools/bench/gather_roulette.py [--femto build/bin/femto] [--out build/media-suite] [--seeds 3] \
      | tools/bench/benchmarks.py set gather-roulette

Per scene and gather_roulette value (0: gathers reach the segment's end; the
default 0.05; the beams' 0.25): renders with seeds 1..N, CPU the median of
their CPU times, relMSE (epsilon = 0.01) the mean over the seeds against the
media suite's reference (cached there) with the reference's own error
subtracted, and relMSE per arrival band: the film's bins grouped by the share
of the reference's light arrived by then (first 1 %, 1-10 %, 10-90 %, last
10 %), each band's relMSE with epsilon relative to that band's own mean, so
a band of dim early bins counts as much as a bright one (the path-traced
references' own error is not subtracted per band: it adds the same to every
row).
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import media_suite  # noqa: E402
import provenance  # noqa: E402

VALUES = (0.0, 0.05, 0.25)
BANDS = (("first 1 %", 0.0, 0.01), ("1-10 %", 0.01, 0.1), ("10-90 %", 0.1, 0.9), ("last 10 %", 0.9, 1.01))
SCENES = ("thick medium, 1024 bins", "large medium", "ToF-Tungsten port")


def band_masks(ref):
    profile = ref.sum(axis=(0, 1, 3))
    arrived = np.cumsum(profile) / max(profile.sum(), 1e-300)
    return [(name, (arrived > lo) & (arrived <= hi)) for name, lo, hi in BANDS]


def band_relmse(x, ref, mask):
    xs, rs = x[:, :, mask, :], ref[:, :, mask, :]
    if rs.size == 0:
        return float("nan")
    m = rs.mean()
    return float(np.mean((xs - rs) ** 2 / (rs ** 2 + media_suite.EPSILON * m * m)))


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--femto", default=os.path.join(media_suite.ROOT, "build", "bin", "femto"))
    p.add_argument("--out", default=os.path.join(media_suite.ROOT, "build", "media-suite"))
    p.add_argument("--seeds", type=int, default=3)
    p.add_argument("--only", help="run only the scenes whose name contains this")
    args = p.parse_args(argv)
    os.makedirs(args.out, exist_ok=True)
    start = os.getloadavg()
    lines = []
    for case in media_suite.cases(args.out, quick=False):
        if case["name"] not in SCENES or (args.only and args.only not in case["name"]):
            continue
        print(f"{case['name']}:", file=sys.stderr, flush=True)
        if case.get("reference") == "tof":
            ref, own = media_suite.tof_reference()
        else:
            ref, own = media_suite.cached_path_reference(femto=args.femto, case=case, out_dir=args.out)
        masks = band_masks(ref)
        rows = []
        for value in VALUES:
            defines = dict(case["defines"], integrator="transient_beams", gather_roulette=value, **case["beams"])
            out = os.path.join(args.out, f"gather-roulette-{media_suite.slug(case['name'])}.exr")
            cpus, errors, bands, candidates = [], [], [], []
            for seed in range(1, args.seeds + 1):
                npy, cpu, _, log = media_suite.render(args.femto, case["scene"], out, defines, seed)
                x = np.load(npy).astype(np.float64)
                cpus.append(cpu)
                errors.append(max(media_suite.relmse(x, ref) - own, 0.0))
                bands.append([band_relmse(x, ref, m) for _, m in masks])
                stats = media_suite.STATS.search(log)
                candidates.append(float(stats.group(1)) if stats else 0.0)
            cpu, error = float(np.median(cpus)), float(np.mean(errors))
            rows.append((value, cpu, error, np.mean(bands, axis=0), float(np.mean(candidates))))
            print(f"  gather_roulette {value}: CPU {cpu:.1f} s relMSE {error:.4g}", file=sys.stderr, flush=True)
        base = rows[0][1] * rows[0][2]
        lines.append(f"### {case['name']}\n")
        lines.append("| gather_roulette | CPU s | candidates / query | relMSE | relMSE × CPU | efficiency vs 0 | " +
                     " | ".join(f"relMSE, {name} of the light" for name, _ in masks) + " |")
        lines.append("|---|---|---|---|---|---|" + "---|" * len(masks))
        for value, cpu, error, band, cand in rows:
            label = f"{value:g}" + (" (default)" if value == 0.05 else "") + (" (off)" if value == 0.0 else "")
            lines.append(f"| {label} | {cpu:.1f} | {cand:.0f} | {error:.3g} | {cpu * error:.3g} | "
                         f"{base / max(cpu * error, 1e-30):.2f} | " + " | ".join(f"{b:.3g}" for b in band) + " |")
        lines.append("")
    end = os.getloadavg()
    provenance.header(
        "transient_beams: Russian roulette along camera segments' gathers",
        "tools/bench/gather_roulette.py", f"tools/bench/gather_roulette.py --seeds {args.seeds}",
        notes=[f"Seeds 1-{args.seeds} per row: CPU the median, relMSE the mean (ε = 0.01, the reference's own error "
               "subtracted); bands: the film's bins grouped by the share of the reference's light arrived, each band's "
               "relMSE with ε relative to its own mean. Budgets and references: the media suite's (docs/BENCHMARKS.md, "
               "\"Media suite\"). Efficiency vs 0: relMSE × CPU with gathers to the segment's end over the row's (> 1: "
               "the row is better)."])
    print("\n".join(lines) + "\n" + provenance.load_line(start, end))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
