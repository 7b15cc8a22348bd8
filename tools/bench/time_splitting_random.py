#!/usr/bin/python3
"""transient_path's time_splitting on and off on seeded random fog cubes (a
point light and a diffuse floor inside a cube of homogeneous fog, sigma_t
log-uniform in [0.2, 5], albedo 0.5-0.99, eta 1 or 1.33, seen from outside;
24x24 pixels, 128 bins): scenes nobody tuned the rule on. Per cube, 64 spp
with seeds 1-3 each way, CPU the median, relMSE (eps 0.01 x mean^2) the mean
against 2 x 1024 spp of splitting, its own error subtracted.

  tools/bench/time_splitting_random.py [generator seed, default 7] [--femto PATH]

Prints one line per cube; the errors are heavy-tailed in thick cubes, so
read a low ratio there with more seeds before trusting it.
"""
import os
import random
import shutil
import statistics
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from media_suite import ROOT, cpu_of_children  # noqa: E402

args = [a for a in sys.argv[1:] if not a.startswith("--femto")]
FEMTO = next((a.split("=", 1)[1] for a in sys.argv[1:] if a.startswith("--femto=")),
             os.path.join(ROOT, "build", "bin", "femto"))
rng = random.Random(int(args[0]) if args else 7)
TMP = tempfile.mkdtemp(prefix="time-splitting-random-")
def scene(c, split):
    return f"""<scene version="3.0.0"><default name="spp" value="64"/>
  <integrator type="transient_path"><integer name="max_depth" value="40"/><boolean name="time_splitting" value="{split}"/></integrator>
  <medium id="fog" type="homogeneous"><float name="sigma_t" value="{c['s']}"/><float name="albedo" value="{c['a']}"/><float name="eta" value="{c['eta']}"/></medium>
  <shape type="cube"><ref name="interior" id="fog"/></shape>
  <shape type="rectangle"><transform name="to_world"><scale value="0.95"/><rotate x="1" angle="-90"/><translate y="-0.95"/></transform><bsdf type="diffuse"><rgb name="reflectance" value="0.7"/></bsdf></shape>
  <emitter type="point"><point name="position" x="{c['x']}" y="{c['y']}" z="{c['z']}"/><float name="intensity" value="3"/></emitter>
  <sensor type="perspective"><float name="fov" value="35"/><transform name="to_world"><lookat origin="0, 0, 4" target="0, 0, 0" up="0, 1, 0"/></transform>
    <sampler type="independent"><integer name="sample_count" value="$spp"/></sampler>
    <film type="transient"><integer name="width" value="24"/><integer name="height" value="24"/><integer name="temporal_bins" value="128"/>
      <float name="start_opl" value="3"/><float name="bin_width_opl" value="0.1"/><rfilter type="box"/></film></sensor></scene>"""
def run(xml, spp, seed):
    open(os.path.join(TMP, "rs.xml"), "w").write(xml)
    c0 = cpu_of_children()
    subprocess.run([FEMTO, "render", os.path.join(TMP, "rs.xml"), "-o", os.path.join(TMP, "rs.exr"), "--seed", str(seed),
                    "--no-progress", "-D", f"spp={spp}"], check=True, capture_output=True)
    return np.load(os.path.join(TMP, "rs.npy")).astype(np.float64), cpu_of_children() - c0
for k in range(6):
    c = dict(s=round(0.2 * 25 ** rng.random(), 3), a=round(0.5 + 0.49 * rng.random(), 3), eta=1.0 if k % 2 == 0 else 1.33,
             x=round(1.6 * rng.random() - 0.8, 2), y=round(1.6 * rng.random() - 0.8, 2), z=round(1.6 * rng.random() - 0.8, 2))
    a, _ = run(scene(c, "true"), 1024, 7919); b, _ = run(scene(c, "true"), 1024, 7920)
    ref = (a + b) / 2; m = ref.mean(); rel = lambda x: float(np.mean((x - ref) ** 2 / (ref ** 2 + 0.01 * m * m)))
    own = float(np.mean((a - b) ** 2 / 4 / (ref ** 2 + 0.01 * m * m)))
    eff = {}
    for split in ("false", "true"):
        r = [run(scene(c, split), 64, s) for s in (1, 2, 3)]
        cpu = statistics.median(t for _, t in r); e = np.mean([rel(x) for x, _ in r]) - own
        eff[split] = (cpu, e)
    (c0, e0), (c1, e1) = eff["false"], eff["true"]
    print(f"cube {k} {c}: off {c0:.2f}s {e0:.3g}, on {c1:.2f}s {e1:.3g}, own {own:.2g}: efficiency on/off {c0*e0/(c1*e1):.2f}x", flush=True)
shutil.rmtree(TMP, ignore_errors=True)
