"""A reference transient volume made of K independent renders, and what its
own error adds to every relMSE measured against it.

A single long render is a poor reference when its integrator's error is
heavy-tailed (transient_path in fog: next-event estimation to a point light
weighs 1/d^2 at a vertex d from the light). The mean of K renders with
different seeds has 1/K of one render's variance, and the K renders also say
how large that variance is: per value v (pixel, bin, channel) the variance of
the mean is s_v^2 / K, s_v^2 the sample variance of the K values.

With femto compare's relMSE (docs/compare.md: the mean over pixels x bins x
channels of (t - r)^2 / (r^2 + eps), r the reference) and a test render t
independent of the reference, the errors of the two add:

    E[relMSE(t, ref)] ~= relMSE(t, truth) + mean_v var_mean_v / (ref_v^2 + eps)

(the denominators use the reference's values, as femto compare does). The
second term is the reference's *expected contribution*: subtracting it from a
measured relMSE estimates the error against the truth. It is an estimate from
K samples: where the renders' error is heavy-tailed, s_v^2 of a few samples
is usually below the true variance, so treat it as a typical value, not a
bound (docs/design/photon-beams.md, "Performance on the fog Cornell box").

    path, estimate = multi_seed_reference(femto, scene, defines, "transient_path", "spp", 8192,
                                          seeds=range(7919, 7927), threads=0, cache_dir="build/compare-cache")

Every render is cached on its own (render_runs.cached_reference, so adding
seeds reuses the others), the mean under cache_dir/mean-<key>/reference.npy
with the first render's sidecar (reference.json: the same window, so femto
compare accepts it) and meta.json (seeds, budget, render times and the error
estimates, read back by reference_meta()). Only the .npy volume is averaged,
not the steady EXR. Tested by test_reference_volume.py.
"""
import hashlib
import json
import os

import numpy as np

import render_runs

EPSILON = 0.01  # femto compare's default relMSE epsilon (docs/compare.md)
# Values of the K renders held at once, in bytes (float64): bounds memory for any volume size.
CHUNK_BYTES = 128 << 20


def rebin(volume, factor):
    """Sum each run of `factor` consecutive time bins (axis 2 of a (H, W, bins, 3)
    array): the volume a film with bins `factor` times wider records (exact for
    the box time filter). factor = bins gives the time integral."""
    bins = volume.shape[2]
    if factor < 1 or bins % factor:
        raise ValueError(f"cannot rebin {bins} time bins by {factor}: it must divide the number of bins")
    return volume.reshape(volume.shape[:2] + (bins // factor, factor) + volume.shape[3:]).sum(axis=3)


def _load_volumes(paths):
    volumes = [np.load(p, mmap_mode="r") for p in paths]
    for p, v in zip(paths, volumes):
        if v.ndim != 4 or v.shape != volumes[0].shape:
            raise ValueError(f"{p}: shape {v.shape}, expected a (height, width, bins, channels) volume "
                             f"of shape {volumes[0].shape} like {paths[0]}")
    return volumes


def mean_and_error(paths, out_path=None, epsilon=EPSILON, factors=(1,), rebin_factor=1, chunk_bytes=CHUNK_BYTES,
                   per_bin=False):
    """Mean of the .npy volumes `paths` (K >= 2 renders of one scene with
    different seeds), written to `out_path` as float32 if given, and the
    reference's expected relMSE contribution mean_v var_mean_v / (mean_v^2 + eps)
    for each time rebinning factor in `factors` (1: the mean as written;
    its number of bins: its time integral, femto compare's "time_integral").
    With `rebin_factor` > 1 each render's bins are first summed in runs of
    that many (renders on a finer time grid give a coarser reference).
    Returns {factor: contribution}, with per_bin also "per_bin": the
    contribution of each bin of the mean (a list). Streams a block of rows at a time."""
    if len(paths) < 2:
        raise ValueError("the variance of a mean needs at least 2 renders")
    volumes = _load_volumes(paths)
    k = len(volumes)
    height, width, fine_bins, channels = volumes[0].shape
    bins = rebin(np.zeros((1, 1, fine_bins, 1)), rebin_factor).shape[2]
    for f in factors:
        rebin(np.zeros((1, 1, bins, 1)), f)  # refuse a factor that does not divide the bins before any work
    out = None
    if out_path:
        out = np.lib.format.open_memmap(out_path, mode="w+", dtype=np.float32, shape=(height, width, bins, channels))
    sums = {f: 0.0 for f in factors}
    bin_sums = np.zeros(bins)
    rows = max(1, chunk_bytes // (k * width * fine_bins * channels * 8))
    for y0 in range(0, height, rows):
        block = np.stack([rebin(np.asarray(v[y0:y0 + rows], dtype=np.float64), rebin_factor)
                          for v in volumes])  # (K, rows, W, bins, C)
        mean = block.mean(axis=0)
        if out is not None:
            out[y0:y0 + rows] = mean
        for f in factors:
            samples = np.stack([rebin(b, f) for b in block]) if f > 1 else block
            m = samples.mean(axis=0)
            # Unbiased sample variance (ddof=1) divided by K: the variance of the mean.
            var_mean = samples.var(axis=0, ddof=1) / k
            share = var_mean / (m * m + epsilon)
            sums[f] += float(np.sum(share))
            if f == 1:
                bin_sums += share.sum(axis=(0, 1, 3))
    if out is not None:
        out.flush()
        del out
    result = {f: sums[f] / (height * width * (bins // f) * channels) for f in factors}
    if per_bin:
        result["per_bin"] = (bin_sums / (height * width * channels)).tolist()
    return result


def _mean_key(scene, defines, integrator, param, budget, seeds, rebin_factor):
    """Cache key of the mean: what each render's key holds, with the seed list."""
    _, spec = render_runs.reference_key(scene, defines, integrator, param, budget, seeds[0])
    spec = dict(spec, seed=None, seeds=list(seeds), rebin_factor=rebin_factor)
    return hashlib.sha256(json.dumps(spec, sort_keys=True).encode()).hexdigest()[:16], spec


def reference_meta(path):
    """meta.json beside a reference made by multi_seed_reference (seeds,
    budget, relmse_estimate, integral_relmse_estimate, ...), or None."""
    meta = os.path.join(os.path.dirname(path), "meta.json")
    if not os.path.exists(meta):
        return None
    with open(meta) as f:
        return json.load(f)


def _write_sidecar(render_sidecar, out, rebin_factor):
    """The renders' sidecar (their window: femto compare checks it), with bins
    rebin_factor times wider. The format is flat JSON (volume_info.h)."""
    if not os.path.exists(render_sidecar):
        return
    with open(render_sidecar) as f:
        info = json.load(f)
    if rebin_factor > 1:
        info["bins"] //= rebin_factor
        info["bin_width_opl"] *= rebin_factor
    with open(out, "w") as f:
        json.dump(info, f, indent=2)


def multi_seed_reference(femto, scene, defines, integrator, param, budget, seeds, threads, cache_dir,
                         log=print, epsilon=EPSILON, rebin_factor=1):
    """The mean of renders of `scene` (with -D `defines` + integrator and
    param=budget) with each of `seeds` (at least 2, all different, none equal
    to a seed of the renders it will judge), as a cached .npy volume.
    Returns (mean .npy path, the reference's expected relMSE contribution at
    `epsilon`); reference_meta(path) has the time integral's too.
    rebin_factor > 1 sums the renders' bins in runs of that many: `defines`
    then give a time grid that many times finer than the reference's (same
    start, bin width / rebin_factor). For transient_path and the box time
    filter this equals rendering the coarse grid (a sample lands in one bin
    of either), so one set of renders serves several bin counts."""
    seeds = [int(s) for s in seeds]
    if len(seeds) < 2 or len(set(seeds)) != len(seeds):
        raise ValueError(f"a multi-seed reference needs at least 2 different seeds, got {seeds}")
    key, spec = _mean_key(scene, defines, integrator, param, budget, seeds, rebin_factor)
    folder = os.path.join(cache_dir, "mean-" + key)
    path = os.path.join(folder, "reference.npy")
    meta = reference_meta(path)
    if meta and os.path.exists(path) and meta.get("epsilon") == epsilon:
        log(f"reference: cached mean of {len(seeds)} renders {path} (relMSE contribution "
            f"{meta['relmse_estimate']:.3g})")
        return path, meta["relmse_estimate"]
    renders = [render_runs.cached_reference(femto, scene, defines, integrator, param, budget, s, threads,
                                            cache_dir, log) for s in seeds]
    for r in renders:
        if not r.endswith(".npy"):
            raise render_runs.RunError(f"{r}: a multi-seed reference averages .npy volumes; "
                                       "this render wrote no transient volume")
    os.makedirs(folder, exist_ok=True)
    bins = np.load(renders[0], mmap_mode="r").shape[2] // rebin_factor
    estimates = mean_and_error(renders, path + ".tmp.npy", epsilon, factors=(1, bins), rebin_factor=rebin_factor)
    os.replace(path + ".tmp.npy", path)
    _write_sidecar(os.path.splitext(renders[0])[0] + ".json", os.path.join(folder, "reference.json"), rebin_factor)
    render_meta = [reference_meta(r) or {} for r in renders]
    meta = dict(spec, scene_file=os.path.abspath(scene), file="reference.npy",
                renders=[os.path.abspath(r) for r in renders],
                seconds=[m.get("seconds") for m in render_meta],
                cpu_seconds=[m.get("cpu_seconds") for m in render_meta], epsilon=epsilon,
                relmse_estimate=estimates[1], integral_relmse_estimate=estimates[bins])
    with open(os.path.join(folder, "meta.json"), "w") as f:
        json.dump(meta, f, indent=2)
    log(f"reference: mean of {len(seeds)} renders in {path}; its expected relMSE contribution "
        f"{estimates[1]:.3g} (time integral {estimates[bins]:.3g})")
    return path, estimates[1]
