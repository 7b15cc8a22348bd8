#!/usr/bin/python3
"""Is transient_beams' window sum on ToF-Tungsten's fog Cornell box port
biased, or is one render's sum just noisy? Renders the port at a small size
with several seeds and compares each render's sum over pixels, bins and
channels with the mean of two long transient_path renders (and with
ToF-Tungsten's own reference, averaged down to the same size); prints a
Markdown table and the mean ratio with its standard error over the seeds.

  tools/compare/tof_port_window_sum.py [--femto build/bin/femto] [--seeds 8]
      [--passes 4] [--spp 2] [--resolution 32] [--path-spp 4096] \
      | tools/bench/benchmarks.py set beams-port-window-sum-4    (--passes 16: ...-16)

A bias b shows as a mean ratio 1 + b whatever the seeds; noise as a spread
between seeds whose mean approaches the reference as 1 / sqrt(seeds).
"""
import argparse
import os
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "bench"))
import media_suite  # noqa: E402  (the port's scene copy, render())
from provenance import header, load_line  # noqa: E402


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--femto", default=os.path.join(media_suite.ROOT, "build", "bin", "femto"))
    p.add_argument("--seeds", type=int, default=8)
    p.add_argument("--passes", type=int, default=4)
    p.add_argument("--spp", type=int, default=2, help="camera samples per pass")
    p.add_argument("--resolution", type=int, default=32, help="a divisor of 128 (the reference is averaged down)")
    p.add_argument("--path-spp", type=int, default=4096)
    args = p.parse_args(argv)
    if not os.path.exists(os.path.join(media_suite.TOF, "reference.npy")):
        sys.exit(f"{media_suite.TOF}/reference.npy not found")
    if 128 % args.resolution:
        sys.exit("--resolution must divide 128")
    load_start = os.getloadavg()
    k = 128 // args.resolution
    tof = np.load(os.path.join(media_suite.TOF, "reference.npy")).astype(np.float64)
    tof = tof.reshape(args.resolution, k, args.resolution, k, *tof.shape[2:]).mean(axis=(1, 3))
    with tempfile.TemporaryDirectory(prefix="tof-window-sum-") as out:
        scene = media_suite.tof_scene(out)
        size = dict(resolution=args.resolution)
        path = []
        for seed in (7919, 7920):
            npy, _, _, _ = media_suite.render(args.femto, scene, os.path.join(out, f"path-{seed}.exr"),
                                              dict(size, integrator="transient_path", spp=args.path_spp), seed)
            path.append(np.load(npy).astype(np.float64).sum())
        ref = 0.5 * (path[0] + path[1])
        rows = []
        for seed in range(1, args.seeds + 1):
            defines = dict(size, integrator="transient_beams", passes=args.passes, spp=args.spp)
            npy, cpu, _, _ = media_suite.render(args.femto, scene, os.path.join(out, f"beams-{seed}.exr"), defines, seed)
            rows.append((seed, cpu, np.load(npy).astype(np.float64).sum() / ref))
    header(f"transient_beams' window sum on the ToF-Tungsten port at {args.passes} passes: bias or noise",
           "tools/compare/tof_port_window_sum.py",
           f"tools/compare/tof_port_window_sum.py --seeds {args.seeds} --passes {args.passes} "
           f"--spp {args.spp} --resolution {args.resolution} --path-spp {args.path_spp}",
           [f"reference: the mean of two transient_path renders of {args.path_spp} spp (seeds 7919, 7920); "
            f"their sums differ by {abs(path[0] / path[1] - 1) * 100:.2f} %; against ToF-Tungsten's reference.npy "
            f"averaged to {args.resolution}² it reads {ref / tof.sum():.4f}"])
    print(f"| seed | CPU s | beams window sum / path reference |")
    print("|---|---|---|")
    for seed, cpu, ratio in rows:
        print(f"| {seed} | {cpu:.1f} | {ratio:.4f} |")
    ratios = np.array([r for _, _, r in rows])
    spread = ratios.std(ddof=1) if len(ratios) > 1 else float("nan")
    print(f"\nMean over {len(ratios)} seeds: {ratios.mean():.4f} ± {spread / np.sqrt(len(ratios)):.4f} "
          f"(standard error); one render's standard deviation: {spread * 100:.1f} %.\n")
    print(load_line(load_start, os.getloadavg()))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
