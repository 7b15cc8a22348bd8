#!/usr/bin/python3
"""transient_beams' progressive radius reduction: relMSE x CPU and window
sum against the number of passes for several `alpha` (r_{i+1} = r_i (i +
alpha) / (i + 1) for beams, so r_N ~ N^(alpha - 1)), on the media suite's
fog box (256 and 1024 bins, its path-traced references) and, when present,
ToF-Tungsten's port (its own reference, 1 camera sample per pass as the
peer ran). Prints a Markdown table; medians over --seeds seeds.

  tools/bench/beams_alpha.py [--femto build/bin/femto] [--alphas 0.7,0.8,0.9]
      [--passes 8] [--seeds 2] [--out build/beams-alpha] | tools/bench/benchmarks.py set beams-alpha
  (--alphas 0.7,0.9 --passes 64 --seeds 1: set beams-alpha-64)

Why it matters: with a 1D kernel a pass's variance grows as 1 / r_i, so the
mean of N passes has variance ~ N^(-alpha) and relMSE x CPU grows as
N^(1 - alpha); the kernel's interior bias falls as r_N^2 ~ N^(2 (alpha - 1)),
a boundary's as r_N. Balancing squared bias and variance gives alpha = 4/5
for the interior and 2/3 where the boundary term dominates.
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import media_suite  # noqa: E402
from provenance import header, load_line  # noqa: E402


def measure(femto, case, ref, own, alpha, passes, seeds, out, extra):
    products, errors, cpus, sums = [], [], [], []
    for seed in range(1, seeds + 1):
        defines = dict(case["defines"], integrator="transient_beams", passes=passes, alpha=alpha, **extra)
        file = os.path.join(out, f"{media_suite.slug(case['name'])}-a{alpha}-p{passes}-{seed}.exr")
        npy, cpu, _, _ = media_suite.render(femto, case["scene"], file, defines, seed)
        x = np.load(npy).astype(np.float64)
        e = media_suite.relmse(x, ref) - own
        products.append(e * cpu), errors.append(e), cpus.append(cpu), sums.append(x.sum() / ref.sum())
    return float(np.median(cpus)), float(np.median(errors)), float(np.median(products)), sums


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--femto", default=os.path.join(media_suite.ROOT, "build", "bin", "femto"))
    p.add_argument("--alphas", default="0.7,0.8,0.9")
    p.add_argument("--passes", default="8")
    p.add_argument("--seeds", type=int, default=2)
    p.add_argument("--out", default=os.path.join(media_suite.ROOT, "build", "beams-alpha"))
    args = p.parse_args(argv)
    os.makedirs(args.out, exist_ok=True)
    load_start = os.getloadavg()
    alphas = [float(a) for a in args.alphas.split(",")]
    passes = [int(n) for n in args.passes.split(",")]
    cases = [c for c in media_suite.cases(args.out, False) if c["name"].startswith("fog box")]
    rows = []
    for case in cases:
        ref, own = media_suite.cached_path_reference(femto=args.femto, case=case, out_dir=args.out)
        for n in passes:
            for alpha in alphas:
                rows.append((case["name"], n, alpha, *measure(args.femto, case, ref, own, alpha, n, args.seeds,
                                                             args.out, {})))
    if os.path.exists(os.path.join(media_suite.TOF, "reference.npy")):
        scene = media_suite.tof_scene(args.out)
        # The suite's integrator file leaves alpha to the integrator: this copy takes -D alpha.
        integrator = os.path.join(os.path.dirname(scene), "integrator-transient_beams.xml")
        text = open(integrator).read()
        if "$alpha" not in text:
            text = text.replace('<integrator type="transient_beams">',
                                '<integrator type="transient_beams">\n    <float name="alpha" value="$alpha"/>')
            open(integrator, "w").write(text)
        port = dict(name="ToF-Tungsten port (128², 1 spp per pass)", scene=scene, defines=dict(spp=1))
        ref = np.load(os.path.join(media_suite.TOF, "reference.npy")).astype(np.float64)
        for n in passes:
            for alpha in alphas:
                rows.append((port["name"], n, alpha, *measure(args.femto, port, ref, 0.0, alpha, n, args.seeds,
                                                             args.out, {})))
    header(f"transient_beams: the radius reduction alpha at {args.passes} passes", "tools/bench/beams_alpha.py",
           f"tools/bench/beams_alpha.py {' '.join(argv)}",
           [f"medians over seeds 1-{args.seeds}; CPU = user + system seconds of the femto process; relMSE as the "
            "media suite's (fog box: its path-traced reference's own error subtracted)"])
    print("| scene | passes | alpha | CPU s | relMSE | relMSE × CPU | window sum / ref (each seed) |")
    print("|---|---|---|---|---|---|---|")
    for name, n, alpha, cpu, e, product, sums in rows:
        print(f"| {name} | {n} | {alpha} | {cpu:.1f} | {e:.3g} | {product:.3g} | "
              f"{' / '.join(f'{s:.3f}' for s in sums)} |")
    print("\n" + load_line(load_start, os.getloadavg()))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
