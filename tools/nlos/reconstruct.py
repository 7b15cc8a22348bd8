#!/usr/bin/python3
"""Reconstruct a hidden scene from a femto NLOS capture (transient_nlos_path
with an nlos_capture_meter; docs/nlos.md).

Two methods, both back-projections of the capture H(w, t) (w a watched wall
point, t an OPL) onto voxels v of a box:
  fbp     filtered back-projection (Velten et al., Nature Comms. 2012):
          V(v) = sum_w H(w, t(v, w)), then the negative 3D Laplacian, clamped at 0;
  phasor  phasor fields (Liu et al., Nature 2019): every H(w, .) is first
          convolved with the virtual wave P(t) = exp(2 pi i t / lambda)
          exp(-t^2 / (2 sigma^2)) (NumPy's FFT), then back-projected; the
          reconstruction is |V|;
  fk      f-k migration (Lindell et al., SIGGRAPH 2019), confocal captures
          only: the capture as a wave field over the wall and time (one-way
          distance s = t / 2, amplitude sqrt(H) s), Fourier transformed,
          remapped from temporal frequency w to depth frequency kz by Stolt's
          w = sqrt(kx^2 + ky^2 + kz^2) (times kz / w), transformed back; the
          reconstruction is its modulus (Lindell et al. show its square; the
          modulus is what the half-maximum of the other methods reads),
          sampled trilinearly at the voxels.
t(v, w) is 2 |v - w| for a confocal capture and |w - v| + |v - y| for one lit
point y (exhaustive captures are one such capture per lit point). Captures
rendered with the first and last legs accounted have them removed first
(--sensor-origin, --laser-origin).

The wall is the rectangle of the capture: centre --wall-center, half sizes
--wall-half along x and y, normal +z (femto's rectangle scaled and moved);
pixel (i, j) of the .npy (row j, column i) watches the point at uv
((i + 0.5) / W, (j + 0.5) / H), as the capture meter places them.

Writes PREFIX.npy (the volume, nz x ny x nx) and PREFIX.png (its maximum
over z, row 0 at the box's largest y, as seen from the wall).
"""
import argparse
import json
import os
import sys

import numpy as np


def parse_vector(text, n):
    values = [float(v) for v in text.split(",")]
    if len(values) != n:
        raise argparse.ArgumentTypeError(f"expected {n} comma-separated numbers, got {text!r}")
    return np.array(values)


def load_capture(path, with_info=False):
    """The capture as H[j, i, t] (channels summed) and its time axis (start,
    width); with_info: and the sidecar's fields (femto writes an NLOS
    capture's geometry there: nlos_* and <stem>_wall.npy)."""
    volume = np.load(path)
    if volume.ndim != 4:
        sys.exit(f"{path}: expected a femto transient volume (height, width, bins, channels), got shape {volume.shape}")
    sidecar = os.path.splitext(path)[0] + ".json"
    if not os.path.exists(sidecar):
        sys.exit(f"{path}: its time axis is in {sidecar}, which is missing")
    with open(sidecar) as f:
        info = json.load(f)
    capture = volume.sum(axis=3).astype(np.float64), float(info["start_opl"]), float(info["bin_width_opl"])
    return capture + (info,) if with_info else capture


def load_phasor_capture(path):
    """A phasor-film capture (phasor_hdr_film: <stem>.npy of shape (height,
    width, frequencies, 2, 3)) as Z[j, i, f] (channels summed), its
    frequencies, start_opl and sidecar fields."""
    x = np.load(path)
    sidecar = os.path.splitext(path)[0] + ".json"
    if not os.path.exists(sidecar):
        sys.exit(f"{path}: its frequencies are in {sidecar}, which is missing")
    with open(sidecar) as f:
        info = json.load(f)
    z = (x[..., 0, :].astype(np.float64) + 1j * x[..., 1, :].astype(np.float64)).sum(axis=3)
    return z, np.array(info["frequencies"], dtype=np.float64), float(info["start_opl"]), info


def phasor_from_film(z, frequencies, start, points, voxels_xyz, lit, legs=None):
    """The phasor method from a phasor film's coefficients: the virtual wave's
    band is the film's frequencies, so the back-projection at the voxels'
    arrival times is a sum over them, V(v) = sum_w sum_f Z_f(w)
    exp(2 pi i f (t(v, w) - start)) (Z_f(w) = sum v exp(-2 pi i f (tau -
    start)), the film's sign); |V|. `legs` (sensor, laser origins): remove
    the first and last legs, a phase shift exp(2 pi i f (legs))."""
    volume = np.zeros(voxels_xyz.shape[:3], dtype=np.complex128)
    to_lit = None if lit is None else np.linalg.norm(voxels_xyz - lit, axis=-1)
    for j in range(z.shape[0]):
        for i in range(z.shape[1]):
            w = points[j, i]
            d = np.linalg.norm(voxels_xyz - w, axis=-1)
            t = 2.0 * d if to_lit is None else d + to_lit
            coefficients = z[j, i]
            if legs is not None:
                target = w if lit is None else lit
                shift = np.linalg.norm(legs[0] - w) + np.linalg.norm(legs[1] - target)
                coefficients = coefficients * np.exp(2j * np.pi * frequencies * shift)
            volume += np.exp(2j * np.pi * (t[..., None] - start) * frequencies) @ coefficients
    return np.abs(volume)


def capture_geometry(path, info):
    """From a femto capture's sidecar: the watched points [j, i, xyz] (or
    None), the lit point (None: confocal), and (sensor, laser) origins when
    the capture kept its first and last legs (else None)."""
    points = None
    if "nlos_wall_points" in info:
        points = np.load(os.path.join(os.path.dirname(os.path.abspath(path)), info["nlos_wall_points"])).astype(np.float64)
    lit = np.array(info["nlos_laser_target"]) if info.get("nlos_confocal") is False else None
    legs = None
    if info.get("nlos_legs") == "kept":
        if "nlos_laser_origin" not in info:
            sys.exit(f"{path}: the capture kept its first and last legs but its sidecar has no laser origin: "
                     "give --sensor-origin and --laser-origin")
        legs = (np.array(info["nlos_sensor_origin"]), np.array(info["nlos_laser_origin"]))
    return points, lit, legs


def default_box(points, sensor):
    """A box in front of a wall perpendicular to z: the wall's extent in x and
    y, depths from 5 % to 100 % of its width on the sensor's side."""
    span = points.reshape(-1, 3)
    lo, hi = span.min(axis=0), span.max(axis=0)
    if hi[2] - lo[2] > 1e-6 * max(hi[0] - lo[0], hi[1] - lo[1]):
        sys.exit("the relay wall is not perpendicular to z: give --box x0,y0,z0,x1,y1,z1")
    width = max(hi[0] - lo[0], hi[1] - lo[1])
    side = 1.0 if sensor is None or sensor[2] >= lo[2] else -1.0
    z0, z1 = sorted((lo[2] + side * 0.05 * width, lo[2] + side * width))
    return np.array([lo[0], lo[1], z0, hi[0], hi[1], z1])


def wall_points(height, width, center, half):
    """World positions of the watched points, [j, i, xyz]."""
    u = (np.arange(width) + 0.5) / width
    v = (np.arange(height) + 0.5) / height
    x = center[0] + half[0] * (2.0 * u - 1.0)
    y = center[1] + half[1] * (2.0 * v - 1.0)
    points = np.zeros((height, width, 3))
    points[..., 0] = x[None, :]
    points[..., 1] = y[:, None]
    points[..., 2] = center[2]
    return points


def voxel_centers(box, voxels):
    lo, hi = box[:3], box[3:]
    axes = [lo[k] + (np.arange(voxels[k]) + 0.5) * (hi[k] - lo[k]) / voxels[k] for k in range(3)]
    z, y, x = np.meshgrid(axes[2], axes[1], axes[0], indexing="ij")
    return np.stack([x, y, z], axis=-1)  # [z, y, x, xyz]


def remove_legs(capture, start, width, points, sensor, laser, lit):
    """Shift every wall point's signal earlier by its first and last legs."""
    bins = capture.shape[2]
    out = np.zeros_like(capture)
    for j in range(capture.shape[0]):
        for i in range(capture.shape[1]):
            w = points[j, i]
            target = w if lit is None else lit
            shift = np.linalg.norm(sensor - w) + np.linalg.norm(laser - target)
            k = int(round(shift / width))
            if k < bins:
                out[j, i, : bins - k] = capture[j, i, k:]
    return out


def phasor_filter(capture, width, wavelength, cycles):
    """Convolve every time signal with the virtual phasor wave (Liu et al. 2019, eq. 5)."""
    bins = capture.shape[2]
    sigma = cycles * wavelength / 6.0  # the Gaussian envelope holds `cycles` periods within +-3 sigma
    half = int(np.ceil(3.0 * sigma / width))
    t = np.arange(-half, half + 1) * width
    kernel = np.exp(2j * np.pi * t / wavelength) * np.exp(-0.5 * (t / sigma) ** 2)
    n = bins + kernel.size - 1
    spectrum = np.fft.fft(capture, n=n, axis=2) * np.fft.fft(kernel, n=n)[None, None, :]
    return np.fft.ifft(spectrum, axis=2)[:, :, half : half + bins]


def back_project(capture, start, width, points, voxels_xyz, lit):
    """V(v) = sum over wall points of the signal at the voxel's arrival time (linear in t)."""
    bins = capture.shape[2]
    volume = np.zeros(voxels_xyz.shape[:3], dtype=capture.dtype)
    to_lit = None if lit is None else np.linalg.norm(voxels_xyz - lit, axis=-1)
    for j in range(capture.shape[0]):
        for i in range(capture.shape[1]):
            d = np.linalg.norm(voxels_xyz - points[j, i], axis=-1)
            t = 2.0 * d if to_lit is None else d + to_lit
            f = (t - start) / width - 0.5  # bin centres at start + (k + 0.5) width
            k = np.floor(f).astype(np.int64)
            a = f - k
            inside = (k >= 0) & (k + 1 < bins)
            k = np.clip(k, 0, bins - 2)
            signal = capture[j, i]
            volume += np.where(inside, (1.0 - a) * signal[k] + a * signal[k + 1], 0.0)
    return volume


def fk_migration(capture, start, width, points, voxels_xyz):
    """f-k migration of a confocal capture (see the module's doc), sampled at voxels_xyz [z, y, x, xyz]."""
    height, wide, bins = capture.shape
    dx = points[0, 1, 0] - points[0, 0, 0] if wide > 1 else 1.0
    dy = points[1, 0, 1] - points[0, 0, 1] if height > 1 else 1.0
    ds = 0.5 * width  # one-way distance per bin
    lead = int(round(start / width))  # bins from OPL 0 to the capture's first
    m = lead + bins
    s = (np.arange(m) + 0.5) * ds
    field = np.zeros((2 * m, 2 * height, 2 * wide))
    field[lead:m, :height, :wide] = np.sqrt(np.maximum(capture, 0.0)).transpose(2, 0, 1) * s[lead:, None, None]
    spectrum = np.fft.fftshift(np.fft.fftn(field))
    fw = np.fft.fftshift(np.fft.fftfreq(2 * m, ds))
    fy = np.fft.fftshift(np.fft.fftfreq(2 * height, dy))
    fx = np.fft.fftshift(np.fft.fftfreq(2 * wide, dx))
    kz, ky, kx = np.meshgrid(fw, fy, fx, indexing="ij")
    w = np.sqrt(kx * kx + ky * ky + kz * kz)
    # Linear interpolation of the spectrum along its temporal-frequency axis at w.
    f = (w - fw[0]) / (fw[1] - fw[0])
    k = np.floor(f).astype(np.int64)
    a = f - k
    inside = (k >= 0) & (k + 1 < 2 * m) & (kz > 0)
    k = np.clip(k, 0, 2 * m - 2)
    lo = np.take_along_axis(spectrum, k, axis=0)
    hi = np.take_along_axis(spectrum, k + 1, axis=0)
    migrated = np.where(inside, ((1.0 - a) * lo + a * hi) * kz / np.maximum(w, 1e-12), 0.0)
    volume = np.abs(np.fft.ifftn(np.fft.ifftshift(migrated)))
    volume = volume[:m, :height, :wide]  # [depth index, j, i]
    # Trilinear samples at the voxels: depth (k + 0.5) ds from the wall, wall point (i, j).
    origin = points[0, 0]
    coords = [(voxels_xyz[..., 2] - origin[2]) / ds - 0.5, (voxels_xyz[..., 1] - origin[1]) / dy,
              (voxels_xyz[..., 0] - origin[0]) / dx]
    base = [np.floor(c).astype(np.int64) for c in coords]
    frac = [c - b for c, b in zip(coords, base)]
    out = np.zeros(voxels_xyz.shape[:3])
    for corner in range(8):
        idx, weight = [], 1.0
        for axis in range(3):
            bit = (corner >> axis) & 1
            idx.append(base[axis] + bit)
            weight = weight * (frac[axis] if bit else 1.0 - frac[axis])
        ok = np.ones(out.shape, dtype=bool)
        for axis, n in enumerate(volume.shape):
            ok &= (idx[axis] >= 0) & (idx[axis] < n)
        clipped = [np.clip(i, 0, n - 1) for i, n in zip(idx, volume.shape)]
        out += np.where(ok, weight * volume[clipped[0], clipped[1], clipped[2]], 0.0)
    return out


def smooth_in_time(capture, width, sigma):
    """Gaussian blur of every time signal (standard deviation `sigma`, OPL units), by FFT."""
    bins = capture.shape[2]
    half = int(np.ceil(3.0 * sigma / width))
    t = np.arange(-half, half + 1) * width
    kernel = np.exp(-0.5 * (t / sigma) ** 2)
    kernel /= kernel.sum()
    n = bins + kernel.size - 1
    spectrum = np.fft.rfft(capture, n=n, axis=2) * np.fft.rfft(kernel, n=n)[None, None, :]
    return np.fft.irfft(spectrum, n=n, axis=2)[:, :, half : half + bins]


def negative_laplacian(volume):
    """-(discrete 3D Laplacian), clamped at 0: the FBP filter (Velten et al. 2012)."""
    padded = np.pad(volume, 1, mode="edge")
    lap = -6.0 * volume
    for axis in range(3):
        lap += np.take(padded, range(2, padded.shape[axis]), axis=axis)[tuple(
            slice(1, -1) if a != axis else slice(None) for a in range(3))]
        lap += np.take(padded, range(0, padded.shape[axis] - 2), axis=axis)[tuple(
            slice(1, -1) if a != axis else slice(None) for a in range(3))]
    return np.maximum(-lap, 0.0)


def reconstruct(capture, start, width, points, box, voxels, lit, method, wavelength=None, cycles=4.0):
    """The reconstructed volume [z, y, x] (non-negative)."""
    centers = voxel_centers(box, voxels)
    if method == "fk":
        if lit is not None:
            raise ValueError("f-k migration needs a confocal capture (the laser on the watched point)")
        return fk_migration(capture, start, width, points, centers)
    if method == "fbp":
        # Back-projection samples each signal once per voxel: blur it first to
        # the voxels' reach in OPL (a voxel edge moves t by up to twice its
        # length), or the Laplacian amplifies the aliased bins.
        voxel = float(np.max((box[3:] - box[:3]) / voxels))
        if voxel > width:
            capture = smooth_in_time(capture, width, voxel)
        return negative_laplacian(back_project(capture, start, width, points, centers, lit))
    if wavelength is None:
        spacing = max(abs(points[0, 1, 0] - points[0, 0, 0]) if points.shape[1] > 1 else 0.0,
                      abs(points[1, 0, 1] - points[0, 0, 1]) if points.shape[0] > 1 else 0.0)
        wavelength = 2.0 * max(spacing, 2.0 * width)  # Nyquist in space and in time
    filtered = phasor_filter(capture, width, wavelength, cycles)
    return np.abs(back_project(filtered, start, width, points, centers, lit))


def max_projection_png(volume, path):
    """Maximum over z as an 8-bit PNG, normalised to its peak, +y up."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    image = volume.max(axis=0)
    peak = image.max()
    image = image / peak if peak > 0 else image
    plt.imsave(path, image[::-1, :], cmap="inferno", vmin=0.0, vmax=1.0)


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("capture", help="the capture's .npy (its .json sidecar beside it)")
    p.add_argument("--wall-center", type=lambda s: parse_vector(s, 3), default=None,
                   help="with --wall-half: the relay wall (default: the capture's sidecar, else 0,0,0 and 1,1)")
    p.add_argument("--wall-half", type=lambda s: parse_vector(s, 2), default=None)
    p.add_argument("--lit-point", type=lambda s: parse_vector(s, 3), default=None,
                   help="the wall point the laser lit (exhaustive capture); confocal when absent")
    p.add_argument("--sensor-origin", type=lambda s: parse_vector(s, 3), default=None,
                   help="with --laser-origin: the capture kept its first and last legs; remove them")
    p.add_argument("--laser-origin", type=lambda s: parse_vector(s, 3), default=None)
    p.add_argument("--box", type=lambda s: parse_vector(s, 6), default=None,
                   help="x0,y0,z0,x1,y1,z1 (default: in front of the wall, as deep as it is wide)")
    p.add_argument("--voxels", type=lambda s: parse_vector(s, 3).astype(int), default=np.array([32, 32, 32]))
    p.add_argument("--method", choices=["fbp", "phasor", "fk"], default="fbp")
    p.add_argument("--wavelength", type=float, default=None, help="phasor: the virtual wavelength (OPL units)")
    p.add_argument("-o", "--output", required=True, help="output prefix: PREFIX.npy and PREFIX.png")
    args = p.parse_args(argv)
    phasor_film = np.load(args.capture, mmap_mode="r").ndim == 5
    if phasor_film:
        z, frequencies, start, info = load_phasor_capture(args.capture)
        if args.method != "phasor":
            p.error("a phasor-film capture reconstructs with --method phasor")
        capture = np.zeros(z.shape[:2] + (1,))  # the wall's shape, for the geometry below
        width = 1.0
    else:
        capture, start, width, info = load_capture(args.capture, with_info=True)
    # What the command line gives wins over the sidecar's geometry.
    side_points, side_lit, side_legs = capture_geometry(args.capture, info)
    if args.wall_center is not None or args.wall_half is not None or side_points is None:
        center = np.zeros(3) if args.wall_center is None else args.wall_center
        half = np.ones(2) if args.wall_half is None else args.wall_half
        points = wall_points(capture.shape[0], capture.shape[1], center, half)
    else:
        points = side_points
    lit = args.lit_point if args.lit_point is not None else side_lit
    if (args.sensor_origin is None) != (args.laser_origin is None):
        p.error("give both --sensor-origin and --laser-origin, or neither")
    legs = (args.sensor_origin, args.laser_origin) if args.sensor_origin is not None else side_legs
    if legs is not None and not phasor_film:
        capture = remove_legs(capture, start, width, points, legs[0], legs[1], lit)
    sensor = np.array(info["nlos_sensor_origin"]) if "nlos_sensor_origin" in info else None
    box = args.box if args.box is not None else default_box(points, sensor)
    if args.method == "fk" and lit is not None:
        p.error("--method fk needs a confocal capture")
    if phasor_film:
        volume = phasor_from_film(z, frequencies, start, points, voxel_centers(box, args.voxels), lit, legs)
    else:
        volume = reconstruct(capture, start, width, points, box, args.voxels, lit, args.method, args.wavelength)
    np.save(args.output + ".npy", volume.astype(np.float32))
    max_projection_png(volume, args.output + ".png")
    nz, ny, nx = volume.shape
    print(f"wrote {args.output}.npy ({args.method} volume, {nz}x{ny}x{nx} voxels, z y x) "
          f"and {args.output}.png (its maximum over depth)")


if __name__ == "__main__":
    main()
