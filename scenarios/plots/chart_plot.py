#!/usr/bin/python3
"""Draws the Pareto charts of a `carom chart` from OUT/chart.h5 (see scenarios/chart/CHARTS.md).

One figure per observable, OUT/pareto_KEY.png: the error of each variant against the reference
(absolute value) against its cost (CPU seconds per simulated second), log-log, with error bars
(the error's uncertainty; the cost's standard error over seeds), the variants labelled, the
Pareto front joined, the reference's cost and its own noise level drawn as lines, the tolerance
as a dashed line. Errors smaller than their uncertainty ("within noise") are drawn as open
triangles pointing down: the true error may be anywhere below the bar's top.

    chart_plot.py OUT                       # every observable
    chart_plot.py OUT --observable KEY      # one of them
    chart_plot.py OUT --out DIR             # write the figures elsewhere

The table (chart.csv), the statistics and the front are computed by carom itself (C++); this
script only draws them.
"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.ticker  # noqa: E402,F401
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from carom_reader import OutputError, open_chart  # noqa: E402


def fail(message):
    sys.exit("chart_plot.py: error: " + message)


def read(path):
    """What the figures draw of a chart's chart.h5, read by carom.open_chart."""
    try:
        table = open_chart(path)
    except OutputError as error:
        fail(str(error))
    variants = table.variants
    chart = {
        "reference": table.reference,
        "chart_file": table.chart_file,
        "names": list(variants["name"]),
        "is_reference": variants["reference"],
        "cost": variants["cost"],
        "cost_stderr": variants["cost_stderr"],
        "completed": variants["n_completed"],
        "observables": {},
    }
    for key, observable in table.observables.items():
        chart["observables"][key] = {
            "key": observable["key"],
            "tolerance": float(observable["tolerance"]),
            "measure": observable["error_measure"],
            **{name: observable[name] for name in ("mean", "stderr", "error", "uncertainty", "noise",
                                                   "within_noise", "within_tolerance", "pareto",
                                                   "pareto_within_noise")},
        }
    return chart


def place_labels(fig, axes, names, xs, ys):
    """Each label beside its point: right-above, right-below, left-above or left-below, the
    first that stays inside the axes and overlaps no label placed before (in order of cost)."""
    renderer = fig.canvas.get_renderer()
    frame = axes.get_window_extent(renderer)
    placed = []
    for name, x, y in sorted(zip(names, xs, ys), key=lambda t: t[1]):
        for dx, dy, ha in ((6, 5, "left"), (6, -13, "left"), (-6, 5, "right"), (-6, -13, "right")):
            label = axes.annotate(name, (x, y), textcoords="offset points", xytext=(dx, dy),
                                  ha=ha, fontsize=8)
            box = label.get_window_extent(renderer).expanded(1.05, 1.1)
            inside = (box.x0 >= frame.x0 and box.x1 <= frame.x1 and box.y0 >= frame.y0
                      and box.y1 <= frame.y1)
            if inside and not any(box.overlaps(other) for other in placed):
                break
            label.remove()
        else:
            label = axes.annotate(name, (x, y), textcoords="offset points", xytext=(6, 5), fontsize=8)
            box = label.get_window_extent(renderer)
        placed.append(box)


def plot(chart, name, obs, path):
    relative = obs["measure"] == "relative"
    scale = 100.0 if relative else 1.0
    unit = " (%)" if relative else ""
    cost, cost_err = chart["cost"], np.nan_to_num(chart["cost_stderr"])
    error = np.abs(obs["error"]) * scale
    uncertainty = np.nan_to_num(obs["uncertainty"]) * scale
    ref = int(np.flatnonzero(chart["is_reference"])[0])
    shown = [v for v in range(len(cost))
             if v != ref and np.isfinite(cost[v]) and cost[v] > 0 and np.isfinite(error[v]) and error[v] > 0]
    left_out = [chart["names"][v] for v in range(len(cost)) if v != ref and v not in shown]

    fig, axes = plt.subplots(figsize=(10, 5.2))
    # The front: non-dominated variants (the reference excepted: its error is 0 by definition).
    front = sorted((v for v in shown if obs["pareto"][v]), key=lambda v: cost[v])
    if len(front) > 1:
        axes.plot(cost[front], error[front], "-", color="tab:blue", lw=1.5, alpha=0.6, zorder=1,
                  label="Pareto front")
    styles = [
        (lambda v: obs["pareto"][v], dict(color="tab:blue", mfc="tab:blue"), "on the front"),
        (lambda v: obs["pareto_within_noise"][v], dict(color="tab:orange", mfc="white"),
         "dominated only within noise"),
        (lambda v: not obs["pareto"][v] and not obs["pareto_within_noise"][v],
         dict(color="tab:gray", mfc="tab:gray"), "dominated"),
    ]
    for pick, style, label in styles:
        for noisy in (False, True):
            rows = [v for v in shown if pick(v) and bool(obs["within_noise"][v]) == noisy]
            if not rows:
                continue
            # Within noise the error may be anywhere below the bar's top: no lower bar (log axes).
            lower = np.where(uncertainty[rows] < error[rows], uncertainty[rows], 0.0)
            axes.errorbar(cost[rows], error[rows], xerr=cost_err[rows], yerr=[lower, uncertainty[rows]],
                          fmt="v" if noisy else "o", ms=7, capsize=3, lw=1, zorder=3,
                          mfc="white" if noisy else style["mfc"], color=style["color"],
                          label=label + (" (error within noise)" if noisy else ""))
    ref_on_front = bool(obs["pareto"][ref])
    axes.axvline(cost[ref], color="k", ls="--", lw=1,
                 label=f"reference: {chart['reference']} ({cost[ref]:.3g} CPU s/s, error 0"
                       + (", on the front)" if ref_on_front else ")"))
    ref_noise = obs["noise"][ref] * scale
    if np.isfinite(ref_noise) and ref_noise > 0:
        text = f"reference's standard error ({ref_noise:.2g}{unit.strip(' ()')}"
        drawn = error[shown] if shown else np.array([ref_noise])
        if ref_noise >= drawn.min() / 30:
            axes.axhline(ref_noise, color="k", ls=":", lw=1, label=text + ")")
        else:  # far below every error: say it rather than stretch the axis over decades
            axes.plot([], [], " ", label=text + ", below the axis)")
    axes.axhline(obs["tolerance"] * scale, color="tab:red", ls="--", lw=1,
                 label=f"tolerance ({obs['tolerance'] * scale:.3g}{unit.strip(' ()')})")
    axes.set_xscale("log")
    axes.set_yscale("log")
    if ref_on_front and front and np.isfinite(cost[ref]):
        # The front ends at the reference (error 0, below every log axis): drop to it.
        bottom = axes.get_ylim()[0]
        last = front[-1]
        axes.plot([cost[last], cost[ref], cost[ref]], [error[last], error[last], bottom], ":",
                  color="tab:blue", lw=1.5, alpha=0.6, zorder=1)
        axes.set_ylim(bottom=bottom)
    for axis, limits in ((axes.xaxis, axes.get_xlim()), (axes.yaxis, axes.get_ylim())):
        if np.log10(limits[1] / limits[0]) < 1.5:  # few decades: label the 2x and 5x ticks too
            axis.set_minor_locator(matplotlib.ticker.LogLocator(subs=(2.0, 5.0)))
            axis.set_minor_formatter(matplotlib.ticker.FuncFormatter(lambda x, _: f"{x:g}"))
    axes.set_xlabel("cost: CPU seconds per simulated second")
    axes.set_ylabel(f"|{'relative ' if relative else ''}error| of {obs['key']}{unit}")
    title = f"{os.path.basename(chart['chart_file'])}: {obs['key']}"
    if left_out:
        title += "\nnot drawn (no completed case, or an error of exactly 0): " + ", ".join(left_out)
    axes.set_title(title, fontsize=10)
    axes.grid(True, which="both", alpha=0.25)
    axes.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0)
    fig.tight_layout()
    place_labels(fig, axes, [chart["names"][v] for v in shown], cost[shown], error[shown])
    fig.savefig(path, dpi=120)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("out", help="the chart's output directory (holds chart.h5)")
    parser.add_argument("--observable", help="draw only this observable (its summary.json key)")
    parser.add_argument("--out", dest="figures", help="folder for the figures (default: OUT)")
    args = parser.parse_args()
    path = os.path.join(args.out, "chart.h5")
    if not os.path.exists(path):
        fail(f"{path} does not exist (run `carom chart CHART.toml` first)")
    chart = read(path)
    keys = list(chart["observables"])
    if args.observable:
        if args.observable.replace("/", "_") not in keys:
            fail(f"'{args.observable}' is not an observable of this chart (observables: {', '.join(keys)})")
        keys = [args.observable.replace("/", "_")]
    folder = args.figures or args.out
    os.makedirs(folder, exist_ok=True)
    for key in keys:
        target = os.path.join(folder, f"pareto_{key}.png")
        plot(chart, key, chart["observables"][key], target)
        print(target)


if __name__ == "__main__":
    main()
