#!/usr/bin/env python3
"""One progress bar for a whole render (issue 16): a progressive render of
several passes that writes frames draws a single bar whose fraction never goes
back (it used to restart at every pass), reaching 100 % once, after the frames.

  progress_bar_test.py FEMTO SCENE WORK_DIR

The bar is drawn only on a terminal: util-linux's `script` gives the render a
pseudo-terminal. Exit 77 (skipped) without it.
"""
import os
import re
import shutil
import subprocess
import sys

femto, scene, work = sys.argv[1], sys.argv[2], sys.argv[3]
if not shutil.which("script"):
    print("`script` (util-linux) is not installed: cannot give femto a terminal")
    sys.exit(77)
os.makedirs(work, exist_ok=True)
command = " ".join([femto, "render", scene, "-D", "integrator=transient_beams", "-D", "passes=3",
                    "-D", "resolution=16", "-D", "bins=64", "-D", "spp=2", "-D", "photon_count=5000", "-D", "frames=true",
                    "-o", os.path.join(work, "progress.exr")])
run = subprocess.run(["script", "-qec", command, "/dev/null"], capture_output=True, text=True, timeout=300)
print(run.stdout[-2000:])
if run.returncode != 0:
    sys.exit(f"render failed: exit {run.returncode}")
fractions = [float(f) for f in re.findall(r"Rendering \[[# ]*\]\s+([0-9.]+)%", run.stdout)]
finals = re.findall(r"Rendering \[[# ]*\]\s+[0-9.]+% \([0-9hms]+\)\x1b\[K\r?\n", run.stdout)
problems = []
if not fractions:
    problems.append("no progress bar drawn on a terminal")
if any(b < a for a, b in zip(fractions, fractions[1:])):
    problems.append(f"the bar went back: {fractions}")
if fractions and fractions[-1] != 100.0:
    problems.append(f"the bar ended at {fractions[-1]} %")
if len(finals) != 1:
    problems.append(f"{len(finals)} finished bars (one per pass?), expected one for the whole render")
if not os.path.isdir(os.path.join(work, "progress_frames")) and not any(
        name.startswith("progress") and "frame" in name for name in os.listdir(work)):
    problems.append("no frames were written: the test must cover frame writing")
for p in problems:
    print("FAIL:", p)
sys.exit(1 if problems else 0)
