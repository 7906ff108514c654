#!/usr/bin/python3
"""Plots the results of a `carom sweep` from OUT/summary.h5 (see SWEEPS.md).

Group means against a varied key, with the standard deviation over seeds as error bars:

    sweep_plot.py OUT/summary.h5 --x species.fines.diameter --y analysis.mixing.rate \
        --group species.fines.fill.mass_fraction --out rate.png

Stacked bars of several metrics per group (a breakdown, e.g. collision frequencies by pair;
shell-style patterns such as 'collision_rate_per_particle.*' pick several metrics at once):

    sweep_plot.py OUT/summary.h5 --stack 'collision_rate_per_particle.*' --out rates.png

Every varied key other than --x and --group must take one value in the plotted rows: fix it
with --where KEY=VALUE. --list prints the varied keys and metrics and exits.
"""
import argparse
import fnmatch
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from carom_reader import OutputError, open_sweep  # noqa: E402


def label(name):
    """An axis label from a dotted key: 'species.fines.diameter' -> 'species fines: diameter'."""
    parts = name.split(".")
    return parts[-1].replace("_", " ") if len(parts) == 1 else " ".join(parts[:-1]) + ": " + parts[-1].replace("_", " ")


def fail(message):
    sys.exit("sweep_plot.py: error: " + message)


class Groups:
    """The groups of a sweep (carom.open_sweep): varied values, counts, mean and std of every
    metric, and the rows picked so far."""

    def __init__(self, path):
        try:
            sweep = open_sweep(path)
        except OutputError as error:
            fail(str(error))
        self.scene = sweep.scene
        self.keys = sweep.varied_keys
        self.metrics = sweep.metrics
        self.values = {k: sweep.groups[k] for k in self.keys}
        self.completed = sweep.groups["n_completed"]
        self.mean = sweep.mean
        self.std = sweep.std
        self.rows = np.arange(len(self.completed))

    def key(self, name):
        if name not in self.keys:
            fail(f"'{name}' is not a varied key (varied keys: {', '.join(self.keys) or 'none'})")
        return name

    def metric(self, name):
        if name not in self.metrics:
            near = [m for m in self.metrics if name.split(".")[-1] in m][:5]
            fail(f"'{name}' is not a metric of this sweep" + (f" (similar: {', '.join(near)})" if near else "")
                 + "; --list shows them all")
        return name

    def select(self, where):
        """Keeps the rows where every KEY=VALUE holds."""
        for condition in where:
            if "=" not in condition:
                fail(f"--where {condition}: expected KEY=VALUE")
            k, v = condition.split("=", 1)
            column = self.values[self.key(k)]
            keep = np.isclose(column, float(v)) if column.dtype.kind == "f" else column == v
            if not keep[self.rows].any():
                fail(f"--where {condition}: no group has {k} = {v} (values: {sorted(set(column.tolist()))})")
            self.rows = self.rows[keep[self.rows]]

    def check_fixed(self, free):
        for k in self.keys:
            if k not in free and len(set(self.values[k][self.rows].tolist())) > 1:
                fail(f"'{k}' takes several values in the plotted groups: plot them as lines with --group {k}, "
                     f"or pick one with --where {k}=VALUE")

    def describe(self, row, keys):
        """'e = 0.9\ndiameter = 0.5': the values of `keys` in a group, by their last name part
        (the full key where two share a last part)."""
        short = [k.split(".")[-1] for k in keys]
        names = [s if short.count(s) == 1 else k for s, k in zip(short, keys)]
        return "\n".join(f"{n}={self.values[k][row]}" for n, k in zip(names, keys))


def plot_lines(groups, args, axes):
    x_key = groups.key(args.x)
    y = groups.metric(args.y)
    if groups.values[x_key].dtype.kind != "f":
        fail(f"--x {x_key}: its values are not numbers; use --stack for a bar chart")
    free = [x_key] + ([groups.key(args.group)] if args.group else [])
    groups.check_fixed(free)
    lines = sorted(set(groups.values[args.group][groups.rows].tolist())) if args.group else [None]
    for value in lines:
        rows = groups.rows if value is None else groups.rows[groups.values[args.group][groups.rows] == value]
        rows = rows[np.argsort(groups.values[x_key][rows])]
        error = np.nan_to_num(groups.std[y][rows])
        axes.errorbar(groups.values[x_key][rows], groups.mean[y][rows], yerr=error, marker="o", capsize=4,
                      label=None if value is None else str(value))
    axes.set_xlabel(label(x_key))
    axes.set_ylabel(label(y))
    if args.group:
        axes.legend(title=label(args.group))
    if args.logx:
        axes.set_xscale("log")


def plot_stack(groups, args, axes):
    metrics = []
    for pattern in args.stack.split(","):
        found = fnmatch.filter(groups.metrics, pattern.strip())
        if not found:
            groups.metric(pattern.strip())
        metrics += [m for m in found if m not in metrics]
    groups.check_fixed(groups.keys)
    shown = [k for k in groups.keys if len(set(groups.values[k][groups.rows].tolist())) > 1]
    names = [groups.describe(r, shown) or "all" for r in groups.rows]
    position = np.arange(len(groups.rows))
    bottom = np.zeros(len(groups.rows))
    for m in metrics:
        height = np.nan_to_num(groups.mean[m][groups.rows])
        axes.bar(position, height, bottom=bottom, label=m.split(".")[-1] if len(set(
            ".".join(n.split(".")[:-1]) for n in metrics)) == 1 else m)
        bottom += height
    axes.set_xticks(position, names, fontsize=9)
    prefix = {".".join(m.split(".")[:-1]) for m in metrics}
    axes.set_ylabel(label(prefix.pop()) if len(prefix) == 1 else "mean over seeds")
    axes.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("summary", help="OUT/summary.h5 written by carom sweep")
    parser.add_argument("--x", help="varied key on the horizontal axis")
    parser.add_argument("--y", help="metric on the vertical axis (its group mean)")
    parser.add_argument("--group", help="varied key: one line per value")
    parser.add_argument("--stack", help="comma-separated metrics (or patterns) stacked as bars, one bar per group")
    parser.add_argument("--where", action="append", default=[], help="KEY=VALUE: plot only these groups")
    parser.add_argument("--logx", action="store_true", help="logarithmic x axis")
    parser.add_argument("--title", help="plot title (default: the scene's file name)")
    parser.add_argument("--out", help="image file (default: show the plot, or sweep.png without a display)")
    parser.add_argument("--list", action="store_true", help="print the varied keys and the metrics, then exit")
    args = parser.parse_args()

    groups = Groups(args.summary)
    if args.list:
        print("varied keys:", ", ".join(groups.keys) or "none")
        print("metrics:\n  " + "\n  ".join(groups.metrics))
        return
    if bool(args.stack) == bool(args.x or args.y):
        fail("give either --x KEY --y METRIC (a line plot) or --stack METRICS (bars)")
    if not args.stack and not (args.x and args.y):
        fail("a line plot needs both --x KEY and --y METRIC")
    groups.select(args.where)
    if (groups.completed[groups.rows] == 0).any():
        print("sweep_plot.py: note: some groups have no completed case; they are left out", file=sys.stderr)
        groups.rows = groups.rows[groups.completed[groups.rows] > 0]

    plt.rcParams.update({"font.size": 12})
    width = max(7.0, 1.4 * len(groups.rows) + 2.0) if args.stack else 7.0
    figure, axes = plt.subplots(figsize=(width, 5), layout="constrained")
    (plot_stack if args.stack else plot_lines)(groups, args, axes)
    axes.set_title(args.title or groups.scene.split("/")[-1])
    axes.grid(alpha=0.3)
    out = args.out or "sweep.png"
    figure.savefig(out, dpi=150)
    print("sweep_plot.py: wrote", out)


if __name__ == "__main__":
    main()
