#!/usr/bin/python3
"""The fluid step and gas cell map (scenarios/scenes/stability_fluid.toml): the error of the small
fluidized bed's pressure drop and mixing rate against the finest fluid step and gas cells, and
the cost, from `carom chart`'s table (OUT/chart.csv, CHARTS.md), with each observable's
tolerance drawn.

    fluid_stability_plot.py OUT FIGURE.png

Variants are named "dt=STEP cell=SIZE" (one-way coupling: "one-way ..."). Panels: the gas force on
the beads per their weight (the pressure drop times the cross-section over the weight), the
mixing rate, each as error (%) against the fluid step, one line per cell size, error bars the
uncertainty over seeds (carom chart's u), the tolerance shaded; and the cost (CPU s per simulated
second). It also reads the mean pressure drop of each case after the inlet ramp from its run.h5
(/timeseries/gas_pressure_drop, t >= 0.1 s) and prints it beside the chart's numbers.
"""
import csv
import math
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.ticker  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from carom_reader import open_run  # noqa: E402

FORCE = "analysis.mechanism.gas_force_per_weight_glass"
MIXING = "analysis.mixing.rate"


def fail(message):
    sys.exit("fluid_stability_plot.py: error: " + message)


def number(x):
    try:
        return float(x)
    except ValueError:
        return float("nan")


def pressure_drops(out):
    """Mean pressure drop after the ramp per case, from OUT/chart_cases.csv and each run.h5."""
    drops = {}
    with open(os.path.join(out, "chart_cases.csv"), newline="") as f:
        for r in csv.DictReader(f):
            path = os.path.join(out, "cases", "%04d" % int(r["case"]), "run.h5")
            if r["status"] != "completed" or not os.path.exists(path):
                continue
            drop = open_run(path).series("gas_pressure_drop")
            drops.setdefault(r["variant"], []).append(float(np.mean(drop.values[drop.time >= 0.1])))
    return drops


def main():
    if len(sys.argv) != 3:
        fail("usage: fluid_stability_plot.py OUT FIGURE.png")
    out, figure = sys.argv[1], sys.argv[2]
    path = os.path.join(out, "chart.csv")
    if not os.path.exists(path):
        fail(path + " not found (run carom chart first)")
    with open(path, newline="") as f:
        table = list(csv.DictReader(f))
    tolerance = {}
    with open(os.path.join(out, "chart.toml")) as f:
        text = f.read()
    for key, tol in re.findall(r'key = "([^"]+)".*?\ntolerance = ([0-9.eE+-]+)', text, re.S):
        tolerance[key] = float(tol)
    drops = pressure_drops(out)
    ref_drop = [np.mean(v) for k, v in drops.items() if any(r["variant"] == k and r["reference"] == "true" for r in table)]
    ref_drop = ref_drop[0] if ref_drop else float("nan")

    lines = {}
    print("variant\tcost\tforce/weight\terror\tu\tmixing rate\terror\tu\tpressure drop (Pa, t>=0.1)\terror")
    for r in table:
        m = re.match(r"(one-way )?dt=(\S+) cell=(\S+)", r["variant"])
        if not m:
            continue
        dp = float(np.mean(drops.get(r["variant"], [float("nan")])))
        print("%s\t%.4g\t%.4g\t%+.4f\t%.4f\t%.4g\t%+.3f\t%.3f\t%.1f\t%+.4f" % (
            r["variant"], number(r["cost"]), number(r[FORCE + ":mean"]), number(r[FORCE + ":error"]),
            number(r[FORCE + ":uncertainty"]), number(r[MIXING + ":mean"]), number(r[MIXING + ":error"]),
            number(r[MIXING + ":uncertainty"]), dp, dp / ref_drop - 1))
        if m.group(1):
            continue
        lines.setdefault(m.group(3), []).append((float(m.group(2)), r))

    colours = {"1mm": "#1f77b4", "2mm": "#2ca02c", "4mm": "#d62728"}
    markers = {"1mm": "o", "2mm": "s", "4mm": "^"}
    fig, axes = plt.subplots(1, 3, figsize=(13, 4.1))
    panels = [(FORCE, "gas force / bed weight (pressure drop)"), (MIXING, "mixing rate")]
    for ax, (key, title) in zip(axes, panels):
        tol = 100 * tolerance.get(key, float("nan"))
        ax.axhspan(-tol, tol, color="0.92", zorder=0)
        ax.axhline(0, color="0.5", lw=0.8)
        for cell, pts in sorted(lines.items()):
            pts.sort(key=lambda x: x[0])
            dt = np.array([p[0] for p in pts])
            e = np.array([100 * number(p[1][key + ":error"]) for p in pts])
            u = np.array([100 * number(p[1][key + ":uncertainty"]) for p in pts])
            ax.errorbar(dt, e, yerr=u, color=colours.get(cell, "k"), marker=markers.get(cell, "o"), ms=5, lw=1.3,
                        capsize=2.5, label="gas cells of " + cell.replace("mm", " mm"))
        ax.set_xscale("log")
        ax.set_xlabel("fluid step (s)")
        ax.set_ylabel("error against dt = 1e-4 s, 1 mm cells (%)")
        ax.set_title(title, fontsize=11)
        ax.text(0.02, 0.96, "shaded: tolerance $\\pm$%g %%" % tol, transform=ax.transAxes, fontsize=8, va="top",
                color="0.3")
        ax.grid(True, which="major", color="0.85", lw=0.6)
    ax = axes[2]
    for cell, pts in sorted(lines.items()):
        dt = np.array([p[0] for p in pts])
        c = np.array([number(p[1]["cost"]) for p in pts])
        s = np.array([number(p[1]["cost_stderr"]) for p in pts])
        ax.errorbar(dt, c, yerr=s, color=colours.get(cell, "k"), marker=markers.get(cell, "o"), ms=5, lw=1.3,
                    capsize=2.5)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("fluid step (s)")
    ax.yaxis.set_major_formatter(matplotlib.ticker.ScalarFormatter())
    ax.yaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
    ax.set_yticks([2, 3, 5, 10, 20])
    ax.set_ylabel("CPU s per simulated second")
    ax.set_title("cost", fontsize=11)
    ax.grid(True, which="major", color="0.85", lw=0.6)
    handles, labels = axes[0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center", ncol=3, fontsize=9, frameon=False)
    fig.suptitle("Fluid step and gas cell size: 400 beads of 1 mm fluidized at 1.6 m/s, relax flights "
                 "(mean $\\pm$ standard error over seeds)", fontsize=11)
    fig.tight_layout(rect=(0, 0.08, 1, 0.95))
    fig.savefig(figure, dpi=150)
    print("wrote " + figure)


if __name__ == "__main__":
    main()
