#!/usr/bin/python3
"""Issue 37: many scenes per job. 16 small scenes (the fog box with the light
moved, 32x32, 128 bins, 64 spp) rendered (a) one `femto render` each,
-t 1, in turn: the sum of their CPU seconds is the work; (b) in one
`femto render a.xml b.xml ...` (-t 1); (c) by `mpirun -n 2 femto render ...`
(-t 1 per rank), each rank rendering whole scenes. Efficiency of (c) =
ideal / wall, ideal = the work of (a) / 2. Prints the "many-scenes" section
of docs/BENCHMARKS.md:

  tools/bench/many_scenes.py [--femto build/bin/femto] [--repeats 3] | tools/bench/benchmarks.py set many-scenes
"""
import argparse
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import provenance  # noqa: E402
from media_suite import ROOT, cpu_of_children  # noqa: E402

MPIRUN = ["mpirun", "--oversubscribe", "--mca", "btl", "self,vader", "--mca", "oob_tcp_if_include", "lo"]
OPTS = ["--no-progress", "-t", "1", "-D", "resolution=32", "-D", "bins=128", "-D", "bin_width=0.08", "-D", "spp=64"]


def scenes(tmp, count):
    """`count` copies of the fog box (its include files beside them), the light moved in x."""
    fog = os.path.join(ROOT, "scenes", "cornell-box-fog")
    text = open(os.path.join(fog, "scene.xml")).read()
    old = '<point name="position" x="0" y="0.8" z="0"/>'
    if old not in text:
        sys.exit("scenes/cornell-box-fog/scene.xml: its light's position line changed; update many_scenes.py")
    for name in os.listdir(fog):
        if name != "scene.xml":
            os.symlink(os.path.join(fog, name), os.path.join(tmp, name))
    files = []
    for k in range(count):
        path = os.path.join(tmp, f"fog{k:02d}.xml")
        with open(path, "w") as f:
            f.write(text.replace(old, f'<point name="position" x="{-0.6 + 1.2 * k / (count - 1):.3f}" y="0.8" z="0"/>'))
        files.append(path)
    return files


def timed(cmd, env=None):
    cpu0, wall0 = cpu_of_children(), time.monotonic()
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env)
    return time.monotonic() - wall0, cpu_of_children() - cpu0


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--femto", default=os.path.join(ROOT, "build", "bin", "femto"))
    p.add_argument("--repeats", type=int, default=3)
    p.add_argument("--count", type=int, default=16)
    args = p.parse_args(argv)
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    start = os.getloadavg()
    tmp = tempfile.mkdtemp(prefix="many-scenes-")
    rows = {"a": [], "b": [], "c": []}
    try:
        files = scenes(tmp, args.count)
        for r in range(args.repeats):
            walls, cpus = 0.0, 0.0
            for f in files:
                w, c = timed([args.femto, "render", f, "-o", os.path.join(tmp, "a", os.path.basename(f)[:-4] + ".exr")] + OPTS)
                walls, cpus = walls + w, cpus + c
            rows["a"].append((walls, cpus))
            rows["b"].append(timed([args.femto, "render"] + files + ["-o", os.path.join(tmp, "b")] + OPTS))
            rows["c"].append(timed(MPIRUN + ["-n", "2", args.femto, "render"] + files + ["-o", os.path.join(tmp, "c")] + OPTS,
                                   env))
            print(f"  run {r + 1}: " + ", ".join(f"{k} wall {v[-1][0]:.2f} s CPU {v[-1][1]:.2f} s" for k, v in rows.items()),
                  file=sys.stderr, flush=True)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    med = {k: (statistics.median(w for w, _ in v), statistics.median(c for _, c in v)) for k, v in rows.items()}
    work = med["a"][1]
    provenance.header("Many scenes per job", "tools/bench/many_scenes.py", "tools/bench/many_scenes.py " + " ".join(argv),
                      notes=[f"{args.count} fog boxes (light moved), 32x32, 128 bins, 64 spp, -t 1 per process or rank; "
                             f"medians of {args.repeats} runs; wall seconds include start-up (mpirun's too)",
                             "ideal = the CPU seconds of the scenes rendered one process each, / 2 ranks"])
    print("| how | wall s | CPU s (children) | ideal wall s | efficiency (ideal / wall) |")
    print("|---|---|---|---|---|")
    print(f"| one `femto render` per scene, in turn | {med['a'][0]:.2f} | {med['a'][1]:.2f} | {work:.2f} | "
          f"{work / med['a'][0]:.2f} |")
    print(f"| one `femto render` of all {args.count} | {med['b'][0]:.2f} | {med['b'][1]:.2f} | {work:.2f} | "
          f"{work / med['b'][0]:.2f} |")
    print(f"| `mpirun -n 2 femto render` of all {args.count} | {med['c'][0]:.2f} | {med['c'][1]:.2f} | {work / 2:.2f} | "
          f"**{work / 2 / med['c'][0]:.2f}** |")
    print()
    print(provenance.load_line(start, os.getloadavg()))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
