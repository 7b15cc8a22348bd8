#!/usr/bin/env python3
"""`femto render a.xml b.xml ...` and --resume, as a dataset job runs them:

- several scenes (positional and --scene-list) render into the folder -o
  names, each file byte-equal to the scene rendered alone;
- a scene that fails is reported and the others still render (exit 1);
- -o naming an image and two scenes with one output name are usage errors;
- --resume skips scenes a finished render wrote, re-renders one whose file
  was removed or whose settings changed, and a job killed mid-way and resumed
  writes the same bytes as one that ran through.

  many_scenes_test.py FEMTO PLANE_SCENE WORK_DIR
"""
import os
import shutil
import signal
import subprocess
import sys
import time

femto, plane, work = sys.argv[1], sys.argv[2], sys.argv[3]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
failures = []
OPTS = ["--no-progress", "-t", "2", "-D", "resolution=24", "-D", "bins=32", "-D", "spp=4"]


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAIL:", message)


def femto_render(args, expect=0):
    r = subprocess.run([femto, "render"] + args, capture_output=True, text=True, timeout=300)
    check(r.returncode == expect, f"femto render {' '.join(args)} exited {r.returncode} (expected {expect}):\n"
                                  f"{r.stdout}{r.stderr}")
    return r


def files(folder):
    return sorted(f for f in os.listdir(folder) if not f.endswith(".femto-done"))


def same_bytes(a, b, names):
    for name in names:
        with open(os.path.join(a, name), "rb") as x, open(os.path.join(b, name), "rb") as y:
            check(x.read() == y.read(), f"{a}/{name} differs from {b}/{name}")


# Five scenes: the plane at five distances (their own names).
scenes = []
text = open(plane).read()
for k in range(5):
    path = os.path.join(work, f"plane{k}.xml")
    with open(path, "w") as f:
        f.write(text.replace('origin="0, 0, 2"', f'origin="0, 0, {2 + 0.25 * k}"'))
    scenes.append(path)
list_file = os.path.join(work, "list.txt")
with open(list_file, "w") as f:
    f.write("# the last three\n\n" + "\n".join(os.path.basename(s) for s in scenes[2:]) + "\n")

# Alone, one by one.
alone = os.path.join(work, "alone")
for s in scenes:
    femto_render([s, "-o", os.path.join(alone, os.path.basename(s)[:-4] + ".exr")] + OPTS)
# Together: two positional, three from the list.
together = os.path.join(work, "together")
r = femto_render(scenes[:2] + ["--scene-list", list_file, "-o", together] + OPTS)
check(r.stdout.count("rendered ") == 5, f"five summary lines expected:\n{r.stdout}")
check(files(together) == files(alone), f"other files: {files(together)} against {files(alone)}")
same_bytes(alone, together, files(alone))

# A broken scene among them: reported, the others rendered, exit 1.
broken = os.path.join(work, "broken.xml")
with open(broken, "w") as f:
    f.write('<scene version="3.0.0">\n  <integrator type="no_such_integrator"/>\n</scene>\n')
mixed = os.path.join(work, "mixed")
r = femto_render([scenes[0], broken, scenes[1], "-o", mixed] + OPTS, expect=1)
check("broken.xml:2" in r.stderr and "1 of 3 scenes failed" in r.stderr, f"the failure is named:\n{r.stderr}")
check(os.path.exists(os.path.join(mixed, "plane1.exr")), "the scene after the broken one rendered")

# Usage errors, before any work.
r = femto_render(scenes[:2] + ["-o", os.path.join(work, "x.exr")] + OPTS, expect=2)
check("names a folder" in r.stderr, f"-o x.exr with two scenes: {r.stderr}")
twin = os.path.join(work, "twin")
os.makedirs(twin)
shutil.copy(scenes[0], os.path.join(twin, "plane0.xml"))
r = femto_render([scenes[0], os.path.join(twin, "plane0.xml"), "-o", os.path.join(work, "t")] + OPTS, expect=2)
check("would both write" in r.stderr, f"two scenes, one output name: {r.stderr}")

# --resume: a second run skips all; a removed file or other settings render again.
resumed = os.path.join(work, "resumed")
femto_render(scenes + ["-o", resumed, "--resume"] + OPTS)
stamp = os.path.getmtime(os.path.join(resumed, "plane0.npy"))
r = femto_render(scenes + ["-o", resumed, "--resume"] + OPTS)
check(r.stdout.count("skipped ") == 5 and "rendered " not in r.stdout, f"all five skipped:\n{r.stdout}")
check(os.path.getmtime(os.path.join(resumed, "plane0.npy")) == stamp, "a skipped scene's files are untouched")
os.remove(os.path.join(resumed, "plane3.npy"))
r = femto_render(scenes + ["-o", resumed, "--resume"] + OPTS)
check(r.stdout.count("skipped ") == 4 and "rendered " + os.path.join(resumed, "plane3.exr") in r.stdout,
      f"only plane3 again:\n{r.stdout}")
r = femto_render(scenes + ["-o", resumed, "--resume", "--seed", "7"] + OPTS)
check(r.stdout.count("rendered ") == 5, f"another seed renders all again:\n{r.stdout}")

# Killed mid-way (after the second scene finished), then resumed: the same
# bytes as a run that went through. The scenes are slow enough (4096 spp) to
# be caught in the middle.
slow = OPTS + ["-D", "spp=2048"]
through = os.path.join(work, "through")
femto_render(scenes + ["-o", through, "--resume"] + slow)
# Under load the poll below may wake only after every scene is done: such
# an attempt stopped nothing part way, and another is made (at most 4).
for attempt in range(4):
    killed = os.path.join(work, f"killed{attempt}")
    p = subprocess.Popen([femto, "render"] + scenes + ["-o", killed, "--resume"] + slow,
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline and not os.path.exists(os.path.join(killed, "plane1.femto-done")):
        time.sleep(0.01)
    p.send_signal(signal.SIGKILL)
    p.wait()
    done = [s for s in range(5) if os.path.exists(os.path.join(killed, f"plane{s}.femto-done"))]
    if 2 <= len(done) < 5:
        break
    print(f"attempt {attempt}: killed after scenes {done}, not part way; again")
check(2 <= len(done) < 5, f"killed after scenes {done}: the test needs a job stopped part way")
r = femto_render(scenes + ["-o", killed, "--resume"] + slow)
check(r.stdout.count("skipped ") == len(done), f"the {len(done)} finished scenes skipped:\n{r.stdout}")
check(files(killed) == files(through), f"other files after resuming: {files(killed)} against {files(through)}")
same_bytes(through, killed, files(through))

print(f"{len(failures)} failures" if failures else "many scenes: all checks passed")
sys.exit(1 if failures else 0)
