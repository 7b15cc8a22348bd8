#!/usr/bin/python3
"""Plot radiance against time at chosen pixels of one or more transient volumes.

Reads the .npy volumes femto's transient film writes (float32, shape
(height, width, bins, 3); see docs/transient-film.md) memory-mapped, so only
the chosen pixels' bins are read, whatever the volume's size. Several volumes
(e.g. photon beams vs path tracing) go on one plot, each with its --label;
an analytic curve can be overlaid from a CSV file (--analytic FILE: two
columns, time and value, in the plot's time unit; a header line is allowed).

Time axis: OPL (scene units) when the volume's window is known, from
--start-opl/--bin-width-opl or from a JSON sidecar <stem>.json next to the
volume holding start_opl and bin_width_opl; otherwise the bin index. --ns
converts OPL to nanoseconds (scene units taken as metres).

  /usr/bin/python3 tools/view/plot_profiles.py out/fog.npy --pixel 64,64 --pixel 20,100 -o profiles.png
  /usr/bin/python3 tools/view/plot_profiles.py beams.npy path.npy --label beams --label path --pixel 64,64 -o cmp.svg
"""
import argparse
import json
import os
import sys

SPEED_OF_LIGHT_M_PER_NS = 0.299792458


def fail(message):
    print(f"error: {message}", file=sys.stderr)
    sys.exit(1)


def parse_pixel(text):
    try:
        x, y = (int(v) for v in text.split(","))
    except ValueError:
        raise argparse.ArgumentTypeError(f'expected X,Y (column, row), got "{text}"')
    return x, y


def load_volume(np, path):
    try:
        volume = np.load(path, mmap_mode="r")
    except (OSError, ValueError) as e:
        fail(f'"{path}" is not a .npy volume: {e}')
    if volume.dtype != np.float32 or volume.ndim != 4 or volume.shape[3] != 3:
        fail(f'"{path}" is not a float32 (height, width, bins, 3) volume (dtype {volume.dtype}, shape {volume.shape})')
    return volume


def time_window(path, args):
    """(start_opl, bin_width_opl) or None when unknown."""
    if args.bin_width_opl is not None:
        return args.start_opl, args.bin_width_opl
    sidecar = os.path.splitext(path)[0] + ".json"
    if os.path.exists(sidecar):
        with open(sidecar) as f:
            meta = json.load(f)
        if "bin_width_opl" in meta:
            return float(meta.get("start_opl", 0.0)), float(meta["bin_width_opl"])
    return None


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("volumes", nargs="+", help="transient volumes (.npy)")
    parser.add_argument("--pixel", type=parse_pixel, action="append", required=True, help="X,Y (repeatable)")
    parser.add_argument("--label", action="append", default=[], help="legend name of each volume, in order")
    parser.add_argument("--analytic", help="CSV of (time, value) to overlay")
    parser.add_argument("--analytic-label", default="analytic")
    parser.add_argument("--channel", choices=["luminance", "r", "g", "b"], default="luminance")
    parser.add_argument("--start-opl", type=float, default=0.0, help="OPL at the start of bin 0")
    parser.add_argument("--bin-width-opl", type=float, help="OPL per bin (else from <stem>.json, else bin index)")
    parser.add_argument("--ns", action="store_true", help="time in nanoseconds (scene units are metres)")
    parser.add_argument("--log", action="store_true", help="logarithmic radiance axis")
    parser.add_argument("--title", default="")
    parser.add_argument("-o", "--output", required=True, help="PNG, SVG or PDF")
    args = parser.parse_args()
    if args.label and len(args.label) != len(args.volumes):
        fail(f"give one --label per volume ({len(args.volumes)}), got {len(args.label)}")

    import numpy as np
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    weights = {"luminance": (0.212671, 0.715160, 0.072169), "r": (1, 0, 0), "g": (0, 1, 0), "b": (0, 0, 1)}
    weight = np.array(weights[args.channel], dtype=np.float64)
    figure, axes = plt.subplots(figsize=(7, 4))
    unit = "bin"
    for index, path in enumerate(args.volumes):
        volume = load_volume(np, path)
        height, width, bins, _ = volume.shape
        window = time_window(path, args)
        if window is None:
            time = np.arange(bins) + 0.5
        else:
            start, step = window
            time = start + (np.arange(bins) + 0.5) * step  # bin centres
            unit = "OPL (scene units)"
            if args.ns:
                time = time / SPEED_OF_LIGHT_M_PER_NS
                unit = "time (ns)"
        name = args.label[index] if args.label else os.path.basename(path)
        for x, y in args.pixel:
            if not (0 <= x < width and 0 <= y < height):
                fail(f'--pixel {x},{y} is outside "{path}" ({width}x{height})')
            values = np.asarray(volume[y, x], dtype=np.float64) @ weight
            axes.plot(time, values, label=f"{name} ({x},{y})", linewidth=1.2, drawstyle="steps-mid")
    if args.analytic:
        try:
            data = np.loadtxt(args.analytic, delimiter=",", ndmin=2, comments="#",
                              skiprows=0 if _first_is_number(args.analytic) else 1)
        except (OSError, ValueError) as e:
            fail(f'cannot read the analytic curve "{args.analytic}": {e}')
        axes.plot(data[:, 0], data[:, 1], "k--", label=args.analytic_label, linewidth=1.0)
    axes.set_xlabel(unit)
    axes.set_ylabel(f"radiance ({args.channel})")
    if args.log:
        axes.set_yscale("log")
    if args.title:
        axes.set_title(args.title)
    axes.legend(fontsize="small")
    figure.tight_layout()
    figure.savefig(args.output, dpi=120)
    print(f"wrote {args.output}")


def _first_is_number(path):
    with open(path) as f:
        first = f.readline().split(",")[0].strip()
    try:
        float(first)
        return True
    except ValueError:
        return False


if __name__ == "__main__":
    main()
