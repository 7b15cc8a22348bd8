#!/usr/bin/python3
"""Put transient volumes side by side in one volume, so that `femto frames`
makes one sequence (one exposure, one GIF) of all of them.

    /usr/bin/python3 tools/figures/side_by_side_volume.py out/fig1/side.npy \
        out/fig1/path.npy out/fig1/beams.npy out/fig1/reference.npy --merge 4

Every volume (height, width, bins, 3) must have the same height and bins.
--merge K averages each run of K bins into one (bins must divide by K): fewer
frames for a small GIF, and each frame the mean over its K bins, as
frame_strip.py's --average calms single-bin noise. --gutter G puts G black
columns between the volumes. --each-exposure scales every volume so that
its own 99.5th percentile of lit luminance is 1 (a continuous source's
running integral is far brighter than its Dirac sequence: one exposure for
both would leave the Dirac side black), as frame_strip.py's --row-exposure.
When all inputs' sidecars (<stem>.json) give the same window, the output gets
one too (bins merged), so `femto frames --label` can stamp frames with OPL.
"""
import argparse
import json
import os

import numpy as np


def merge_bins(volume, merge):
    """Average each run of `merge` bins of a (height, width, bins, 3) volume."""
    height, width, bins, channels = volume.shape
    if bins % merge:
        raise ValueError(f"{bins} bins are not a multiple of --merge {merge}")
    return np.asarray(volume, dtype=np.float32).reshape(height, width, bins // merge, merge, channels).mean(axis=3)


def unit_exposure(volume, percentile=99.5):
    """`volume` scaled so the given percentile of its nonzero luminance is 1
    (unchanged when it is all black)."""
    luminance = volume @ np.array([0.2126, 0.7152, 0.0722], dtype=np.float32)
    lit = luminance[luminance > 0]
    return volume / np.percentile(lit, percentile) if lit.size else volume


def side_by_side(volumes, merge=1, gutter=2):
    """The volumes left to right, bins merged, `gutter` black columns between."""
    parts = [merge_bins(v, merge) for v in volumes]
    shapes = {(p.shape[0], p.shape[2], p.shape[3]) for p in parts}
    if len(shapes) != 1:
        raise ValueError(f"the volumes differ in height, bins or channels: {sorted(shapes)}")
    black = np.zeros((parts[0].shape[0], gutter) + parts[0].shape[2:], dtype=np.float32)
    row = [parts[0]]
    for part in parts[1:]:
        row += [black, part]
    return np.concatenate(row, axis=1)


def sidecar(volume_paths, row, merge):
    """The sidecar (docs/transient-film.md) of the side-by-side volume `row`
    when every input's says the same window (then `femto frames --label`
    can stamp its frames with OPL), else None."""
    windows = []
    for path in volume_paths:
        info_path = os.path.splitext(path)[0] + ".json"
        if not os.path.exists(info_path):
            return None
        with open(info_path) as f:
            info = json.load(f)
        windows.append((info["start_opl"], info["bin_width_opl"]))
    if len(set(windows)) != 1:
        return None
    start, width = windows[0]
    height, total_width, bins, _ = row.shape
    return {"format": "femto transient volume", "version": 1, "width": total_width, "height": height, "bins": bins,
            "time_unit": "opl", "start_opl": start, "bin_width_opl": width * merge,
            "end_opl": start + width * merge * bins, "film_width": total_width, "film_height": height,
            "crop": [0, 0, total_width, height], "time_filter": "box"}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("output", help=".npy to write")
    parser.add_argument("volumes", nargs="+", help=".npy volumes, left to right")
    parser.add_argument("--merge", type=int, default=1, help="average runs of K bins")
    parser.add_argument("--gutter", type=int, default=2, help="black columns between volumes")
    parser.add_argument("--each-exposure", action="store_true", help="scale each volume to its own exposure")
    args = parser.parse_args()
    try:
        volumes = [np.load(p, mmap_mode="r") for p in args.volumes]
        if args.each_exposure:
            volumes = [unit_exposure(np.asarray(v, dtype=np.float32)) for v in volumes]
        row = side_by_side(volumes, args.merge, args.gutter)
    except ValueError as e:
        raise SystemExit(f"side_by_side_volume: {' '.join(args.volumes)}: {e}")
    np.save(args.output, row)
    print(f"wrote {args.output}")
    info = sidecar(args.volumes, row, args.merge)
    info_path = os.path.splitext(args.output)[0] + ".json"
    if info:
        with open(info_path, "w") as f:
            json.dump(info, f, indent=2)
    elif os.path.exists(info_path):
        os.remove(info_path)  # a stale one would label the frames wrongly


if __name__ == "__main__":
    main()
