#!/usr/bin/python3
"""How much of a relMSE against a noisy reference is the reference's own.

  tools/compare/reference_floor.py REFERENCE.npy RENDER_1.npy RENDER_2.npy [...]

RENDER_i: renders of one scene and budget with different seeds (femto's
volumes, H x W x bins x channels, as the reference). relMSE is the media
suite's (media_suite.relmse): mean of (x - ref)^2 / (ref^2 + eps mean(ref)^2).
Splits it into

  variance   one render's variance term: the mean over pairs of the same
             weighted (x_i - x_j)^2, halved (independent seeds);
  floor      relMSE(mean of the N renders) - variance / N: what no number of
             renders removes, the reference's Monte Carlo error plus the
             renders' squared bias, in the same weights.

A floor that stays put while the budget (and a kernel radius) changes, and
that lies evenly over the image where the renders' own variance does not, is
the reference's. The block table gives both over 16 x 16 blocks of the image.
tools/compare/tof_peer.py prints the split for each budget it renders.
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "bench"))
import media_suite  # noqa: E402  (relmse() and its epsilon)


def weights(ref):
    """relMSE's per-voxel weights (media_suite.relmse)."""
    return 1.0 / (ref**2 + media_suite.EPSILON * ref.mean() ** 2)


def split(volumes, ref, w=None, keep=None):
    """(one render's variance, relMSE of the renders' mean, floor) and the
    per-voxel floor and variance maps behind them. `w`: relMSE's weights
    (default weights(ref)); `keep`: a mask of the cells scored (default all)."""
    w = weights(ref) if w is None else w
    n = len(volumes)
    mean = sum(volumes) / n
    pair_maps = [(volumes[i] - volumes[j]) ** 2 * w / 2.0 for i in range(n) for j in range(i + 1, n)]
    variance_map = sum(pair_maps) / len(pair_maps)
    error_map = (mean - ref) ** 2 * w
    floor_map = error_map - variance_map / n
    scored = (lambda m: m) if keep is None else (lambda m: m[keep])
    return (float(scored(variance_map).mean()), float(scored(error_map).mean()), float(scored(floor_map).mean()),
            floor_map, variance_map)


def block_means(voxel_map, blocks=16):
    """Means over blocks x blocks tiles of the image (all bins and channels)."""
    h, w = voxel_map.shape[:2]
    image = voxel_map.reshape(h, w, -1).mean(axis=2)
    bh, bw = h // blocks, w // blocks
    return image[: bh * blocks, : bw * blocks].reshape(blocks, bh, blocks, bw).mean(axis=(1, 3))


def main(argv):
    if len(argv) < 3:
        sys.exit(__doc__)
    ref = np.load(argv[0]).astype(np.float64)
    volumes = [np.load(f).astype(np.float64) for f in argv[1:]]
    variance, of_mean, floor, floor_map, variance_map = split(volumes, ref)
    one = float(np.median([media_suite.relmse(v, ref) for v in volumes]))
    print(f"relMSE of one render (median of {len(volumes)}): {one:.3g}")
    print(f"variance of one render: {variance:.3g}; relMSE of the mean: {of_mean:.3g}; floor: {floor:.3g}")
    fb, vb = block_means(floor_map), block_means(variance_map)
    print(f"over 16 x 16 blocks: floor {fb.min():.2f} to {fb.max():.2f} (quartiles "
          f"{np.percentile(fb, 25):.2f}, {np.percentile(fb, 75):.2f}); one render's variance "
          f"{vb.min():.2f} to {vb.max():.2f} (quartiles {np.percentile(vb, 25):.2f}, {np.percentile(vb, 75):.2f})")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
