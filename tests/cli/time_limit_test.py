#!/usr/bin/env python3
"""`femto render --time-limit` as a user runs it: a time-limited render of the
fog box (transient_path in passes of 1 spp; transient_beams in its passes)
writes a sidecar with the passes reached, prints the command that renders the
same image without a limit, and that command writes the same bytes. No time is
asserted: the count reached is read back and rendered again.

  time_limit_test.py FEMTO FOG_SCENE WORK_DIR
"""
import json
import os
import re
import shlex
import subprocess
import sys

femto, scene, work = sys.argv[1], sys.argv[2], sys.argv[3]
os.makedirs(work, exist_ok=True)
failures = []
TINY = ["-D", "resolution=12", "-D", "bins=16", "-D", "bin_width=0.64", "-D", "frames=false", "--no-progress", "-t", "2"]
# (the scene's settings, the time-limited render's own): the summary's --passes/--spp/--seed replace the latter.
CASES = {
    "transient_path": (["-D", "integrator=transient_path"], ["--spp", "1"]),
    "transient_beams": (["-D", "integrator=transient_beams", "-D", "photon_count=2000", "-D", "beam_photon_count=300",
                         "-D", "spp=2"], []),
}


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAIL:", message)


def render(args):
    r = subprocess.run([femto, "render", scene] + TINY + args, capture_output=True, text=True, timeout=300)
    check(r.returncode == 0, f"femto render {' '.join(args)} exited {r.returncode}:\n{r.stdout}{r.stderr}")
    return r.stdout


for name, (args, own) in CASES.items():
    limited = os.path.join(work, f"{name}_limited.exr")
    out = render(args + own + ["--seed", "3", "--time-limit", "0.5s", "--time-clock", "cpu", "-o", limited])
    with open(os.path.splitext(limited)[0] + ".json") as f:
        sidecar = json.load(f)
    check(sidecar.get("time_limit_seconds") == 0.5 and sidecar.get("time_clock") == "cpu",
          f"{name}: the sidecar does not record the limit: {sidecar}")
    passes, spp = sidecar["passes"], sidecar["spp_per_pass"]
    check(passes >= 1 and sidecar["spp"] == passes * spp, f"{name}: sidecar counts {sidecar}")
    # The summary names the count and the equivalent command's options.
    m = re.search(r"the same image without it: (--passes (\d+) --spp (\d+) --seed (\d+))", out)
    check(m is not None, f"{name}: no 'the same image without it' in:\n{out}")
    if not m:
        continue
    check((int(m.group(2)), int(m.group(3)), int(m.group(4))) == (passes, spp, 3),
          f"{name}: the summary's {m.group(1)} disagrees with the sidecar {sidecar}")
    counted = os.path.join(work, f"{name}_counted.exr")
    render(args + shlex.split(m.group(1)) + ["-o", counted])
    for ext in (".npy", ".exr"):
        a, b = (open(os.path.splitext(p)[0] + ext, "rb").read() for p in (limited, counted))
        check(a == b, f"{name}: {ext} of the time-limited render ({passes} passes) differs from --passes {passes}")
    print(f"{name}: {passes} passes of {spp} spp reached; --passes {passes} renders the same bytes")

if failures:
    sys.exit(f"{len(failures)} failure(s)")
print("ok")
