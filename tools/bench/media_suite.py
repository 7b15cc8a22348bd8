#!/usr/bin/python3
"""The media suite: transient_beams against transient_path at equal CPU time
on scenes nobody tuned the beams for, plus ToF-Tungsten's transient fog
Cornell box when ../shared/scenes/tof-tungsten-cbox-trans is present. Writes
the "media-suite" section of docs/BENCHMARKS.md (tools/bench/run_media_suite.sh).

  tools/bench/media_suite.py [--femto build/bin/femto] [--out build/media-suite] [--quick]

Per scene: a reference (the mean of two long transient_path renders with
other seeds, or ToF-Tungsten's own 8192-spp volume averaged over 2x2 pixels
for the port rendered at half its resolution), one render of each integrator
at a fixed budget (and lajolla's fog Cornell box, a real scene, steady, when
../shared/scenes holds it); relMSE (epsilon = 0.01, as tools/compare and the peer's
README) against the reference, CPU time (user + system of the femto process)
and their product: for a Monte Carlo estimator relMSE x CPU is about constant
in the budget, so the ratio of the products is the ratio of relMSE at equal
CPU time. The reference's own error (estimated from its two renders'
difference) is subtracted from both relMSEs ("corrected"). From transient_beams'
log: the first pass's kernel radius and the candidates and pair hits per beam
query.
"""
import argparse
import hashlib
import os
import re
import resource
import subprocess
import sys
import time

import numpy as np

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
SUITE = os.path.join(ROOT, "tools", "bench", "media_suite")
RADIUS_CASES = os.path.join(ROOT, "tools", "bench", "beams_radius")
TOF = os.path.abspath(os.path.join(ROOT, "..", "shared", "scenes", "tof-tungsten-cbox-trans"))
LAJOLLA = os.path.abspath(os.path.join(ROOT, "..", "shared", "scenes", "lajolla-vol-cbox-fog-0.5"))
EPSILON = 0.01
STATS = re.compile(r"beam queries \(([0-9.e+-]+) candidates and ([0-9.e+-]+) pair hits each\)")
RADIUS = re.compile(r"pass 0: BeamPass\[.*?radius=([0-9.e+-]+)")


def cpu_of_children():
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def render(femto, scene, out, defines, seed):
    """One render; returns (volume file, CPU seconds, wall seconds, log)."""
    cmd = [femto, "render", scene, "-o", out, "--seed", str(seed), "--no-progress"]
    for name, value in defines.items():
        cmd += ["-D", f"{name}={value}"]
    cpu0, wall0 = cpu_of_children(), time.monotonic()
    proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    cpu, wall = cpu_of_children() - cpu0, time.monotonic() - wall0
    if proc.returncode != 0:
        sys.exit(f"`{' '.join(cmd)}` exited {proc.returncode}:\n{proc.stdout}")
    return os.path.splitext(out)[0] + ".npy", cpu, wall, proc.stdout


def slug(name):
    return re.sub("[^a-z0-9]+", "-", name.lower()).strip("-")


def relmse(x, ref):
    m = ref.mean()
    return float(np.mean((x - ref) ** 2 / (ref ** 2 + EPSILON * m * m)))


def cached_path_reference(femto, case, out_dir):
    """Mean of two transient_path renders (seeds 7919, 7920) and the relMSE
    its own noise adds to a measurement against it: each render's error
    variance is (a - b)^2 / 2 per value, the mean's a quarter of that."""
    defines = dict(case["defines"], integrator="transient_path", spp=case["reference_spp"])
    key = hashlib.sha1((open(case["scene"]).read() + repr(sorted(defines.items()))).encode()).hexdigest()[:12]
    path = os.path.join(out_dir, f"ref-{slug(case['name'])}-{key}.npy")
    renders = []
    for seed in (7919, 7920):
        file = os.path.join(out_dir, f"ref-{slug(case['name'])}-{key}-{seed}.exr")
        npy = os.path.splitext(file)[0] + ".npy"
        if not os.path.exists(npy):
            print(f"  reference {case['name']} seed {seed} ({case['reference_spp']} spp) ...", flush=True)
            render(femto, case["scene"], file, defines, seed)
        renders.append(np.load(npy).astype(np.float64))
    a, b = renders
    ref = 0.5 * (a + b)
    m = ref.mean()
    own = float(np.mean((a - b) ** 2 / 4.0 / (ref ** 2 + EPSILON * m * m)))
    np.save(path, ref)
    return ref, own


def tof_reference():
    """ToF-Tungsten's 8192-spp volume, averaged over 2x2 pixels: femto renders
    the port at 64x64, whose box-filtered pixels are exactly those averages.
    Its own error is not known here (one render): taken as 0."""
    ref = np.load(os.path.join(TOF, "reference.npy")).astype(np.float64)
    h, w, bins, c = ref.shape
    return ref.reshape(h // 2, 2, w // 2, 2, bins, c).mean(axis=(1, 3)), 0.0


def write_scene_copy(d, text, source):
    """Write `text` as d/scene.xml beside the suite's integrator files and a
    link to the meshes of the scene's `source` folder; returns its path."""
    open(os.path.join(d, "scene.xml"), "w").write(text)
    for name in ("integrator-transient_path.xml", "integrator-transient_beams.xml"):
        open(os.path.join(d, name), "w").write(open(os.path.join(SUITE, name)).read())
    if not os.path.exists(os.path.join(d, "meshes")):
        os.symlink(os.path.join(source, "meshes"), os.path.join(d, "meshes"))
    return os.path.join(d, "scene.xml")


def tof_scene(out_dir):
    """The port with the suite's integrator files: a copy of its scene.xml
    whose <integrator> is the suite's include, beside links to its meshes."""
    d = os.path.join(out_dir, "tof-port")
    os.makedirs(d, exist_ok=True)
    text = open(os.path.join(TOF, "scene.xml")).read()
    text = re.sub(r'<integrator type="\$integrator">.*?</integrator>',
                  '<include filename="integrator-$integrator.xml"/>', text, flags=re.S)
    text = text.replace('<rfilter type="box"/>', '<boolean name="write_frames" value="false"/>\n      <rfilter type="box"/>')
    return write_scene_copy(d, text, TOF)


def lajolla_scene(out_dir):
    """Lajolla's fog Cornell box (a Mitsuba 0.5 scene by others, in
    millimetres; ../shared/scenes/lajolla-vol-cbox-fog-0.5) with the suite's
    integrator files, its film a one-bin transient film (the steady image,
    written as a volume) at $resolution, its sampler at $spp."""
    d = os.path.join(out_dir, "lajolla-fog")
    os.makedirs(d, exist_ok=True)
    text = open(os.path.join(LAJOLLA, "vol_cbox.xml")).read()
    text = re.sub(r'<integrator type="volpath">.*?</integrator>',
                  '<default name="integrator" value="transient_path"/><default name="max_depth" value="-1"/>'
                  '<default name="resolution" value="48"/><default name="spp" value="16"/>'
                  '<include filename="integrator-$integrator.xml"/>', text, flags=re.S)
    text = text.replace('<integer name="sampleCount" value="1024"/>', '<integer name="sampleCount" value="$spp"/>')
    text = re.sub(r'<film type="hdrfilm">.*?</film>',
                  '<film type="transient"><integer name="width" value="$resolution"/>'
                  '<integer name="height" value="$resolution"/><integer name="temporal_bins" value="1"/>'
                  '<float name="start_opl" value="0"/><float name="bin_width_opl" value="1e7"/>'
                  '<boolean name="write_frames" value="false"/><rfilter type="box"/></film>', text, flags=re.S)
    return write_scene_copy(d, text, LAJOLLA)


def cases(out_dir, quick):
    fog = os.path.join(ROOT, "scenes", "cornell-box-fog", "scene.xml")
    s = 1 if quick else 2  # budget scale
    list_ = [
        dict(name="fog box, 256 bins", scene=fog, defines=dict(resolution=32, bins=256, bin_width=0.04, frames="false"),
             path=dict(spp=64 * s), beams=dict(passes=4 * s), reference_spp=2048),
        dict(name="fog box, 1024 bins", scene=fog,
             defines=dict(resolution=32, bins=1024, bin_width=0.01, frames="false"),
             path=dict(spp=64 * s), beams=dict(passes=4 * s), reference_spp=2048),
        # Issue 14's two single-scattering cases, shared with tools/bench/beams_radius_cases.py.
        dict(name="large medium", scene=os.path.join(RADIUS_CASES, "large_medium.xml"), defines={},
             path=dict(spp=256 * s), beams=dict(passes=2 * s, spp=16), reference_spp=8192),
        dict(name="thick medium", scene=os.path.join(SUITE, "thick-medium.xml"), defines={},
             path=dict(spp=64 * s), beams=dict(passes=2 * s, spp=16), reference_spp=2048),
        # Multiple scattering alone at 1024 bins (issue 14's "20x on multiple scattering at 1024 bins").
        dict(name="thick medium, 1024 bins", scene=os.path.join(SUITE, "thick-medium.xml"),
             defines=dict(bins=1024, bin_width=0.0125),
             path=dict(spp=64 * s), beams=dict(passes=2 * s, spp=16), reference_spp=2048),
        dict(name="box, light outside", scene=os.path.join(RADIUS_CASES, "bounded_box.xml"), defines={},
             path=dict(spp=256 * s), beams=dict(passes=2 * s, spp=16), reference_spp=8192),
    ]
    if os.path.exists(os.path.join(LAJOLLA, "vol_cbox.xml")):
        # A real scene in millimetres, steady (one bin): thin fog (sigma_t 1.5e-3 per mm) and walls.
        list_.append(dict(name="lajolla fog box (steady)", scene=lajolla_scene(out_dir), defines={},
                          path=dict(spp=128 * s), beams=dict(passes=4 * s, spp=2), reference_spp=4096))
    if os.path.exists(os.path.join(TOF, "reference.npy")):
        list_.append(dict(name="ToF-Tungsten port", scene=tof_scene(out_dir), defines=dict(resolution=64),
                          path=dict(spp=16 * s), beams=dict(passes=2 * s, spp=2), reference="tof"))
    return list_


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--femto", default=os.path.join(ROOT, "build", "bin", "femto"))
    p.add_argument("--out", default=os.path.join(ROOT, "build", "media-suite"))
    p.add_argument("--quick", action="store_true", help="half the budgets")
    p.add_argument("--only", help="run only the cases whose name contains this")
    p.add_argument("--repeats", type=int, default=3, help="renders per integrator and scene; CPU is their median")
    args = p.parse_args(argv)
    os.makedirs(args.out, exist_ok=True)
    rows = []
    for case in cases(args.out, args.quick):
        if args.only and args.only not in case["name"]:
            continue
        print(f"{case['name']}:", flush=True)
        ref, own = tof_reference() if case.get("reference") == "tof" else cached_path_reference(femto=args.femto, case=case, out_dir=args.out)
        row = dict(name=case["name"], own=own)
        for integrator in ("transient_path", "transient_beams"):
            budget = case["path" if integrator == "transient_path" else "beams"]
            defines = dict(case["defines"], integrator=integrator, **budget)
            out = os.path.join(args.out, f"{slug(case['name'])}-{integrator}.exr")
            # The same render (seed 1) `repeats` times: the median CPU time, on a
            # shared machine whose single runs vary by tens of percent.
            cpus = []
            for _ in range(args.repeats):
                npy, cpu, wall, log = render(args.femto, case["scene"], out, defines, seed=1)
                cpus.append(cpu)
            cpu = float(np.median(cpus))
            x = np.load(npy).astype(np.float64)
            e = relmse(x, ref)
            row[integrator] = dict(budget=budget, cpu=cpu, wall=wall, relmse=e, corrected=max(e - own, 0.0),
                                   sum=float(x.sum() / ref.sum()))
            if integrator == "transient_beams":
                m, r = STATS.search(log), RADIUS.search(log)
                row["candidates"], row["hits"] = (float(m.group(1)), float(m.group(2))) if m else (0.0, 0.0)
                row["radius"] = float(r.group(1)) if r else 0.0
            print(f"  {integrator}: {budget} CPU {cpu:.1f} s (runs: {', '.join(f'{c:.1f}' for c in cpus)}) relMSE {e:.4g} (corrected {max(e - own, 0.0):.4g})",
                  flush=True)
        rows.append(row)
    print()
    print("| scene | path budget | path CPU s | path relMSE | beams budget | beams CPU s | beams relMSE | "
          "relMSE×CPU path / beams | beams window sum / ref | candidates / query | pair hits / query | "
          "hits per candidate | radius |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        pa, be = r["transient_path"], r["transient_beams"]
        ratio = (pa["corrected"] * pa["cpu"]) / max(be["corrected"] * be["cpu"], 1e-30)
        fmt = lambda b: ", ".join(f"{k} {v}" for k, v in b.items())  # noqa: E731
        print(f"| {r['name']} | {fmt(pa['budget'])} | {pa['cpu']:.1f} | {pa['corrected']:.3g} | {fmt(be['budget'])} | "
              f"{be['cpu']:.1f} | {be['corrected']:.3g} | {ratio:.2f} | {be['sum']:.3f} | {r['candidates']:.0f} | "
              f"{r['hits']:.0f} | {r['hits'] / max(r['candidates'], 1e-30):.2f} | {r['radius']:.3g} |")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
