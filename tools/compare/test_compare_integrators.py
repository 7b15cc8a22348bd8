#!/usr/bin/python3
"""End to end, tiny: `femto compare SCENE -i A -i B` on the fog box at 16x16
pixels and 32 bins, two budgets of a fraction of a CPU second, a reference of
1 CPU second and two arrival bands. Checks the table (a row per budget, a
finite equal-CPU ratio, the bands' ratios), the CSV and the PNG, and that a
second run takes the reference from the cache. A few seconds of CPU; no time
is asserted. Run by ctest:  test_compare_integrators.py FEMTO SOURCE_DIR WORK_DIR"""
import csv
import math
import os
import re
import shutil
import subprocess
import sys

femto, source, work = sys.argv[1], sys.argv[2], sys.argv[3]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
scene = os.path.join(source, "scenes", "cornell-box-fog", "scene.xml")
cmd = [femto, "compare", scene, "-i", "transient_path,spp=1",
       "-i", "transient_beams,photon_count=2000,beam_photon_count=300,spp=2",
       "-D", "resolution=16", "-D", "bins=32", "-D", "bin_width=0.32", "-D", "frames=false",
       "--budgets", "0.2,0.4", "--reference-time", "1", "--bands", "2", "-t", "2",
       "-o", os.path.join(work, "out"), "--cache-dir", os.path.join(work, "cache")]
failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAIL:", message)


def run(extra=(), path=None):
    env = dict(os.environ, MPLBACKEND="Agg")
    if path is not None:
        env["PATH"] = path
    r = subprocess.run(cmd + list(extra), capture_output=True, text=True, timeout=600, env=env)
    print(r.stdout, r.stderr)
    if r.returncode != 0:
        sys.exit(f"femto compare exited {r.returncode}")
    return r


first = run()
out = first.stdout
check(re.search(r"^\s+0\.2 s\s", out, re.M) and re.search(r"^\s+0\.4 s\s", out, re.M), "a table row per budget")
m = re.search(r"^  transient_beams: ([0-9.eE+-]+)x", out, re.M)
check(m is not None, "the equal-CPU efficiency ratio line")
if m:
    check(math.isfinite(float(m.group(1))) and float(m.group(1)) > 0, f"a finite positive ratio, got {m.group(1)}")
check(re.search(r"early light only \(bins 0:\d+\): transient_beams [0-9.]+x", out), "the early band's ratio")
check(re.search(r"late light only \(bins \d+:32\): transient_beams [0-9.]+x", out), "the late band's ratio")
check("no shared range" not in out and "<=" not in out, "never 'no shared range' or a '<=' bound")
check(re.search(r"its own relMSE, estimated from its two halves: [0-9.e-]+", out), "the reference's own error")
for name in ("table.txt", "results.csv", "relmse_vs_cpu.png"):
    path = os.path.join(work, "out", name)
    check(os.path.exists(path) and os.path.getsize(path) > 0, f"{name} written")
with open(os.path.join(work, "out", "results.csv")) as f:
    rows = list(csv.DictReader(f))
check(len(rows) == 4, f"4 rows (2 integrators x 2 budgets), got {len(rows)}")
for r in rows:
    check(int(r["passes"]) >= 1 and float(r["cpu_seconds"]) > 0 and float(r["relmse"]) > 0, f"a measured row: {r}")
check(not os.path.exists(os.path.join(work, "out", "renders")), "the budget renders are deleted once measured")
second = run(["--budgets", "0.2"])
check("reference: cached" in second.stderr, "the second run takes the reference from the cache")
# A fresh machine has no git (tools/check-fresh-machine.sh found compare failing there):
# a PATH with python3 alone still compares, without a commit in the caption.
nogit = os.path.join(work, "nogit")
os.makedirs(nogit)
os.symlink(sys.executable, os.path.join(nogit, "python3"))
third = run(["--budgets", "0.2"], path=nogit)
check("(commit " not in third.stdout, "no commit in the caption without git")
if failures:
    sys.exit(f"{len(failures)} failure(s)")
print("ok")
