#!/usr/bin/python3
"""transient_path's distance sampling, measured: prints the Markdown of
docs/BENCHMARKS.md's "transient_path sampling" sections.

  tools/bench/path_sampling_bench.py [--seeds 3] | tools/bench/benchmarks.py set path-sampling
  tools/bench/path_sampling_bench.py [--seeds 3] --only c \
      | tools/bench/benchmarks.py set path-sampling-heterogeneous

(a) Equiangular next-event vertices vs free flights only (transient_path's
    `equiangular`) on scenes/cornell-box-fog, single scattering (max_depth 2)
    and the scene's max_depth 8, there also with and without light-directed
    vertices (`light_directions`).
(b) Time windows on the same scene: the full window, its first and its last
    10 %, with `time_gating` off and on.
(c) Equiangular vertices in a heterogeneous medium: the same scene with its
    fog as a grid (written by this script), free flights against equiangular.
(d) The late window of (b) at a larger budget (--late-spp, 512), where its
    heavy tail shows in a pairwise MSE.
ToF-Tungsten's scene has its own script and section:
tools/compare/tof_peer_path.py ("transient_path on the peer's scene").

Error in (a) and (b) is estimated without a reference: two renders with
independent seeds differ by twice the variance (both estimators are
unbiased; the tests check that), so MSE = mean (a - b)^2 / 2 and, in (a),
relMSE = mean (a - b)^2 / (2 (m^2 + 0.01 mean(m)^2)), m = (a + b) / 2. A late
window is sparse (most cells get no sample at all), where this relMSE,
normalised by the renders' own values, rewards empty cells: (b) uses MSE.
Medians over seed pairs; CPU = user + system seconds of the whole
`femto render` process, median over its runs.
"""
import argparse
import os
import resource
import statistics
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from provenance import header, load_line  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
FEMTO = os.path.join(ROOT, "build", "bin", "femto")
FOG = os.path.join(ROOT, "scenes", "cornell-box-fog", "scene.xml")
ARGS = argparse.Namespace(femto=FEMTO)


def render(scene, defines, seed, out_dir, threads):
    """Render; returns (volume as float64, CPU seconds of the process)."""
    out = os.path.join(out_dir, f"r{seed}_{abs(hash(tuple(sorted(defines.items())))) % 10**8}.exr")
    cmd = [ARGS.femto, "render", scene, "-o", out, "--seed", str(seed), "-t", str(threads)]
    for k, v in defines.items():
        cmd += ["-D", f"{k}={v}"]
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return np.load(out[:-4] + ".npy").astype(np.float64), cpu


def pairwise_rel_mse(a, b):
    m = 0.5 * (a + b)
    return float(np.mean((a - b) ** 2 / (m ** 2 + 0.01 * np.mean(m) ** 2))) / 2.0


def worst_share(x, ref, fraction=0.01):
    """Share of the squared error held by the worst `fraction` of cells."""
    e = np.sort(((x - ref) ** 2).ravel())[::-1]
    return float(e[: max(1, int(len(e) * fraction))].sum() / e.sum()) if e.sum() > 0 else 0.0


def measure_pairs(scene, defines, seeds, out_dir, threads, crop=None):
    """Median pairwise relMSE, MSE, worst-1 % share and CPU over seed pairs."""
    errors, mses, shares, cpus = [], [], [], []
    for k in range(seeds):
        a, ca = render(scene, defines, 2 * k + 1, out_dir, threads)
        b, cb = render(scene, defines, 2 * k + 2, out_dir, threads)
        if crop is not None:
            a, b = a[:, :, crop[0]:crop[1]], b[:, :, crop[0]:crop[1]]
        errors.append(pairwise_rel_mse(a, b))
        mses.append(float(np.mean((a - b) ** 2)) / 2.0)
        shares.append(worst_share(a, b))
        cpus += [ca, cb]
    return statistics.median(errors), statistics.median(mses), statistics.median(shares), statistics.median(cpus)


def fog_defines(**extra):
    d = {"resolution": 48, "spp": 128, "frames": "false"}
    d.update(extra)
    return d


def table_equiangular(args, out_dir):
    print("### (a) Equiangular next-event vertices vs free flights (fog Cornell box)\n")
    print("48×48, 128 spp, 512 bins (OPL 3 to 13.24); relMSE and MSE (per cell) from independent seed pairs, "
          f"medians over {args.seeds} pairs. Efficiency = 1 / (MSE × CPU), relative to free flights.\n")
    print("| max_depth | distance sampling | CPU s | relMSE | MSE | MSE × CPU | efficiency | worst 1 % cells' error share |")
    print("|---|---|---|---|---|---|---|---|")
    for depth in (2, 8):
        base = None
        strategies = [("free flights", dict(equiangular="false")),
                      ("free flights + equiangular (MIS)", dict(light_directions="false")),
                      ("free flights + equiangular + light-directed (MIS)", {})]
        if depth == 2:  # single scattering: no vertex has a second segment for light-directed vertices
            strategies = strategies[:2]
        for name, params in strategies:
            rel, e, share, cpu = measure_pairs(FOG, fog_defines(max_depth=depth, **params), args.seeds,
                                               out_dir, args.threads)
            base = base or e * cpu
            print(f"| {depth} | {name} | {cpu:.2f} | {rel:.3g} | {e:.3g} | {e * cpu:.3g} | {base / (e * cpu):.2f} | "
                  f"{share:.2f} |")
    print()


def table_windows(args, out_dir):
    print("### (b) Time windows and time gating (fog Cornell box)\n")
    print("48×48, 128 spp, bins of 0.02 OPL; the full window is OPL [3, 13.24) in 512 bins, the first 10 % "
          "[3, 4.02) and the last 10 % [12.22, 13.24) in 51 bins. `late bins of full` scores the full render's "
          "bins 461..511 (the late window's OPLs) and charges the full render's CPU. Efficiency = 1 / (MSE × CPU) "
          "of the late window, relative to the full render's late bins. MSE per cell (volume values), pairwise. "
          "With `time_gating`, next-event connections whose light surely arrives before the window are made with "
          "probability `before_window_rate` (default 1/8; weighted by its inverse, so the steady image and `_before` "
          "keep their means); rate 1 makes them all (gating before this option), rate 0 none "
          "(`skip_before_window`: the steady image and `_before` then lack that light).\n")
    print("| window | time_gating | CPU s | CPU / full window's | MSE in the window | MSE × CPU | efficiency |")
    print("|---|---|---|---|---|---|---|")
    full_cpu = {}
    late_base = None
    rows = [("full", {}, None), ("late bins of full", {}, (461, 512)), ("first 10 %", {"bins": 51}, None),
            ("last 10 %", {"bins": 51, "start": 12.22}, None)]
    for name, window, crop in rows:
        options = [("false", {}), ("true", {})]
        if name in ("first 10 %", "last 10 %"):
            options = [("false", {}), ("true, rate 1", {"before_window_rate": 1}), ("true (rate 1/8)", {}),
                       ("true, rate 0", {"before_window_rate": 0})]
        for gating, extra in options:
            _, e, _, cpu = measure_pairs(FOG, fog_defines(time_gating=gating.split()[0].rstrip(","), **window, **extra), args.seeds,
                                         out_dir, args.threads, crop)
            if name == "full":
                full_cpu[gating] = cpu
            if name == "late bins of full" and gating == "false":
                late_base = e * cpu
            ratio = cpu / full_cpu["false"]
            eff = f"{late_base / (e * cpu):.2f}" if late_base and name in ("late bins of full", "last 10 %") else "-"
            print(f"| {name} | {gating} | {cpu:.2f} | {ratio:.2f} | {e:.3g} | {e * cpu:.3g} | {eff} |")
    print()


HETEROGENEOUS_MEDIUM = """<?xml version="1.0" encoding="utf-8"?>
<!-- path_sampling_bench.py (c): scene.xml's fog as a heterogeneous medium. -->
<scene version="3.0.0">
  <medium type="heterogeneous" id="fog">
    <volume name="sigma_t" type="gridvolume"><string name="filename" value="density.vol"/></volume>
    <float name="scale" value="0.8"/>
    <rgb name="albedo" value="0.8"/>
    <phase type="isotropic"/>
  </medium>
  <shape type="cube" id="fog_boundary">
    <transform name="to_world"><scale value="0.998"/></transform>
    <ref name="interior" id="fog"/>
  </shape>
</scene>
"""


def heterogeneous_fog_box(out_dir):
    """A copy of the fog box whose fog (-D medium=hetero) is a 16^3 grid of
    densities 0.3-1 (times 0.8): a smooth product of sines, written as a
    Mitsuba .vol file."""
    import shutil
    import struct
    scene_dir = os.path.join(out_dir, "hetero-fog-box")
    shutil.copytree(os.path.dirname(FOG), scene_dir)
    n = 16
    x = np.linspace(0.0, 1.0, n)
    X, Y, Z = np.meshgrid(x, x, x, indexing="ij")
    density = 0.3 + 0.7 * (0.5 + 0.5 * np.sin(6 * X) * np.cos(5 * Y + 1) * np.sin(4 * Z + 0.5))
    with open(os.path.join(scene_dir, "density.vol"), "wb") as f:
        f.write(b"VOL" + bytes([3]) + struct.pack("<5i", 1, n, n, n, 1) + struct.pack("<6f", -1, -1, -1, 1, 1, 1))
        f.write(density.transpose(2, 1, 0).astype("<f4").tobytes())  # x fastest
    with open(os.path.join(scene_dir, "medium-hetero.xml"), "w") as f:
        f.write(HETEROGENEOUS_MEDIUM)
    return os.path.join(scene_dir, "scene.xml")


GRID_FOG_BESIDE_THE_LIGHT = """<?xml version="1.0" encoding="utf-8"?>
<!-- path_sampling_bench.py (c): double scattering in a grid fog around the
     camera, a point light just beside the view (as the CI test
     TransientPathLightDirections.DoubleScatteringInHeterogeneousFogAgreesWithoutThem). -->
<scene version="3.0.0">
  <default name="spp" value="256"/>
  <default name="equiangular" value="true"/>
  <default name="light_directions" value="true"/>
  <integrator type="transient_path"><integer name="max_depth" value="3"/>
    <boolean name="equiangular" value="$equiangular"/><boolean name="light_directions" value="$light_directions"/>
  </integrator>
  <medium id="m" type="heterogeneous"><volume name="sigma_t" type="gridvolume"><string name="filename" value="density.vol"/></volume>
    <float name="scale" value="0.7"/><rgb name="albedo" value="0.8, 0.75, 0.7"/></medium>
  <shape type="cube"><transform name="to_world"><scale value="2"/></transform><ref name="interior" id="m"/></shape>
  <sensor type="perspective"><float name="fov" value="22.6"/><ref id="m"/>
    <transform name="to_world"><lookat origin="0, 0, 0" target="0, 0, 1" up="0, 1, 0"/></transform>
    <sampler type="independent"><integer name="sample_count" value="$spp"/></sampler>
    <film type="transient"><integer name="width" value="32"/><integer name="height" value="32"/>
      <integer name="temporal_bins" value="64"/><float name="start_opl" value="1"/>
      <float name="bin_width_opl" value="0.0625"/><boolean name="write_frames" value="false"/><rfilter type="box"/></film>
  </sensor>
  <emitter type="point"><point name="position" x="0.45" y="0.02" z="1"/><float name="intensity" value="2"/></emitter>
</scene>
"""


def grid_fog_beside_the_light(out_dir):
    """GRID_FOG_BESIDE_THE_LIGHT with its 6^3 grid (densities 0.1-1.5 in a
    pattern, as tests/unit/media_test_util.h's writeDensityGrid) on [-2, 2]^3."""
    import struct
    scene_dir = os.path.join(out_dir, "grid-fog-beside-the-light")
    os.makedirs(scene_dir, exist_ok=True)
    n, h = 6, 2.0
    with open(os.path.join(scene_dir, "density.vol"), "wb") as f:
        f.write(b"VOL" + bytes([3]) + struct.pack("<5i", 1, n, n, n, 1) + struct.pack("<6f", -h, -h, -h, h, h, h))
        for z in range(n):
            for y in range(n):
                for x in range(n):
                    f.write(struct.pack("<f", 0.1 + 1.4 * ((x + 2 * y + 3 * z) % 5) / 4.0))
    with open(os.path.join(scene_dir, "scene.xml"), "w") as f:
        f.write(GRID_FOG_BESIDE_THE_LIGHT)
    return os.path.join(scene_dir, "scene.xml")


def strategy_table(args, out_dir, scene, defines):
    """Free flights, + equiangular, + light-directed vertices on `scene`
    (`defines` maps each row's integrator parameters to the render's)."""
    print("| distance sampling | CPU s | MSE | MSE × CPU | efficiency |")
    print("|---|---|---|---|---|")
    base = None
    for name, params in [("free flights", dict(equiangular="false")),
                         ("free flights + equiangular", dict(light_directions="false")),
                         ("free flights + equiangular + light-directed (default)", {})]:
        _, e, _, cpu = measure_pairs(scene, defines(params), args.seeds, out_dir, args.threads)
        base = base or e * cpu
        print(f"| {name} | {cpu:.2f} | {e:.3g} | {e * cpu:.3g} | {base / (e * cpu):.2f} |")
    print()


def table_heterogeneous(args, out_dir):
    print("### (c) Equiangular next-event vertices in a heterogeneous medium (fog Cornell box)\n")
    print("The fog box with its fog as a heterogeneous medium (a 16³ grid of densities 0.3–1 times 0.8, albedo 0.8). "
          "48×48, 128 spp, 512 bins, max_depth 8; MSE from independent seed pairs, medians over "
          f"{args.seeds} pairs. There the equiangular vertex takes every distance it can sample and the free-flight "
          "vertex the rest (docs/media.md); a light-directed vertex takes the first heterogeneous segment of its ray "
          "and shares those distances with the equiangular vertex. "
          "Efficiency = 1 / (MSE × CPU), relative to free flights.\n")
    strategy_table(args, out_dir, heterogeneous_fog_box(out_dir), lambda params: fog_defines(medium="hetero", **params))
    print("The same three on double scattering in a grid fog around the camera with a point light just beside the "
          "view (the scene of the CI test TransientPathLightDirections.DoubleScatteringInHeterogeneousFogAgreesWith"
          "outThem; 32×32, 256 spp, 64 bins, max_depth 3), where paths' own directions pass close to the light.\n")
    strategy_table(args, out_dir, grid_fog_beside_the_light(out_dir), lambda params: params)


def table_late_window(args, out_dir):
    print(f"### (d) The late window at {args.late_spp} spp (fog Cornell box)\n")
    print(f"As (b), at {args.late_spp} spp instead of 128: the last 10 % of the transport, gated, against the full "
          "render's late bins. The late window is heavy-tailed, and at 128 spp a pairwise MSE mostly sees its "
          "typical samples; here its tail shows. MSE per cell, pairwise, median and mean over "
          f"{args.seeds} seed pairs; MSE × CPU relative to the full render's late bins.\n")
    print("| window | time_gating | CPU s | CPU / full render's | MSE (median) | MSE (mean) | MSE × CPU (median) | "
          "MSE × CPU (mean) |")
    print("|---|---|---|---|---|---|---|---|")
    rows = [("late bins of full", "false", {}, (461, 512)),
            ("last 10 %", "true, rate 1", {"bins": 51, "start": 12.22, "before_window_rate": 1}, None),
            ("last 10 %", "true (rate 1/8)", {"bins": 51, "start": 12.22}, None)]
    base = None
    for name, gating, window, crop in rows:
        defines = fog_defines(time_gating=gating.split()[0].rstrip(","), **window)
        defines["spp"] = args.late_spp
        mses, cpus = [], []
        for k in range(args.seeds):
            a, ca = render(FOG, defines, 2 * k + 1, out_dir, args.threads)
            b, cb = render(FOG, defines, 2 * k + 2, out_dir, args.threads)
            if crop is not None:
                a, b = a[:, :, crop[0]:crop[1]], b[:, :, crop[0]:crop[1]]
            mses.append(float(np.mean((a - b) ** 2)) / 2.0)
            cpus += [ca, cb]
        median, mean, cpu = statistics.median(mses), float(np.mean(mses)), statistics.median(cpus)
        base = base or (cpu, median * cpu, mean * cpu)
        print(f"| {name} | {gating} | {cpu:.2f} | {cpu / base[0]:.2f} | {median:.3g} | {mean:.3g} | "
              f"{median * cpu / base[1]:.2f} | {mean * cpu / base[2]:.2f} |")
    print()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--seeds", type=int, default=3, help="seed pairs for (a) and (b)")
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--only", default="abd", help="which tables (c alone: its own section)")
    parser.add_argument("--late-spp", type=int, default=512, help="the budget of table (d)")
    parser.add_argument("--femto", default=FEMTO,
                        help="the femto executable (e.g. a copy of an older build, to measure before and after)")
    args = parser.parse_args()
    ARGS.femto = args.femto
    load_start = os.getloadavg()
    with tempfile.TemporaryDirectory(prefix="path-sampling-") as out_dir:
        # Table (c) has a section of its own (tools/bench/benchmarks.py: path-sampling-heterogeneous).
        title = ("transient_path sampling in a heterogeneous medium" if args.only == "c"
                 else "transient_path sampling: equiangular, time windows")
        header(title, "tools/bench/path_sampling_bench.py",
               f"tools/bench/path_sampling_bench.py --seeds {args.seeds}"
               f"{' --only ' + args.only if args.only != 'abd' else ''}",
               ["CPU = user + system seconds of the whole `femto render` process (loading, rendering, writing); "
                "the machine is shared, so wall time is not quoted"], threads=args.threads)
        if "a" in args.only:
            table_equiangular(args, out_dir)
        if "b" in args.only:
            table_windows(args, out_dir)
        if "c" in args.only:
            table_heterogeneous(args, out_dir)
        if "d" in args.only:
            table_late_window(args, out_dir)
        load_end = os.getloadavg()
        print(load_line(load_start, load_end))
        sys.stdout.flush()


if __name__ == "__main__":
    main()
