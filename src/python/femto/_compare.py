"""femto.compare: `femto compare REF TEST --json` (femto_view's compareFiles) for files or arrays."""
import json
import os
import shutil
import tempfile
from pathlib import Path

import numpy as np

from . import _femto


def _as_file(value, folder, name):
    """A path as it is; a memory-mapped .npy as its own file (no copy); an
    array written to `folder` (.npy for a height x width x bins x 3 volume,
    .exr for an image)."""
    if isinstance(value, (str, os.PathLike)):
        return os.fspath(value)
    axis = getattr(value, "time_axis", None)
    if axis is not None and getattr(value, "transient", None) is not None:
        # A RenderResult: its volume with the time window as a sidecar, so the
        # windows are checked (and no "no sidecar" warning is printed).
        path = Path(_as_file(value.transient, folder, name))
        height, width = value.transient.shape[:2]
        sidecar = {"format": "femto transient volume", "version": 1, "width": width, "height": height,
                   "bins": axis.bins, "time_unit": "opl", "start_opl": axis.start_opl,
                   "bin_width_opl": axis.bin_width_opl, "end_opl": axis.start_opl + axis.bins * axis.bin_width_opl}
        if path.parent != Path(folder):
            return str(path)  # a memory-mapped volume: its own file and sidecar, never written to
        path.with_suffix(".json").write_text(json.dumps(sidecar))
        return str(path)
    if isinstance(value, np.memmap) and _is_whole_npy(value):
        return str(value.filename)
    array = np.ascontiguousarray(value, dtype=np.float32)
    if array.ndim == 4:
        path = Path(folder) / (name + ".npy")
        np.save(path, array)
    elif array.ndim in (2, 3):
        path = Path(folder) / (name + ".exr")
        _femto.write_exr(path, array if array.ndim == 3 else array[:, :, None])
    else:
        raise ValueError(f"compare: expected an image (height x width x channels) or a volume "
                         f"(height x width x bins x 3), got shape {array.shape}")
    return str(path)


def _is_whole_npy(m):
    """Does memmap `m` cover all of the .npy it maps (not a slice of it)?"""
    if not m.filename or not str(m.filename).endswith(".npy"):
        return False
    try:
        whole = np.load(m.filename, mmap_mode="r")
    except (OSError, ValueError):
        return False
    return whole.shape == m.shape and whole.dtype == m.dtype and m.offset == whole.offset


def compare(reference, test, epsilon=None, crop=None, mask=None, bins=None) -> dict:
    """Error metrics of `test` against `reference`, as `femto compare --json` reports them.

    Both are paths (.npy volumes or images), render results (their volume and
    time window, which must match) or arrays (height x width x bins x 3
    volumes, height x width x channels images); a volume memory-mapped from a
    .npy is read from its file. epsilon: relMSE's (default 1e-2). crop:
    (x, y, width, height). mask: an image file (white = counted). bins:
    (first, end) of volumes, end exclusive, either may be None.
    Returns {"metrics": {"mse", "relmse", "mae", "max_error", ...}, and for
    volumes "time_integral" and "per_bin"}; docs/compare.md has the formulas."""
    folder = tempfile.mkdtemp(prefix="femto-compare-")
    try:
        ref = _as_file(reference, folder, "reference")
        tst = _as_file(test, folder, "test")
        return _femto.compare_files(ref, tst, _femto.default_relmse_epsilon if epsilon is None else float(epsilon),
                                    None if crop is None else tuple(int(v) for v in crop),
                                    "" if mask is None else os.fspath(mask), None if bins is None else tuple(bins))
    finally:
        shutil.rmtree(folder, ignore_errors=True)
