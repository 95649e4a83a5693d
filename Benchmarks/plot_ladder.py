#!/usr/bin/env python3
"""Log-log plot of the conformal map's time over mobius-benchmark's size ladder.

    mobius-benchmark --ladder 1100000 --ladder-csv after.csv MESH...
    python3 Benchmarks/plot_ladder.py after.csv [--before before.csv] -o docs/images/map-scaling.png

Fits seconds = c * V^k by least squares on the logarithms (rungs of at least --fit-from
vertices, default 20,000, where fixed costs no longer dominate) and prints k; the plot
shows the measured rungs, the fitted line with k in the legend, and the peak memory on a
second axis. Needs matplotlib (Debian python3-matplotlib).
"""
import argparse
import csv
import math
import sys


def read_ladder(path):
    with open(path, newline="") as f:
        rows = [r for r in csv.DictReader(f)]
    if not rows:
        sys.exit(f"{path}: no rungs")
    rows.sort(key=lambda r: int(r["vertices"]))
    return rows


def fit_exponent(rows, fit_from):
    points = [(math.log(int(r["vertices"])), math.log(float(r["map_seconds"])))
              for r in rows if int(r["vertices"]) >= fit_from and float(r["map_seconds"]) > 0]
    if len(points) < 2:
        return None, None
    n = len(points)
    mx = sum(p[0] for p in points) / n
    my = sum(p[1] for p in points) / n
    sxx = sum((p[0] - mx) ** 2 for p in points)
    sxy = sum((p[0] - mx) * (p[1] - my) for p in points)
    if sxx == 0:
        return None, None
    k = sxy / sxx
    return k, math.exp(my - k * mx)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("ladder", help="CSV from mobius-benchmark --ladder-csv")
    parser.add_argument("--before", help="a second ladder CSV (an earlier version) to compare")
    parser.add_argument("--label", default="now")
    parser.add_argument("--before-label", default="before")
    parser.add_argument("--fit-from", type=int, default=20000)
    parser.add_argument("-o", "--output", required=True, help="image file (.png, .svg)")
    args = parser.parse_args()

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    series = [(args.label, read_ladder(args.ladder), "tab:blue")]
    if args.before:
        series.insert(0, (args.before_label, read_ladder(args.before), "tab:gray"))
    fig, ax = plt.subplots(figsize=(7, 4.5), dpi=100)
    for label, rows, color in series:
        v = [int(r["vertices"]) for r in rows]
        t = [float(r["map_seconds"]) for r in rows]
        k, c = fit_exponent(rows, args.fit_from)
        text = label if k is None else f"{label}: time ∝ V^{k:.2f}"
        if k is not None:
            print(f"{label}: fitted exponent {k:.3f} over {sum(x >= args.fit_from for x in v)} rungs")
            lo, hi = max(min(v), args.fit_from), max(v)
            ax.plot([lo, hi], [c * lo ** k, c * hi ** k], "--", color=color, linewidth=1)
        ax.plot(v, t, "o-", color=color, label=text)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("vertices")
    ax.set_ylabel("conformal map, seconds")
    ax.grid(True, which="both", alpha=0.3)
    memory = ax.twinx()
    rows = series[-1][1]
    memory.plot([int(r["vertices"]) for r in rows], [float(r["peak_mb"]) for r in rows], "s:",
                color="tab:orange", label=f"{series[-1][0]}: peak memory")
    memory.set_yscale("log")
    memory.set_ylabel("peak resident memory, MB")
    lines = ax.get_legend_handles_labels()
    more = memory.get_legend_handles_labels()
    ax.legend(lines[0] + more[0], lines[1] + more[1], loc="upper left")
    ax.set_title("Spherical conformal map over Loop subdivisions")
    fig.tight_layout()
    fig.savefig(args.output)


if __name__ == "__main__":
    main()
