#!/usr/bin/python3
"""Issue 14's two single-scattering cases (beams_radius/large_medium.xml,
beams_radius/bounded_box.xml): transient_beams at its defaults against a long
transient_path reference, and transient_path at a budget, measured as a user
would. For each render: CPU seconds of the femto process (user + system,
getrusage of the child), relMSE over the volume (epsilon 0.01, as femto
compare), the window sum's deviation from the reference's, the energy in bins
that end before the earliest possible arrival, and the beam radius and
candidates / pair hits per query from transient_beams' log.

  tools/bench/beams_radius_cases.py --bin build/bin [--case box|large|both] [--passes 1,4]
      [--path-spp 4096] [--ref-spp 65536] [--runs 1] [--out DIR]

The reference renders are cached in DIR (per case and spp)."""
import argparse, os, re, resource, subprocess, sys, time
from pathlib import Path
import numpy as np

HERE = Path(__file__).resolve().parent / "beams_radius"
# Earliest possible arrival (OPL) of each case: large medium eta |camera - light|;
# the box has the camera outside in vacuum, its bound is |camera - light| (eta >= 1).
CASES = {"large": ("large_medium.xml", 1.33 * 2.0), "box": ("bounded_box.xml", float(np.linalg.norm([1, 0, 3])))}


def render(binary, scene, out, defines, threads):
    cmd = [str(Path(binary) / "femto"), "render", str(scene), "-o", str(out), "-t", str(threads),
           "-p", str(Path(binary) / "plugins")]
    for k, v in defines.items():
        cmd += ["-D", f"{k}={v}"]
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    p = subprocess.run(cmd, capture_output=True, text=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if p.returncode != 0:
        sys.exit(f"render failed: {' '.join(cmd)}\n{p.stderr}")
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return np.load(Path(out).with_suffix(".npy")).astype(np.float64), cpu, p.stdout + p.stderr


def beams_stats(log):
    r = re.search(r"radius=([0-9.eE+-]+)", log)
    q = re.search(r"\(([0-9.eE+-]+) candidates and ([0-9.eE+-]+) pair hits each\)", log)
    return (float(r.group(1)) if r else float("nan"), float(q.group(1)) if q else float("nan"),
            float(q.group(2)) if q else float("nan"))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--bin", required=True)
    ap.add_argument("--case", default="both")
    ap.add_argument("--passes", default="1")
    ap.add_argument("--path-spp", type=int, default=4096)
    ap.add_argument("--ref-spp", type=int, default=65536)
    ap.add_argument("--runs", type=int, default=1)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--observer-time", default="true")
    ap.add_argument("--radius", default="0")
    ap.add_argument("--out", default="/tmp/beams_radius_cases")
    a = ap.parse_args()
    out = Path(a.out)
    out.mkdir(parents=True, exist_ok=True)
    for case in (["large", "box"] if a.case == "both" else [a.case]):
        scene, earliest = CASES[case]
        scene = HERE / scene
        ot = {"observer_time": a.observer_time}
        ref_file = out / f"{case}_ot{a.observer_time}_ref{a.ref_spp}.exr"
        if ref_file.with_suffix(".npy").exists():
            ref = np.load(ref_file.with_suffix(".npy")).astype(np.float64)
        else:
            ref, cpu, _ = render(a.bin, scene, ref_file, {"integrator": "transient_path", "spp": a.ref_spp, **ot},
                                 a.threads)
            print(f"{case}: reference {a.ref_spp} spp, {cpu:.1f} CPU s")
        start = float(re.search(r'name="start(?:_opl)?" value="([0-9.]+)"', scene.read_text()).group(1))
        width = float(re.search(r'name="bin_width_opl" value="([0-9.]+)"', scene.read_text()).group(1))
        # Bins that end before the earliest arrival (observer time on).
        early = int(np.floor((earliest - start) / width)) if a.observer_time == "true" else 0
        ref_sum = ref.sum()

        def report(name, v, cpu, extra=""):
            relmse = np.mean((v - ref) ** 2 / (ref ** 2 + 0.01))
            early_e = v[:, :, :early, :].sum() / max(v.sum(), 1e-30) if early > 0 else 0.0
            print(f"{case} {name}: CPU {cpu:.2f} s, relMSE {relmse:.4g}, relMSE x CPU {relmse * cpu:.4g}, "
                  f"window sum {100 * (v.sum() / ref_sum - 1):+.2f} %, energy before earliest arrival "
                  f"{early_e:.3g} (bins 0..{early - 1}){extra}", flush=True)

        for run in range(a.runs):
            v, cpu, _ = render(a.bin, scene, out / f"{case}_path.exr",
                               {"integrator": "transient_path", "spp": a.path_spp, **ot}, a.threads)
            report(f"path {a.path_spp} spp (run {run})", v, cpu)
            for passes in [int(p) for p in a.passes.split(",")]:
                v, cpu, log = render(a.bin, scene, out / f"{case}_beams.exr",
                                     {"integrator": "transient_beams", "passes": passes, "radius": a.radius, **ot},
                                     a.threads)
                r, cand, hits = beams_stats(log)
                report(f"beams {passes} passes (run {run})", v, cpu,
                       f", radius {r:.4g}, {cand:.1f} candidates / {hits:.1f} pair hits per query")


if __name__ == "__main__":
    main()
