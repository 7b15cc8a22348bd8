#!/usr/bin/python3
"""Equal-time relMSE ratios of several speed_vs_error.py runs (e.g. one per
seed of the budget renders) as a Markdown table: for each results.csv, the
ratio of each integrator to the first at both ends of the time range the
curves share, for the relMSE as measured and with the reference's
contribution subtracted.

  tools/compare/ratio_table.py --time cpu_seconds seed1=out/1/results.csv seed2=out/2/results.csv
"""
import argparse
import csv
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import error_curves as ec  # noqa: E402


def curves(rows, time_key, metric):
    out = {}
    for r in rows:
        out.setdefault(r["integrator"], []).append((float(r[time_key]), float(r[metric])))
    return out


def ratio_cells(rows, time_key, metric):
    """'ratio at start / ratio at end' per integrator after the first, with the times."""
    c = curves(rows, time_key, metric)
    names = list(c)
    span = ec.common_time_range(c)
    if not span:
        return ["no common time range"] * (len(names) - 1)
    cells = []
    for name in names[1:]:
        parts = []
        for when in span:
            r = ec.equal_time_ratios(c, names[0], when)[name]
            parts.append(f"{r:.3g} at {when:.3g} s" if r is not None else f"n/a at {when:.3g} s")
        cells.append(", ".join(parts))
    return cells


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--time", default="seconds")
    p.add_argument("runs", nargs="+", metavar="LABEL=CSV")
    args = p.parse_args(argv)
    runs = [r.split("=", 1) for r in args.runs]
    tables = [(label, list(csv.DictReader(open(path)))) for label, path in runs]
    names = list(dict.fromkeys(r["integrator"] for r in tables[0][1]))
    print("| run | " + " | ".join(f"{n} / {names[0]}, as measured | {n} / {names[0]}, reference's error subtracted"
                                    for n in names[1:]) + " |")
    print("|---|" + "---|---|" * (len(names) - 1))
    for label, rows in tables:
        raw, fixed = ratio_cells(rows, args.time, "relmse"), ratio_cells(rows, args.time, "relmse_corrected")
        print(f"| {label} | " + " | ".join(f"{a} | {b}" for a, b in zip(raw, fixed)) + " |")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
