#!/usr/bin/python3
"""transient_path's time_splitting (roulette and splitting against the film's
time profile) against Mitsuba's roulette (time_splitting=false), paired on
each scene: the same spp, seeds 1..--seeds, CPU the median, relMSE (eps 0.01 x
mean^2) the mean over seeds against a reference independent of both renders.
Prints the "time-splitting" section of docs/BENCHMARKS.md:

  tools/bench/time_splitting.py [--seeds 3] | tools/bench/benchmarks.py set time-splitting

Scenes: mitransient's volumetric box (its 8192-spp mitransient render, the
emitter's bins masked, as tools/bench/mitransient_peer.py scores it),
ToF-Tungsten's fog box (reference-independent.npy), the fog box at 1024 bins
with and without its fog, and the media suite's thick medium (the mean of two
long transient_path renders, their own error subtracted, cached under
build/time-splitting). The shared scenes are read from copies whose
integrator gets the switch; nothing else in them changes.
"""
import argparse
import contextlib
import os
import re
import shutil
import statistics
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import provenance  # noqa: E402
from media_suite import ROOT, SUITE, cached_path_reference, relmse, render  # noqa: E402
from mitransient_peer import SCENE_DIR as MITRANSIENT, mask  # noqa: E402
from mitransient_peer import relmse as masked_relmse  # noqa: E402

SHARED = os.path.join(os.path.dirname(ROOT.rstrip("/")), "shared")
TOF = os.path.join(SHARED, "scenes", "tof-tungsten-cbox-trans")
FOG = os.path.join(ROOT, "scenes", "cornell-box-fog", "scene.xml")
SWITCH = '<boolean name="time_splitting" value="$time_splitting"/>'


def switched_copy(source_dir, scene_name, out_dir, integrator_file=None):
    """A copy of source_dir (files linked, the scene and the integrator file
    rewritten) whose transient_path takes -D time_splitting=...; returns its scene."""
    d = os.path.join(out_dir, os.path.basename(source_dir.rstrip("/")))
    os.makedirs(d, exist_ok=True)
    for name in os.listdir(source_dir):
        target = os.path.join(d, name)
        if not os.path.exists(target):
            os.symlink(os.path.join(source_dir, name), target)
    edited = integrator_file or scene_name
    text = open(os.path.join(source_dir, edited)).read()
    text, n = re.subn(r'(<integer name="max_depth" value="[^"]*"\s*/>)', r"\1" + SWITCH, text, count=1)
    if n != 1:
        sys.exit(f"{source_dir}/{edited}: no max_depth to put the switch beside")
    os.unlink(os.path.join(d, edited))
    open(os.path.join(d, edited), "w").write(text)
    scene = os.path.join(d, scene_name)
    text = open(scene).read()
    if '<default name="time_splitting"' not in text:
        text = re.sub(r"(<scene[^>]*>)", r'\1<default name="time_splitting" value="true"/>', text, count=1)
        os.unlink(scene)
        open(scene, "w").write(text)
    return scene


def cases(out_dir, cache):
    thick = switched_copy(SUITE, "thick-medium.xml", out_dir, "integrator-transient_path.xml")
    mitr = switched_copy(MITRANSIENT, "cbox_volumetric.xml", out_dir)
    tof = switched_copy(TOF, "scene.xml", out_dir)
    mitr_ref = np.load(os.path.join(MITRANSIENT, "reference-mitransient.npy")).astype(np.float64)
    keep = mask(mitr_ref.shape)
    fog = dict(resolution=64, bins=1024, bin_width=0.01)
    return [
        ("mitransient's volumetric box, 64x64x400", mitr, dict(res=64), 256,
         lambda: (mitr_ref, 0.0), lambda x, ref: masked_relmse(x.reshape(ref.shape), ref, keep)),
        ("ToF-Tungsten's fog box, 128x128x200", tof, {}, 32,
         lambda: (np.load(os.path.join(TOF, "reference-independent.npy")).astype(np.float64), 0.0), None),
        ("fog box, 64x64x1024", FOG, fog, 64,
         lambda: cached_path_reference(femto_bin, dict(name="fog box 1024", scene=FOG, defines=fog,
                                                       reference_spp=2048), cache), None),
        ("fog box without fog, 64x64x1024", FOG, dict(fog, medium="none"), 64,
         lambda: cached_path_reference(femto_bin, dict(name="fog box none 1024", scene=FOG,
                                                       defines=dict(fog, medium="none"), reference_spp=4096), cache),
         None),
        ("thick medium, 32x32x256", thick, dict(integrator="transient_path"), 64,
         lambda: cached_path_reference(femto_bin, dict(name="thick medium", scene=thick,
                                                       defines=dict(integrator="transient_path"),
                                                       reference_spp=2048), cache), None),
    ]


femto_bin = None


def main(argv):
    global femto_bin
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--femto", default=os.path.join(ROOT, "build", "bin", "femto"))
    p.add_argument("--seeds", type=int, default=3)
    p.add_argument("--only", default="", help="run only the scenes whose name contains this")
    args = p.parse_args(argv)
    femto_bin = args.femto
    cache = os.path.join(os.path.dirname(os.path.dirname(args.femto)), "time-splitting")
    os.makedirs(cache, exist_ok=True)
    start = os.getloadavg()
    tmp = tempfile.mkdtemp(prefix="time-splitting-")
    rows = []
    try:
        for name, scene, defines, spp, reference, score in cases(tmp, cache):
            if args.only not in name:
                continue
            with contextlib.redirect_stdout(sys.stderr):  # the reference's progress lines
                ref, own = reference()
            score = score or (lambda x, r: relmse(x.reshape(r.shape), r))
            result = {}
            for seed in range(1, args.seeds + 1):
                for on in ("false", "true"):
                    d = dict(defines, spp=spp, time_splitting=on)
                    npy, cpu, _, _ = render(args.femto, scene, os.path.join(tmp, "run.exr"), d, seed)
                    result.setdefault(on, []).append((cpu, score(np.load(npy).astype(np.float64), ref) - own))
            cells = []
            for on in ("false", "true"):
                cpu = statistics.median(c for c, _ in result[on])
                err = float(np.mean([e for _, e in result[on]]))
                cells.append((cpu, err))
            (c0, e0), (c1, e1) = cells
            rows.append((name, spp, c0, e0, c1, e1, own))
            print(f"  {name}: off {c0:.2f} s {e0:.4g}, on {c1:.2f} s {e1:.4g}: {c0 * e0 / (c1 * e1):.2f}x",
                  file=sys.stderr, flush=True)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    provenance.header("Splitting against time: transient_path's time_splitting on and off",
                      "tools/bench/time_splitting.py", "tools/bench/time_splitting.py " + " ".join(argv),
                      notes=[f"the same spp on and off, seeds 1-{args.seeds}; CPU (user + system of the femto "
                             f"process, 2 threads) the median, relMSE the mean over seeds, the reference's own "
                             f"relMSE subtracted where it is known (long femto references: from their two halves)"])
    print("| scene | spp | off: CPU s | off: relMSE | on: CPU s | on: relMSE | reference's own relMSE | "
          "efficiency, on / off (relMSE × CPU) |")
    print("|---|---|---|---|---|---|---|---|")
    for name, spp, c0, e0, c1, e1, own in rows:
        print(f"| {name} | {spp} | {c0:.2f} | {e0:.4g} | {c1:.2f} | {e1:.4g} | {own:.2g} | "
              f"**{c0 * e0 / (c1 * e1):.2f}** |")
    print()
    print(provenance.load_line(start, os.getloadavg()))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
