"""Looking at transient volumes (height x width x bins x 3) from Python, with
the CLI's own exposure and encoding (`femto frames`, `femto streak`;
docs/viewing.md)."""
import numpy as np

from . import _femto

# `femto frames`' default: this percentile of all non-black voxels' luminance becomes white.
DEFAULT_PERCENTILE = 99.5
# Frames converted per call into C++: bounds the float copy a memory-mapped volume needs.
_FRAMES_PER_BATCH_BYTES = 64 << 20


def _check_volume(vol):
    if vol.ndim != 4 or vol.shape[3] != 3:
        raise ValueError(f"expected a transient volume, height x width x bins x 3, got shape {vol.shape}")


def exposure_of(vol, percentile=DEFAULT_PERCENTILE) -> float:
    """The exposure in stops (scale 2^E) that maps `percentile` of the non-black
    voxels' luminance to white: one exposure for the whole sequence, as
    `femto frames --percentile`; 0 for a black volume."""
    return float(_femto.auto_exposure(np.asarray(vol, dtype=np.float32), float(percentile)))


def frames(vol, exposure=None, percentile=DEFAULT_PERCENTILE, false_colour=False, bins=None) -> np.ndarray:
    """Tone-mapped 8-bit sRGB frames, bins x height x width x 3 uint8: frame b
    is the bytes `femto frames` writes for bin b. exposure: stops for every
    frame (None: exposure_of(vol, percentile)). false_colour: the luminance
    through the CLI's false-colour ramp. bins: a range of bins (default all)."""
    _check_volume(vol)
    if exposure is None:
        exposure = exposure_of(vol, percentile)
    count = vol.shape[2]
    if bins is None:
        chosen = list(range(count))
    elif isinstance(bins, tuple) and len(bins) == 2:
        chosen = list(range(*slice(*bins).indices(count)))  # (first, end), end exclusive, either may be None
    else:
        chosen = [int(b) for b in bins]
    out = np.empty((len(chosen), vol.shape[0], vol.shape[1], 3), dtype=np.uint8)
    per_batch = max(1, _FRAMES_PER_BATCH_BYTES // (vol.shape[0] * vol.shape[1] * 12))
    for start in range(0, len(chosen), per_batch):
        batch = chosen[start:start + per_batch]
        linear = np.ascontiguousarray(np.moveaxis(vol[:, :, batch, :], 2, 0), dtype=np.float32)
        out[start:start + len(batch)] = _femto.display_frames(linear, float(exposure), bool(false_colour))
    return out


def streak(vol, row=None, column=None) -> np.ndarray:
    """The streak image (linear float32), as `femto streak`: at image `row`,
    bins x width x 3 (x left to right, time top to bottom); at `column`,
    height x bins x 3 (y top to bottom, time left to right)."""
    _check_volume(vol)
    if (row is None) == (column is None):
        raise ValueError("streak: give exactly one of row= and column=")
    if row is not None:
        if not 0 <= row < vol.shape[0]:
            raise ValueError(f"streak: row {row} is outside the image's rows 0..{vol.shape[0] - 1}")
        return np.ascontiguousarray(np.swapaxes(vol[row], 0, 1), dtype=np.float32)
    if not 0 <= column < vol.shape[1]:
        raise ValueError(f"streak: column {column} is outside the image's columns 0..{vol.shape[1] - 1}")
    return np.ascontiguousarray(vol[:, column], dtype=np.float32)


def display(image, exposure=0.0, false_colour=False) -> np.ndarray:
    """A linear height x width x 3 image (a steady image, a streak) as the
    8-bit sRGB bytes the CLI's PNG would hold."""
    image = np.asarray(image, dtype=np.float32)
    return _femto.display_frames(image[None], float(exposure), bool(false_colour))[0]


def animate(vol, exposure=None, percentile=DEFAULT_PERCENTILE, interval=50, time_axis=None, false_colour=False):
    """A matplotlib animation of the frames (one exposure for the sequence).
    In Jupyter: `IPython.display.HTML(femto.view.animate(vol).to_jshtml())`;
    in a script: `.save("out.gif")`. time_axis (a femto.TimeAxis) labels each
    frame with its OPL."""
    import matplotlib.pyplot as plt
    from matplotlib import animation

    pictures = frames(vol, exposure=exposure, percentile=percentile, false_colour=false_colour)
    figure, axes = plt.subplots()
    axes.set_axis_off()
    shown = axes.imshow(pictures[0])
    title = axes.set_title("")

    def draw(b):
        shown.set_data(pictures[b])
        if time_axis is not None:
            edges = time_axis.edges_opl
            title.set_text(f"bin {b}: OPL {edges[b]:.3g} to {edges[b + 1]:.3g}")
        else:
            title.set_text(f"bin {b}")
        return shown, title

    anim = animation.FuncAnimation(figure, draw, frames=len(pictures), interval=interval, blit=False)
    plt.close(figure)  # shown through the animation, not as a still
    return anim
