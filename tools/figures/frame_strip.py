#!/usr/bin/python3
"""Assemble a figure from transient volumes: one row per volume, one column
per chosen time, plus an optional steady column; one exposure for the whole
figure so rows compare directly.

Each row is `LABEL=VOLUME.npy@START` (START: the OPL at the start of the
volume's bin 0, as given to the film); `LABEL=VOLUME.npy@START#running` shows
the running integral over bins instead (the response to continuous emission
switched on at OPL 0, when the volume is the response to a Dirac pulse);
`LABEL=VOLUME.npy@START#continuous` marks a volume rendered with continuous
emission (`pulse` = `continuous`): its steady column is its last bin, the
level reached at the window's end (the steady image once all light has
arrived), not the mean over bins. Columns are OPLs *relative to each
row's START* (--times), so rows rendered with different windows (e.g. with and
without observer time) line up by elapsed time since their window start. A
frame is the mean of --average bins around the chosen time, to calm
transient_path's noise without hiding the wavefronts.

    /usr/bin/python3 tools/figures/frame_strip.py out/fig.png \
        "multiple, observer time=out/a.npy@3" "multiple, no observer time=out/b.npy@0" \
        --bin-width 0.05 --times 0.5 1 1.5 2 --steady
"""
import argparse

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def parse_row(text):
    """LABEL=VOLUME.npy@START[#running|#continuous] -> label, path, start, mode ("", "running" or "continuous")."""
    label, rest = text.split("=", 1)
    rest, _, mode = rest.partition("#")
    if mode not in ("", "running", "continuous"):
        raise SystemExit(f"frame_strip: unknown row mode #{mode} in {text!r} (use #running or #continuous)")
    path, start = rest.rsplit("@", 1)
    return label, path, float(start), mode


def to_srgb(linear):
    linear = np.clip(linear, 0.0, 1.0)
    return np.where(linear <= 0.0031308, 12.92 * linear, 1.055 * np.power(linear, 1 / 2.4) - 0.055)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("output", help="PNG to write")
    parser.add_argument("rows", nargs="+", help="LABEL=VOLUME.npy@START_OPL")
    parser.add_argument("--bin-width", type=float, required=True, help="OPL per bin (scene units)")
    parser.add_argument("--times", type=float, nargs="+", required=True, help="OPLs after each row's start")
    parser.add_argument("--average", type=int, default=3, help="bins averaged per frame")
    parser.add_argument("--steady", action="store_true", help="add the time integral as a last column")
    parser.add_argument("--percentile", type=float, default=99.0, help="exposure: this percentile of all frames -> 1")
    parser.add_argument("--row-exposure", action="store_true", help="one exposure per row (frames, and the steady column) instead of per figure")
    parser.add_argument("--title", default="")
    parser.add_argument("--note", default="", help="text under the figure (e.g. which mesh); may have several lines")
    args = parser.parse_args()

    rows = []
    for text in args.rows:
        label, path, _start, mode = parse_row(text)
        volume = np.load(path, mmap_mode="r")  # (height, width, bins, 3)
        # The time integral over the window (per bin, so exposures compare);
        # under continuous emission, the level reached at the window's end.
        steady = None
        if args.steady:
            steady = np.asarray(volume[:, :, -1]) if mode == "continuous" else np.asarray(volume).mean(axis=2)
        if mode == "running":
            volume = np.cumsum(volume, axis=2, dtype=np.float32)
        frames = []
        for t in args.times:
            centre = int(t / args.bin_width)
            lo = max(0, centre - args.average // 2)
            hi = min(volume.shape[2], lo + args.average)
            frames.append(np.asarray(volume[:, :, lo:hi]).mean(axis=2))
        rows.append((label, frames, steady))

    # One exposure for every transient frame (or per row); the steady column
    # (a sum over the window, far brighter per bin) gets its own, shared by
    # its rows (or per row with --row-exposure: a continuous row's steady
    # column is a level, not a mean over bins).
    def exposure(frames):
        values = np.concatenate([f.ravel() for f in frames])
        return 1.0 / max(np.percentile(values, args.percentile), 1e-12)

    figure_scale = exposure([f for _, frames, _ in rows for f in frames])
    steady_scale = 1.0
    if args.steady:
        steady_values = np.concatenate([s.ravel() for _, _, s in rows])
        steady_scale = 1.0 / max(np.percentile(steady_values, args.percentile), 1e-12)

    columns = len(args.times) + (1 if args.steady else 0)
    # A note may have several lines: each gets its own strip of the figure's height.
    note_height = 0.05 + 0.13 * (args.note.count("\n") + 1) if args.note else 0.0
    height = 1.9 * len(rows) + 0.4 + note_height
    fig, axes = plt.subplots(len(rows), columns, figsize=(1.8 * columns, height), squeeze=False)
    for r, (label, frames, steady) in enumerate(rows):
        scale = exposure(frames) if args.row_exposure else figure_scale
        for c, frame in enumerate(frames):
            ax = axes[r][c]
            ax.imshow(to_srgb(frame * scale))
            if r == 0:
                ax.set_title(f"+{args.times[c]:g}", fontsize=8)
        if args.steady:
            row_steady_scale = exposure([steady]) if args.row_exposure else steady_scale
            axes[r][-1].imshow(to_srgb(steady * row_steady_scale))
            if r == 0:
                axes[r][-1].set_title("steady", fontsize=8)
        axes[r][0].set_ylabel(label, fontsize=7)
        for ax in axes[r]:
            ax.set_xticks([])
            ax.set_yticks([])
    title = args.title + ("\n" if args.title else "") + "columns: OPL after the window start (scene units)"
    fig.suptitle(title, fontsize=9)
    if args.note:
        fig.text(0.5, 0.005, args.note, ha="center", fontsize=7)
    fig.tight_layout(rect=(0, note_height / height, 1, 1))
    fig.savefig(args.output, dpi=110)
    print(f"wrote {args.output}")


if __name__ == "__main__":
    main()
