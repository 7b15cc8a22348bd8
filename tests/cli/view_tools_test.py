#!/usr/bin/python3
"""End-to-end test of the viewing tools on a tiny synthetic volume.

  view_tools_test.py FEMTO PLOT_PROFILES WORKDIR

Writes a black (5, 7, 9, 3) float32 volume with one hot voxel, runs
`femto frames|streak|integrate|profile` and tools/view/plot_profiles.py on it
and checks what they wrote: the hot voxel appears in the right frame at the
right pixel and nowhere else, the streak image is width x bins with the hot
value at (x, bin), the running integral is numpy's cumsum, bad input gives one
error line. Exits 77 (skipped) when numpy or matplotlib is missing.
"""
import csv
import os
import shutil
import subprocess
import sys

try:
    import numpy as np
    import matplotlib.image
except ImportError:
    print("numpy/matplotlib missing: skipped")
    sys.exit(77)

FEMTO, PLOT, WORK = sys.argv[1:4]
H, W, BINS = 5, 7, 9
HOT_Y, HOT_X, HOT_BIN = 3, 2, 6
failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAIL:", message)


def run(*args, expect=0):
    result = subprocess.run([FEMTO, *args], capture_output=True, text=True)
    check(result.returncode == expect,
          f"femto {' '.join(args)}: exit {result.returncode}, expected {expect}\n{result.stdout}{result.stderr}")
    return result


def png(path):
    """An 8-bit PNG as floats in [0, 1], shape (height, width, channels)."""
    return matplotlib.image.imread(path)


shutil.rmtree(WORK, ignore_errors=True)
os.makedirs(WORK)
volume_path = os.path.join(WORK, "hot.npy")
volume = np.zeros((H, W, BINS, 3), np.float32)
volume[HOT_Y, HOT_X, HOT_BIN] = [1.0, 1.0, 1.0]
np.save(volume_path, volume)

# Frames: one PNG per bin, W x H, the hot voxel white in its frame only.
frames_dir = os.path.join(WORK, "frames")
run("frames", volume_path, "-o", frames_dir, "--contact-sheet", "--sheet-frames", "3")
names = sorted(n for n in os.listdir(frames_dir) if n.startswith("frame_"))
check(names == [f"frame_{b:05d}.png" for b in range(BINS)], f"frame files: {names}")
for b in range(BINS):
    image = png(os.path.join(frames_dir, f"frame_{b:05d}.png"))
    check(image.shape[:2] == (H, W), f"frame {b} has shape {image.shape}")
    lit = np.argwhere(image[:, :, :3].max(axis=2) > 0)
    expected = [[HOT_Y, HOT_X]] if b == HOT_BIN else []
    check(lit.tolist() == expected, f"frame {b}: lit pixels {lit.tolist()}, expected {expected}")
# 99.5th percentile of the one non-black voxel maps it to white (within the
# histogram's 2 % bucket, so at least 250/255).
hot = png(os.path.join(frames_dir, f"frame_{HOT_BIN:05d}.png"))[HOT_Y, HOT_X, :3]
check(hot.min() >= 250 / 255, f"hot pixel shows {hot}, expected white")
sheet = png(os.path.join(frames_dir, "contact_sheet.png"))
check(sheet.shape[:2] == (H, 3 * W + 2 * 2), f"contact sheet has shape {sheet.shape}")

# A sub-range, every other bin: only those frames, stale ones removed.
run("frames", volume_path, "-o", frames_dir, "--bins", "2:9", "--every", "2", "--exposure", "0")
names = sorted(n for n in os.listdir(frames_dir) if n.startswith("frame_"))
check(names == [f"frame_{b:05d}.png" for b in (2, 4, 6, 8)], f"--bins 2:9 --every 2 wrote {names}")

# Running integral: the hot pixel stays lit from its bin on.
run("frames", volume_path, "-o", frames_dir, "--running-integral", "--exposure", "0")
for b in range(BINS):
    lit = png(os.path.join(frames_dir, f"frame_{b:05d}.png"))[HOT_Y, HOT_X, :3].min() > 0.9
    check(lit == (b >= HOT_BIN), f"running integral frame {b}: hot pixel lit={lit}")

# GIF and MP4, when ffmpeg is there.
if shutil.which("ffmpeg"):
    run("frames", volume_path, "-o", frames_dir, "--gif", "--mp4", "--fps", "4")
    for name in ("sequence.gif", "sequence.mp4"):
        path = os.path.join(frames_dir, name)
        check(os.path.exists(path) and os.path.getsize(path) > 0, f"{name} not written")
else:
    result = run("frames", volume_path, "-o", frames_dir, "--gif", expect=1)
    check("needs ffmpeg" in result.stderr, f"missing ffmpeg: {result.stderr}")

# Streak image: width x bins, the hot value at (x, bin).
stem = os.path.join(WORK, "streak")
run("streak", volume_path, "--row", str(HOT_Y), "-o", stem, "--exposure", "0")
check(os.path.exists(stem + ".exr"), "streak EXR not written")
streak = png(stem + ".png")
check(streak.shape[:2] == (BINS, W), f"streak PNG has shape {streak.shape}, expected ({BINS}, {W})")
lit = np.argwhere(streak[:, :, :3].max(axis=2) > 0).tolist()
check(lit == [[HOT_BIN, HOT_X]], f"streak lit at (bin, x) {lit}")

# Column streak: bins across, height down, the hot value at (bin, y); another column is black.
stem = os.path.join(WORK, "streak_col")
run("streak", volume_path, "--column", str(HOT_X), "-o", stem, "--exposure", "0")
streak = png(stem + ".png")
check(streak.shape[:2] == (H, BINS), f"column streak PNG has shape {streak.shape}, expected ({H}, {BINS})")
lit = np.argwhere(streak[:, :, :3].max(axis=2) > 0).tolist()
check(lit == [[HOT_Y, HOT_BIN]], f"column streak lit at (y, bin) {lit}")
run("streak", volume_path, "--column", str((HOT_X + 1) % W), "-o", stem, "--exposure", "0")
check(png(stem + ".png")[:, :, :3].max() == 0, "another column's streak is not black")

# Running integral volume = numpy's cumulative sum.
integral_path = os.path.join(WORK, "hot_integral.npy")
run("integrate", volume_path, "-o", integral_path)
integral = np.load(integral_path)
check(integral.shape == volume.shape and integral.dtype == np.float32, f"integral {integral.shape} {integral.dtype}")
check(np.allclose(integral, np.cumsum(volume, axis=2), rtol=1e-6, atol=0), "integral is not the cumsum")

# With the film's sidecar (time window): the profile gets an OPL column and
# the integral volume a copy of the sidecar.
with open(os.path.join(WORK, "hot.json"), "w") as f:
    f.write('{"format": "femto transient volume", "version": 1, "width": %d, "height": %d, "bins": %d, '
            '"time_unit": "opl", "start_opl": 3, "bin_width_opl": 0.5, "end_opl": %g, "film_width": %d, '
            '"film_height": %d, "crop": [0, 0, %d, %d], "time_filter": "box"}' % (W, H, BINS, 3 + 0.5 * BINS, W, H, W, H))
run("integrate", volume_path, "-o", integral_path)
check(os.path.exists(os.path.join(WORK, "hot_integral.json")), "integrate did not copy the sidecar")

# Profile CSV: one row per bin, the hot value in its bin, OPL at bin centres.
csv_path = os.path.join(WORK, "profile.csv")
run("profile", volume_path, "--pixel", f"{HOT_X},{HOT_Y}", "--pixel", "0,0", "-o", csv_path)
with open(csv_path) as f:
    rows = list(csv.DictReader(f))
check(len(rows) == BINS, f"profile has {len(rows)} rows")
column = f"r_{HOT_X}_{HOT_Y}"
check([float(r[column]) for r in rows] == [1.0 if b == HOT_BIN else 0.0 for b in range(BINS)], "profile values")
check(all(float(r["r_0_0"]) == 0.0 for r in rows), "black pixel profile")
check([float(r["opl"]) for r in rows] == [3 + 0.5 * (b + 0.5) for b in range(BINS)], "profile OPL column")

# Profile plot: two volumes on one plot with an analytic overlay.
analytic = os.path.join(WORK, "analytic.csv")
with open(analytic, "w") as f:
    f.write("time,value\n0,0\n9,1\n")
plot = os.path.join(WORK, "profiles.png")
result = subprocess.run([sys.executable, PLOT, volume_path, integral_path, "--label", "pulse", "--label", "step",
                         "--pixel", f"{HOT_X},{HOT_Y}", "--analytic", analytic, "-o", plot],
                        capture_output=True, text=True)
check(result.returncode == 0 and os.path.getsize(plot) > 0, f"plot_profiles.py failed: {result.stderr}")

# Bad input: one error line, exit 1 (2 for command-line usage errors).
float64_path = os.path.join(WORK, "float64.npy")
np.save(float64_path, np.zeros((H, W, BINS, 3)))
text_path = os.path.join(WORK, "text.npy")
with open(text_path, "w") as f:
    f.write("hello\n")
for args, fragment in [
    (("streak", volume_path, "--row", str(H)), f"--row {H} is outside the volume, whose rows are 0 to {H - 1}"),
    (("streak", volume_path, "--column", str(W)), f"--column {W} is outside the volume, whose columns are 0 to {W - 1}"),
    (("frames", float64_path), "is not a float32 C-order (height, width, bins, 3) volume"),
    (("frames", text_path), "is not a version 1 .npy file"),
    (("frames", volume_path, "--bins", "5:3"), "--bins 5:3 selects no bins"),
    (("frames", volume_path, "--bins", "x"), "--bins expects FIRST:END"),
    (("profile", volume_path, "--pixel", "7,0"), "--pixel 7,0 is outside the volume (7x5)"),
    (("integrate", volume_path, "-o", volume_path), "would overwrite its input"),
]:
    result = run(*args, expect=1)
    lines = result.stderr.strip().split("\n")
    check(len(lines) == 1 and lines[0].startswith("error: ") and fragment in lines[0],
          f"femto {' '.join(args)}: stderr {result.stderr!r}, expected one line with {fragment!r}")

# A malformed value is a usage error (docs/cli.md: exit 2), not a failed command.
result = run("profile", volume_path, "--pixel", "5", expect=2)
check("--pixel expects X,Y" in result.stderr, f"femto profile --pixel 5: stderr {result.stderr!r}")

if failures:
    print(f"{len(failures)} check(s) failed")
    sys.exit(1)
print("all viewing-tool checks passed")
