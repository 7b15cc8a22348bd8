#!/usr/bin/python3
"""The NLOS gallery figure: a capture's streak image (one row of wall points
against OPL) beside the max-projections of its FBP and phasor-field
reconstructions (tools/nlos/reconstruct.py).

Usage: gallery_figure.py CAPTURE.npy OUT.png --box x0,y0,z0,x1,y1,z1 [--row J]
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import reconstruct  # noqa: E402


def main():
    p = argparse.ArgumentParser()
    p.add_argument("capture")
    p.add_argument("output")
    p.add_argument("--box", type=lambda s: reconstruct.parse_vector(s, 6), required=True)
    p.add_argument("--voxels", type=lambda s: reconstruct.parse_vector(s, 3).astype(int), default=np.array([48, 48, 24]))
    p.add_argument("--row", type=int, default=None, help="the wall row of the streak image (default: the middle)")
    args = p.parse_args()
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    capture, start, width = reconstruct.load_capture(args.capture)
    points = reconstruct.wall_points(capture.shape[0], capture.shape[1], np.zeros(3), np.ones(2))
    row = capture.shape[0] // 2 if args.row is None else args.row
    fig, axes = plt.subplots(1, 3, figsize=(12, 4))
    streak = capture[row]  # [wall x, t]
    end = start + width * capture.shape[2]
    axes[0].imshow(streak.T ** 0.5, aspect="auto", origin="lower", cmap="inferno",
                   extent=[-1.0, 1.0, start, end])
    axes[0].set(title=f"capture: wall row {row}, sqrt(radiance)", xlabel="wall x", ylabel="OPL from the wall")
    box = args.box
    for ax, method, name in zip(axes[1:], ("fbp", "phasor"), ("filtered back-projection", "phasor fields")):
        volume = reconstruct.reconstruct(capture, start, width, points, box, args.voxels, None, method)
        image = volume.max(axis=0)
        ax.imshow(image / image.max(), origin="lower", cmap="inferno", extent=[box[0], box[3], box[1], box[4]])
        ax.set(title=f"{name}: max over depth", xlabel="x", ylabel="y")
    fig.tight_layout()
    fig.savefig(args.output, dpi=100)


if __name__ == "__main__":
    main()
