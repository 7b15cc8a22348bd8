#!/usr/bin/env python3
"""Resources and signals of `femto render` (issue 16), run as a user would.

  resource_limits_test.py FEMTO SCENE WORK_DIR

- A film of 2^20 time bins renders with the tiles' memory under the render
  loop's documented bound (TileMemoryBound, 1 GiB): the tile side shrinks.
  Before, one 16x16 tile held 3 GiB. Peak RSS of the child is measured.
- --resolution 65536x65536 is refused at once, naming the size, not with
  std::bad_alloc.
- SIGTERM, and a second Ctrl-C, leave no temporary file: the process dies by
  the signal (returncode -N), and the unfinished outputs are gone.
"""
import glob
import os
import resource
import signal
import subprocess
import sys
import time

femto, scene, work = sys.argv[1], sys.argv[2], sys.argv[3]
os.makedirs(work, exist_ok=True)
failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAIL:", message)


def run(args, **kw):
    return subprocess.run([femto, "render", scene, "--no-progress"] + args, capture_output=True, text=True, **kw)


# 1. 2^20 bins at 16x16 without a volume file: memory is the tiles' only.
GiB = 1 << 30
before = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
r = run(["-D", "bins=1048576", "-D", "volume=false", "-t", "2", "-o", os.path.join(work, "bins.exr")], timeout=300)
peak = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss * 1024  # ru_maxrss is in KiB on Linux
check(r.returncode == 0, f"2^20 bins: exit {r.returncode}: {r.stderr.strip()}")
check("bad_alloc" not in r.stderr, "2^20 bins: bad_alloc reached the user")
# The bound covers the tiles; the rest (Embree, TBB, images of 16x16 pixels)
# is far below 512 MiB (an empty render's RSS is about 140 MiB).
check(peak < GiB + 512 * (1 << 20), f"2^20 bins: peak RSS {peak / GiB:.2f} GiB above the 1 GiB tile bound + 0.5 GiB")
print(f"2^20 bins at 16x16: peak RSS {peak / GiB:.2f} GiB")

# 2. An image that cannot fit in memory is refused before rendering.
start = time.monotonic()
r = run(["--resolution", "65536x65536", "-o", os.path.join(work, "huge.exr")], timeout=60)
check(r.returncode == 1, f"65536x65536: exit {r.returncode}, expected 1")
check("65536x65536" in r.stderr and "GiB" in r.stderr and "bad_alloc" not in r.stderr,
      f"65536x65536: message does not name the size: {r.stderr.strip()}")
check(time.monotonic() - start < 30, "65536x65536: refused only after a long time")


# 3. Signals leave no temporary file.
def catches(pid, sig):
    try:
        with open(f"/proc/{pid}/status") as status:
            for line in status:
                if line.startswith("SigCgt:"):
                    return int(line.split()[1], 16) & (1 << (sig - 1)) != 0
    except OSError:
        pass
    return False


def signalled_render(name, signals):
    folder = os.path.join(work, name)
    os.makedirs(folder, exist_ok=True)
    for stale in glob.glob(os.path.join(folder, "*")) + glob.glob(os.path.join(folder, ".tmp-*")):
        os.remove(stale)
    # Minutes of work: 256 bins, 128x128 pixels, 4096 spp.
    p = subprocess.Popen([femto, "render", scene, "--no-progress", "-D", "bins=256", "-D", "resolution=128",
                          "-D", "spp=4096", "-o", os.path.join(folder, "out.exr")],
                         stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    deadline = time.monotonic() + 60
    # The volume's temporary exists once rendering started.
    while time.monotonic() < deadline and not (catches(p.pid, signals[0]) and glob.glob(os.path.join(folder, ".tmp-*"))):
        time.sleep(0.05)
    check(bool(glob.glob(os.path.join(folder, ".tmp-*"))), f"{name}: no temporary volume appeared while rendering")
    for sig in signals:
        p.send_signal(sig)
        time.sleep(0.2)
    try:
        _, err = p.communicate(timeout=60)
    except subprocess.TimeoutExpired:
        p.kill()
        check(False, f"{name}: did not end within 60 s of the signal")
        return
    left = glob.glob(os.path.join(folder, ".tmp-*"))
    check(p.returncode == -signals[-1], f"{name}: returncode {p.returncode}, expected {-signals[-1]} (killed by it)")
    check(not left, f"{name}: temporary files left: {left}")
    check(not os.path.exists(os.path.join(folder, "out.npy")), f"{name}: a volume was written")
    print(f"{name}: returncode {p.returncode}, temporaries left: {len(left)}")


signalled_render("sigterm", [signal.SIGTERM])
signalled_render("double_ctrl_c", [signal.SIGINT, signal.SIGINT])

sys.exit(1 if failures else 0)
