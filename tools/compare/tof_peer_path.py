#!/usr/bin/python3
"""femto's transient_path on ToF-Tungsten's transient fog Cornell box
(../shared/scenes/tof-tungsten-cbox-trans, its README), by medium-vertex
strategy, scored two ways; prints the Markdown of docs/BENCHMARKS.md's
"transient_path on the peer's scene" section.

  tools/compare/tof_peer_path.py --only 1 | tools/bench/benchmarks.py set path-peer
  tools/compare/tof_peer_path.py --only 2 [--protocol-resolution 32] \
      | tools/bench/benchmarks.py set path-peer-protocols

Strategies (transient_path's parameters): free flights only (equiangular and
light_directions false: what ToF-Tungsten's path tracer does), equiangular
vertices (light_directions false: femto before issue 15's fix), and
equiangular plus light-directed vertices (the default).

(1) At the peer's 128x128, against its 8192-spp reference.npy with the
    README's relMSE (epsilon 0.01): CPU s, relMSE, relMSE x CPU and the error
    share of the worst 1 % and worst 100 cells, beside the peer's own figures.
(2) The reference protocol, at a small resolution: the peer's reference is
    its own 8192-spp render, and its shorter renders repeat that render's
    first samples (Tungsten seeds each pixel once; femto seeds each sample from
    (seed, pixel, index), so a femto render with the reference's seed does the
    same). Each strategy is scored against (i) its own 8192-spp render with
    the same seed, the peer's protocol, and (ii) an independent reference: the
    mean of two 8192-spp renders of the default strategy with other seeds,
    whose own error (from their difference) is subtracted. Under (i) a sample
    shared with the reference can contribute at most (N_ref/N - 1)^2 to its
    cell's relative squared error (49 at 1024 of 8192 spp), however large.

CPU = user + system seconds of the femto process (loading, rendering,
writing), one run each: the machine is shared, so the figures carry its load.
"""
import argparse
import os
import resource
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "bench"))
from provenance import header, load_line  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
PEER = os.path.join(ROOT, "..", "shared", "scenes", "tof-tungsten-cbox-trans")
EPSILON = 0.01
REFERENCE_SPP = 8192
# ToF-Tungsten's path tracer as its README reports it: spp -> (CPU s, relMSE).
PEER_FIGURES = {16: (2.1, 91.3), 64: (7.6, 22.5), 256: (30.0, 5.58), 1024: (113.0, 1.26)}
STRATEGIES = [
    ("free flights (the peer's strategy)", {"equiangular": "false", "light_directions": "false"}),
    ("free flights + equiangular", {"light_directions": "false"}),
    ("free flights + equiangular + light-directed (default)", {}),
]


def scene_with(out_dir, params):
    """The port's scene.xml with `params` added to its integrator, meshes by absolute path."""
    text = open(os.path.join(PEER, "scene.xml")).read()
    extra = "".join(f'<boolean name="{k}" value="{v}"/>' for k, v in params.items())
    text = text.replace('<integer name="max_depth" value="$max_depth"/>',
                        '<integer name="max_depth" value="$max_depth"/>' + extra)
    text = text.replace('"meshes/', '"' + os.path.join(os.path.abspath(PEER), "meshes") + "/")
    path = os.path.join(out_dir, "scene-" + "-".join(f"{k}{v}" for k, v in params.items()) + ".xml")
    open(path, "w").write(text)
    return path


def render(femto, scene, out_dir, spp, seed, resolution):
    """One render; returns (volume as float64, CPU seconds of the process)."""
    out = os.path.join(out_dir, f"{os.path.basename(scene)[:-4]}-{resolution}-{spp}-{seed}.exr")
    cmd = [femto, "render", scene, "-o", out, "--spp", str(spp), "--seed", str(seed), "--no-progress",
           "-D", f"resolution={resolution}"]
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return np.load(out[:-4] + ".npy").astype(np.float64), cpu


def cell_errors(x, ref, m=None):
    """The README's relative squared error per cell; `m` the mean normalising epsilon (ref's by default)."""
    m = ref.mean() if m is None else m
    return (x - ref) ** 2 / (ref ** 2 + EPSILON * m * m)


def worst_share(errors, count):
    e = np.sort(errors.ravel())[::-1]
    return float(e[:count].sum() / e.sum()) if e.sum() > 0 else 0.0


def table_peer_reference(args, out_dir):
    ref = np.load(os.path.join(PEER, "reference.npy")).astype(np.float64)
    print("### (1) Against ToF-Tungsten's reference.npy (128×128×200 bins, seed 1)\n")
    print("| strategy | spp | CPU s | relMSE | relMSE × CPU | worst 1 % cells' share | worst 100 cells' share | "
          "ToF-Tungsten relMSE × CPU (its README) |")
    print("|---|---|---|---|---|---|---|---|")
    for name, params in STRATEGIES:
        scene = scene_with(out_dir, params)
        for spp in args.spp:
            x, cpu = render(args.femto, scene, out_dir, spp, 1, 128)
            e = cell_errors(x, ref)
            peer = PEER_FIGURES.get(spp)
            theirs = f"{peer[0] * peer[1]:.0f}" if peer else "-"
            print(f"| {name} | {spp} | {cpu:.1f} | {e.mean():.3g} | {e.mean() * cpu:.3g} | "
                  f"{worst_share(e, e.size // 100):.2f} | {worst_share(e, 100):.3f} | {theirs} |", flush=True)
    print()


def table_protocol(args, out_dir):
    res = args.protocol_resolution
    print(f"### (2) Scored as the peer scores itself, and independently ({res}×{res}×200 bins)\n")
    # The independent reference: two default-strategy renders with seeds other than the test's.
    default = scene_with(out_dir, STRATEGIES[-1][1])
    a, _ = render(args.femto, default, out_dir, REFERENCE_SPP, 2, res)
    b, _ = render(args.femto, default, out_dir, REFERENCE_SPP, 3, res)
    independent = 0.5 * (a + b)
    m = independent.mean()
    # Each render's error variance is (a - b)^2 / 2 per cell, their mean's a quarter of that.
    own = float(np.mean((a - b) ** 2 / 4.0 / (independent ** 2 + EPSILON * m * m)))
    print(f"Independent reference: the mean of two {REFERENCE_SPP}-spp renders of the default strategy "
          f"(seeds 2, 3); its own relMSE, {own:.3g}, is subtracted from the independent column. "
          f"Same-seed reference: the strategy's own {REFERENCE_SPP}-spp render with the test's seed 1, "
          "whose first samples the test repeats (the peer's protocol).\n")
    print("| strategy | spp | CPU s | relMSE, same-seed reference | its worst 100 cells' mean error | "
          "relMSE, independent reference | relMSE × CPU, independent | ToF-Tungsten's README relMSE |")
    print("|---|---|---|---|---|---|---|---|")
    for name, params in STRATEGIES:
        scene = scene_with(out_dir, params)
        shared, _ = render(args.femto, scene, out_dir, REFERENCE_SPP, 1, res)
        for spp in args.spp:
            x, cpu = render(args.femto, scene, out_dir, spp, 1, res)
            same = cell_errors(x, shared)
            worst = np.sort(same.ravel())[::-1][:100].mean()
            indep = cell_errors(x, independent).mean() - own
            peer = PEER_FIGURES.get(spp)
            print(f"| {name} | {spp} | {cpu:.2f} | {same.mean():.3g} | {worst:.3g} | {indep:.3g} | "
                  f"{indep * cpu:.3g} | {peer[1] if peer else '-'} |", flush=True)
    print()


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--femto", default=os.path.join(ROOT, "build", "bin", "femto"))
    p.add_argument("--spp", default="16,64,256,1024")
    p.add_argument("--protocol-resolution", type=int, default=32)
    p.add_argument("--only", default="12", help="which tables")
    args = p.parse_args(argv)
    args.spp = [int(s) for s in args.spp.split(",")]
    if not os.path.exists(os.path.join(PEER, "reference.npy")):
        sys.exit(f"{PEER}/reference.npy not found")
    load_start = os.getloadavg()
    with tempfile.TemporaryDirectory(prefix="tof-peer-path-") as out_dir:
        # Each table has a section of its own (tools/bench/benchmarks.py: path-peer, path-peer-protocols).
        title = {"1": "transient_path on the peer's scene: against ToF-Tungsten's reference",
                 "2": "transient_path on the peer's scene: reference protocols"}.get(
                     args.only, "transient_path on the peer's scene: strategies and reference protocols")
        header(title, "tools/compare/tof_peer_path.py",
               f"tools/compare/tof_peer_path.py --spp {','.join(map(str, args.spp))} "
               f"--protocol-resolution {args.protocol_resolution}"
               f"{' --only ' + args.only if args.only != '12' else ''}",
               ["CPU = user + system seconds of the femto process, one run each"], threads=2)
        if "1" in args.only:
            table_peer_reference(args, out_dir)
        if "2" in args.only:
            table_protocol(args, out_dir)
    load_end = os.getloadavg()
    print(load_line(load_start, load_end))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
