#!/usr/bin/python3
"""Checks a transient volume rendered from examples/transient-first-bounce/scene.xml
against the scene's closed form (see the comment in scene.xml).

Camera at height H_C looking straight down, point light at height H_L on the same
vertical, diffuse floor of reflectance RHO, light intensity I, box pulse
[offset, offset + width]. The image plane is parallel to the floor, so pixel
(i, j) sees exactly the floor square H_C * [u0, u1] x [v0, v1] and its range of
distances r from the vertical, [r_min, r_max]. With a box pixel filter a pixel is
the mean of `spp` samples at uniform points of that square. Checked:

1. Where the light lands in time (exact): every deposit of a pixel lies in the bins
   overlapping [opl(r_min) + offset, opl(r_max) + offset + width] (direct:
   opl = sqrt(r^2 + H_C^2) + sqrt(r^2 + H_L^2); depth: sqrt(r^2 + H_C^2), no pulse).
   Their mean arrival (energy-weighted, at bin centres) lies in
   [opl(r_min), opl(r_max)] + offset + width / 2, +- half a bin (each bit of
   light is counted at most half a bin from where it lands): the pulse's centre.
2. How much (exact): a pixel's total over its bins is a mean of values in
   [L(r_max), L(r_min)] (direct: L = RHO/pi * I * H_L / (r^2 + H_L^2)^1.5,
   decreasing in r), or exactly 1 (depth).
3. Direct only, the estimator's mean: the image mean is within 5 sigma of the
   footprint-averaged closed form, sigma^2 = sum_p Var_p(L) / spp / N^2 with
   Var_p the variance of L over pixel p's square (both by midpoint quadrature).

Tolerances: OPLs are computed in float32 by the renderer (relative error a few
ulps, < 1e-6 at OPL ~3), so bin edges get a slack of 1e-4 OPL; a pixel's total
is float32 arithmetic on 16 samples of a few float32 operations each (relative
rounding below ~2e-6), so totals get 2e-5 relative, ten times that.

usage: check_first_bounce.py VOLUME.npy MODE SPP PULSE_OFFSET PULSE_WIDTH
"""
import json
import math
import sys
from pathlib import Path

import numpy as np

H_C, H_L, RHO, INTENSITY, FOV_DEGREES = 1.0, 2.0, 0.5, 3.0, 60.0
OPL_SLACK = 1e-4
TOTAL_RTOL = 2e-5
SUBDIVISIONS = 24  # midpoint quadrature per pixel side: 1.2e-7 relative from 200 (0.005 sigma)


def radiance(r):
    return RHO / math.pi * INTENSITY * H_L / (r * r + H_L * H_L) ** 1.5


def arrival(r, mode):
    depth = np.sqrt(r * r + H_C * H_C)
    return depth if mode == "depth" else depth + np.sqrt(r * r + H_L * H_L)


def footprints(width, height):
    """Per pixel (y, x): the floor square's corners [x0, x1] x [y0, y1]."""
    tan_x = math.tan(math.radians(FOV_DEGREES) / 2)  # fov_axis "x"
    tan_y = tan_x * height / width
    xs = H_C * tan_x * (1 - 2 * np.arange(width + 1) / width)
    ys = H_C * tan_y * (1 - 2 * np.arange(height + 1) / height)
    return xs, ys


def r_range(a0, a1, b0, b1):
    lo_a = 0.0 if min(a0, a1) <= 0 <= max(a0, a1) else min(abs(a0), abs(a1))
    lo_b = 0.0 if min(b0, b1) <= 0 <= max(b0, b1) else min(abs(b0), abs(b1))
    return math.hypot(lo_a, lo_b), math.hypot(max(abs(a0), abs(a1)), max(abs(b0), abs(b1)))


def main():
    volume_path, mode, spp, offset, width = sys.argv[1], sys.argv[2], int(sys.argv[3]), float(sys.argv[4]), float(sys.argv[5])
    if mode == "depth":
        offset, width = 0.0, 0.0  # the depth mode records no emitter: no pulse
    volume = np.load(volume_path).astype(np.float64)
    info = json.loads(Path(volume_path).with_suffix(".json").read_text())
    start, bin_width, bins = info["start_opl"], info["bin_width_opl"], info["bins"]
    height, width_px = volume.shape[:2]
    assert volume.shape == (height, width_px, bins, 3), volume.shape
    xs, ys = footprints(info["film_width"], info["film_height"])
    cx, cy = info["crop"][0], info["crop"][1]

    failures = []
    totals = volume.sum(axis=2)  # (h, w, 3)
    quad_mean = np.zeros((height, width_px))
    quad_var = np.zeros((height, width_px))
    grid = (np.arange(SUBDIVISIONS) + 0.5) / SUBDIVISIONS
    centres = start + (np.arange(bins) + 0.5) * bin_width
    for y in range(height):
        for x in range(width_px):
            x0, x1, y0, y1 = xs[cx + x], xs[cx + x + 1], ys[cy + y], ys[cy + y + 1]
            r_min, r_max = r_range(x0, x1, y0, y1)
            lo = arrival(r_min, mode) + offset - OPL_SLACK
            hi = arrival(r_max, mode) + offset + width + OPL_SLACK
            first = max(int(math.floor((lo - start) / bin_width)), 0)
            last = min(int(math.floor((hi - start) / bin_width)), bins - 1)
            pixel = volume[y, x]
            outside = np.abs(pixel).sum() - np.abs(pixel[first:last + 1]).sum()
            if outside > 1e-6 * max(np.abs(pixel).sum(), 1e-30):
                failures.append(f"pixel ({x}, {y}): {outside:.3g} lands outside bins {first}..{last} "
                                f"(OPL {lo:.4f}..{hi:.4f})")
            energy = pixel[:, 0].sum()
            if energy > 0:
                centroid = (centres * pixel[:, 0]).sum() / energy
                c_lo = arrival(r_min, mode) + offset + width / 2 - bin_width / 2 - OPL_SLACK
                c_hi = arrival(r_max, mode) + offset + width / 2 + bin_width / 2 + OPL_SLACK
                if not c_lo <= centroid <= c_hi:
                    failures.append(f"pixel ({x}, {y}): mean arrival {centroid:.4f} outside [{c_lo:.4f}, {c_hi:.4f}]")
            if mode == "depth":
                expect_lo = expect_hi = 1.0
            else:
                expect_lo, expect_hi = radiance(r_max), radiance(r_min)
                px = x0 + (x1 - x0) * grid
                py = y0 + (y1 - y0) * grid
                values = radiance(np.sqrt(px[None, :] ** 2 + py[:, None] ** 2))
                quad_mean[y, x] = values.mean()
                quad_var[y, x] = values.var()
            for c in range(3):
                t = totals[y, x, c]
                if not (expect_lo * (1 - TOTAL_RTOL) <= t <= expect_hi * (1 + TOTAL_RTOL)):
                    failures.append(f"pixel ({x}, {y}) channel {c}: total {t:.6g} outside the closed form's "
                                    f"[{expect_lo:.6g}, {expect_hi:.6g}]")
    report = f"{mode}: {height}x{width_px} pixels, {bins} bins from OPL {start}: every pixel's arrival and total match"
    if mode == "direct":
        n = height * width_px
        sigma = math.sqrt(quad_var.sum() / spp) / n
        expected = quad_mean.mean()
        tolerance = 5 * sigma + TOTAL_RTOL * expected
        for c in range(3):
            mean = totals[:, :, c].mean()
            if abs(mean - expected) > tolerance:
                failures.append(f"channel {c}: image mean {mean:.7g}, closed form {expected:.7g} "
                                f"({abs(mean - expected) / sigma:.1f} sigma, sigma {sigma:.3g})")
        report += f"; image mean {totals[:, :, 0].mean():.7g}, closed form {expected:.7g}, sigma {sigma:.2g}"
    if failures:
        shown = failures[:20] + ([f"... and {len(failures) - 20} more"] if len(failures) > 20 else [])
        print("\n".join(shown), file=sys.stderr)
        return 1
    print(report)
    return 0


if __name__ == "__main__":
    sys.exit(main())
