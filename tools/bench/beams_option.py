#!/usr/bin/python3
"""One of transient_beams' boolean options on and off, paired on the media
suite's scenes at the suite's beams budgets: seeds 1..--seeds, CPU the
median, relMSE (eps 0.01 x mean^2) the mean over seeds against the suite's
references (independent of both renders; their own error subtracted).
Prints a section of docs/BENCHMARKS.md:

  tools/bench/beams_option.py --option time_splitting | tools/bench/benchmarks.py set beams-time-splitting
  tools/bench/beams_option.py --option stratified_photons | tools/bench/benchmarks.py set beams-stratified-photons

time_splitting: photons rouletted and split against the film's time profile
from pass 1 on, against the roulette on power alone. stratified_photons:
photons leave the emitters along scrambled (0,2)-sequences, against
independent draws. References are the media suite's, cached under
BUILD/media-suite (made on first use, as tools/bench/media_suite.py makes
them). The steady lajolla box is left out by default (--only lajolla runs it).
"""
import argparse
import contextlib
import os
import statistics
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import provenance  # noqa: E402
from media_suite import ROOT, cached_path_reference, cases, relmse, render, tof_reference  # noqa: E402


TITLES = {
    "time_splitting": "Splitting photons against time: transient_beams' time_splitting on and off",
    "stratified_photons": "Stratified photon emission: transient_beams' stratified_photons on and off",
}


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--femto", default=os.path.join(ROOT, "build", "bin", "femto"))
    p.add_argument("--option", default="time_splitting", choices=sorted(TITLES))
    p.add_argument("--seeds", type=int, default=3)
    p.add_argument("--only", default="", help="run only the scenes whose name contains this")
    args = p.parse_args(argv)
    out = os.path.join(os.path.dirname(os.path.dirname(args.femto)), "media-suite")
    os.makedirs(out, exist_ok=True)
    start = os.getloadavg()
    rows = []
    for case in cases(out, False):
        if args.only not in case["name"] or (not args.only and "lajolla" in case["name"]):
            continue
        with contextlib.redirect_stdout(sys.stderr):  # the reference's progress lines
            ref, own = (tof_reference() if case.get("reference") == "tof"
                        else cached_path_reference(args.femto, case, out))
        result = {}
        for seed in range(1, args.seeds + 1):
            for on in ("false", "true"):
                d = dict(case["defines"], integrator="transient_beams", **{args.option: on}, **case["beams"])
                npy, cpu, _, _ = render(args.femto, case["scene"], os.path.join(out, "option-run.exr"), d, seed)
                x = np.load(npy).astype(np.float64)
                result.setdefault(on, []).append((cpu, relmse(x.reshape(ref.shape), ref) - own))
        (c0, e0), (c1, e1) = [(statistics.median(c for c, _ in result[on]), float(np.mean([e for _, e in result[on]])))
                              for on in ("false", "true")]
        rows.append((case["name"], case["beams"], c0, e0, c1, e1))
        print(f"  {case['name']}: off {c0:.2f} s {e0:.4g}, on {c1:.2f} s {e1:.4g}: {c0 * e0 / (c1 * e1):.2f}x",
              file=sys.stderr, flush=True)
    provenance.header(TITLES[args.option], "tools/bench/beams_option.py", "tools/bench/beams_option.py " + " ".join(argv),
                      notes=[f"the media suite's scenes and beams budgets, on and off, seeds 1-{args.seeds}; CPU "
                             f"(user + system of the femto process, 2 threads) the median, relMSE the mean over "
                             f"seeds, the reference's own relMSE subtracted"])
    print("| scene | budget | off: CPU s | off: relMSE | on: CPU s | on: relMSE | efficiency, on / off (relMSE × CPU) |")
    print("|---|---|---|---|---|---|---|")
    for name, budget, c0, e0, c1, e1 in rows:
        b = ", ".join(f"{k} {v}" for k, v in budget.items())
        print(f"| {name} | {b} | {c0:.2f} | {e0:.4g} | {c1:.2f} | {e1:.4g} | **{c0 * e0 / (c1 * e1):.2f}** |")
    print()
    print(provenance.load_line(start, os.getloadavg()))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
