"""A transient volume larger than the memory limit comes back as a memory map
of the streamed .npy, and the render's peak memory stays far below the
volume's size. Measured in a child process (peak RSS of this one is shared
with every other test)."""
import json
import os
import subprocess
import sys
import textwrap

from conftest import FOG_BOX

# 128 x 128 pixels x 64 bins x RGB float32 = 12.6 MB, six times the limit;
# one thread: two 32x32 tiles in flight, 1.5 MB.
CHILD = textwrap.dedent("""
    import json, sys
    import numpy as np
    import femto

    def status(key):
        for line in open("/proc/self/status"):
            if line.startswith(key + ":"):
                return int(line.split()[1]) * 1024

    scene = femto.load_file(sys.argv[1], resolution=128, bins=64, bin_width=0.16, frames=False, medium="none", spp=1)
    femto.load_file(sys.argv[1], resolution=8, bins=8, frames=False).render()  # warm up: every library loaded
    limit = int(sys.argv[2])
    before = status("VmRSS")
    with open("/proc/self/clear_refs", "w") as f:
        f.write("5")  # resets the peak (VmHWM) to the current RSS
    result = scene.render(threads=1, memory_limit=limit)
    peak = status("VmHWM")
    volume = result.transient
    print(json.dumps({"mapped": isinstance(volume, np.memmap), "nbytes": int(volume.nbytes), "limit": limit,
                      "growth": peak - before, "shape": list(volume.shape), "sum": float(volume.sum())}))
""")


def run_child(limit):
    env = dict(os.environ)
    out = subprocess.run([sys.executable, "-c", CHILD, str(FOG_BOX), str(limit)], capture_output=True, text=True,
                         env=env, check=True)
    return json.loads(out.stdout.strip().splitlines()[-1])


def test_large_volume_is_memory_mapped_and_rss_bounded():
    report = run_child(limit=2 << 20)
    assert report["shape"] == [128, 128, 64, 3]
    assert report["nbytes"] >= 6 * report["limit"]
    assert report["mapped"]
    assert report["sum"] > 0  # the map holds the render
    # Tiles in flight and the steady images are ~2 MB; a copy of the volume would add 12.6 MB.
    assert report["growth"] < report["nbytes"] / 3, report
