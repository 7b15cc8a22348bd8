#!/usr/bin/python3
"""Issue 34 part 2: time-gated rendering. One window of a scene's time range
rendered alone (the film's window is the gate) against the same bins of a
render of the whole range, both integrators at their defaults. Prints the
"time-gating" section of docs/BENCHMARKS.md:

  tools/bench/time_gating.py [--femto build/bin/femto] [--repeats 3] [--only NAME] | tools/bench/benchmarks.py set time-gating

Scenes: the fog Cornell box (scenes/cornell-box-fog), ToF-Tungsten's fog box
(../shared/scenes/tof-tungsten-cbox-trans, when present) and the media
suite's thick medium. Windows: the first, a middle and the last 10 % of each
scene's bins. Reference: the mean of 4 transient_path renders of the whole
range with seeds no compared render uses; its own error (the variance of
the mean, from the 4 renders' spread) is subtracted from every relMSE
("corrected"), per window. relMSE = mean over the window's cells of
(x - ref)^2 / (ref^2 + 0.01 m^2), m the reference's mean over those cells.
CPU = user + system of the femto process, median of --repeats runs (seeds
1..repeats), relMSE the mean over them (and their median: transient_path's
error in fog is heavy-tailed, a few seeds' mean moves with one firefly).
Efficiency = (relMSE x CPU) of the whole range's render scored on the
window's bins over (relMSE x CPU) of the window rendered alone: how much
cheaper the window is at equal error; from the means, and from the medians.
"""
import argparse
import os
import shutil
import statistics
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import provenance  # noqa: E402
from media_suite import EPSILON, ROOT, SUITE, TOF, render, tof_scene  # noqa: E402

REF_SEEDS = (7919, 7920, 7921, 7922)


def cases(out_dir):
    fog = os.path.join(ROOT, "scenes", "cornell-box-fog", "scene.xml")
    list_ = [
        dict(name="fog box", scene=fog, start=3.0, bins=512, width=0.02,
             defines=dict(resolution=32, frames="false"),
             path=dict(spp=64), beams=dict(passes=4), reference_spp=1024),
        dict(name="thick medium", scene=os.path.join(SUITE, "thick-medium.xml"), start=3.8, bins=256, width=0.05,
             defines={}, path=dict(spp=64), beams=dict(passes=2, spp=16), reference_spp=1024),
    ]
    if os.path.exists(os.path.join(TOF, "scene.xml")):
        list_.append(dict(name="ToF-Tungsten fog box", scene=tof_scene(out_dir), start=10.0, bins=200, width=0.1,
                          defines=dict(resolution=32), path=dict(spp=64), beams=dict(passes=4, spp=2),
                          reference_spp=512))
    return list_


def windows(bins):
    """(name, first bin, bin count): the first, a middle and the last 10 %."""
    n = max(1, round(bins / 10))
    return [("first 10 %", 0, n), ("middle 10 %", (bins - n) // 2, n), ("last 10 %", bins - n, n)]


def grid(case, first, count):
    return dict(start=f"{case['start'] + first * case['width']:.6g}", bins=count, bin_width=case["width"])


def reference(femto, case, out_dir):
    """Mean of the reference renders and the variance of that mean, per cell."""
    defines = dict(case["defines"], integrator="transient_path", spp=case["reference_spp"],
                   **grid(case, 0, case["bins"]))
    vols = []
    for seed in REF_SEEDS:
        out = os.path.join(out_dir, f"ref-{seed}.exr")
        print(f"  reference seed {seed} ({case['reference_spp']} spp) ...", file=sys.stderr, flush=True)
        npy, _, _, _ = render(femto, case["scene"], out, defines, seed)
        vols.append(np.load(npy).astype(np.float64))
    vols = np.stack(vols)
    return vols.mean(axis=0), vols.var(axis=0, ddof=1) / len(vols)


def relmse(x, ref, var_ref):
    """(relMSE of x against ref, the reference's own expected share of it)."""
    m = ref.mean()
    w = 1.0 / (ref ** 2 + EPSILON * m * m)
    return float(np.mean((x - ref) ** 2 * w)), float(np.mean(var_ref * w))


def runs(femto, case, integrator, window, out_dir, repeats):
    """[(CPU s, volume)] of `repeats` seeds; window = (first, count)."""
    budget = case["path" if integrator == "transient_path" else "beams"]
    defines = dict(case["defines"], integrator=integrator, **budget, **grid(case, *window))
    result = []
    for seed in range(1, repeats + 1):
        npy, cpu, _, _ = render(femto, case["scene"], os.path.join(out_dir, "run.exr"), defines, seed)
        result.append((cpu, np.load(npy).astype(np.float64)))
    return budget, result


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--femto", default=os.path.join(ROOT, "build", "bin", "femto"))
    p.add_argument("--repeats", type=int, default=6)
    p.add_argument("--only", help="scenes whose name contains this")
    p.add_argument("--integrators", default="transient_path,transient_beams")
    args = p.parse_args(argv)
    start = os.getloadavg()
    tmp = tempfile.mkdtemp(prefix="time-gating-")
    rows = []
    try:
        for case in cases(tmp):
            if args.only and args.only not in case["name"]:
                continue
            print(f"{case['name']}:", file=sys.stderr, flush=True)
            ref, var_ref = reference(args.femto, case, tmp)
            wins = windows(case["bins"])
            for integrator in args.integrators.split(","):
                budget, full = runs(args.femto, case, integrator, (0, case["bins"]), tmp, args.repeats)
                full_cpu = statistics.median(c for c, _ in full)
                for name, first, count in wins:
                    sl = slice(first, first + count)
                    r, v = ref[:, :, sl], var_ref[:, :, sl]
                    own = relmse(r, r, v)[1]
                    full_errors = [relmse(x[:, :, sl], r, v)[0] - own for _, x in full]
                    _, alone = runs(args.femto, case, integrator, (first, count), tmp, args.repeats)
                    cpu = statistics.median(c for c, _ in alone)
                    errors = [relmse(x, r, v)[0] - own for _, x in alone]
                    e_full, e = float(np.mean(full_errors)), float(np.mean(errors))
                    m_full, m = float(np.median(full_errors)), float(np.median(errors))
                    gain = (e_full * full_cpu) / (e * cpu) if e > 0 and e_full > 0 else float("nan")
                    gain_m = (m_full * full_cpu) / (m * cpu) if m > 0 and m_full > 0 else float("nan")
                    rows.append((case["name"], integrator, budget, name, full_cpu, e_full, m_full, cpu, e, m, own, gain,
                                 gain_m))
                    print(f"  {integrator} {name}: full CPU {full_cpu:.2f} relMSE {e_full:.4g} ({m_full:.4g}); alone "
                          f"CPU {cpu:.2f} relMSE {e:.4g} ({m:.4g}) (reference's own {own:.3g}); efficiency "
                          f"{gain:.2f} ({gain_m:.2f})", file=sys.stderr, flush=True)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    provenance.header("Time-gated windows: one window alone against the whole range's bins",
                      "tools/bench/time_gating.py", "tools/bench/time_gating.py " + " ".join(argv),
                      notes=[f"defaults of each integrator (both gate by the film's window, time_gating); "
                             f"CPU the median of {args.repeats} runs, relMSE the mean (and median) over "
                             "them, corrected by the reference's own share",
                             "reference: mean of 4 transient_path renders of the whole range "
                             f"(seeds {', '.join(map(str, REF_SEEDS))})"])
    print("| scene | integrator | budget | window | whole range: CPU s | relMSE in the window, mean (median) | "
          "window alone: CPU s | relMSE, mean (median) | reference's own relMSE | efficiency, alone / whole: "
          "means (medians) |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for name, integrator, budget, win, fc, fe, fm, c, e, m, own, gain, gain_m in rows:
        b = ", ".join(f"{k} {v}" for k, v in budget.items())
        print(f"| {name} | {integrator} | {b} | {win} | {fc:.2f} | {fe:.3g} ({fm:.3g}) | {c:.2f} | {e:.3g} ({m:.3g}) | "
              f"{own:.2g} | **{gain:.2f}** ({gain_m:.2f}) |")
    print()
    print(provenance.load_line(start, os.getloadavg()))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
