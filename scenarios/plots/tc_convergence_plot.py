#!/usr/bin/python3
"""Collision and impact frequencies against the TC time, from a chart whose variants set
collisions.collapse.contact_time (scenarios/scenes/fines_bed_tc_chart.toml), with the chart's
other variants (soft spheres) as bands at the right.

    /usr/bin/python3 scenarios/plots/tc_convergence_plot.py out/fines_bed_tc_chart.out [--out FILE]

Writes DIR/tc_convergence.png: one panel per species pair that the chart has both
analysis.collision_frequency.PAIR and analysis.impact_frequency.PAIR for (else impacts alone),
each value the mean over the seeds with its standard error. The TC time is read from each
variant's settings in the chart file (chart.toml in the output directory)."""

import argparse
import os
import sys
import tomllib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from carom_reader import OutputError, open_chart  # noqa: E402
import style  # noqa: E402

TC_KEY = "collisions.collapse.contact_time"


def variant_tc_times(directory):
    """{variant name: its TC time (s), or None} from the chart file copied into `directory`."""
    with open(os.path.join(directory, "chart.toml"), "rb") as f:
        chart = tomllib.load(f)
    times = {}
    for v in chart.get("chart", {}).get("variant", []):
        settings = v.get("set", {})
        kind = settings.get("method.kind", "event_driven")
        times[v["name"]] = settings.get(TC_KEY) if kind == "event_driven" else None
    return times


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("directory", help="the chart's output directory")
    parser.add_argument("--out", help="figure file (default DIR/tc_convergence.png)")
    args = parser.parse_args()
    try:
        chart = open_chart(args.directory)
    except OutputError as e:
        sys.exit(f"tc_convergence_plot.py: {e}")
    directory = os.path.dirname(chart.path)
    times = variant_tc_times(directory)
    names = list(chart.variants["name"])
    pairs = [k.split(".")[-1] for k in chart.observable_keys if k.startswith("analysis.impact_frequency.")]
    if not pairs:
        sys.exit("tc_convergence_plot.py: the chart has no analysis.impact_frequency observable")
    fig, axes = plt.subplots(1, len(pairs), figsize=(4.2 * len(pairs), 4.2), squeeze=False)
    for ax, pair in zip(axes[0], pairs):
        for kind, marker, label in (("collision_frequency", "s", "collisions (raw count)"),
                                    ("impact_frequency", "o", "impacts")):
            key = f"analysis.{kind}.{pair}"
            if key not in chart.observables:
                continue
            column = chart.observables[key]
            tc = [(times.get(n), m, s) for n, m, s in zip(names, column["mean"], column["stderr"])
                  if times.get(n) is not None]
            tc.sort()
            x = np.array([t for t, _, _ in tc])
            colour = style.species_colour(0 if kind == "impact_frequency" else 1)
            ax.errorbar(x, [m for _, m, _ in tc], yerr=[s for _, _, s in tc], marker=marker,
                        color=colour, capsize=3, label=f"event-driven: {label}")
            # Other methods (no TC time): a band of mean +- standard error across the panel.
            for n, m, s in zip(names, column["mean"], column["stderr"]):
                if times.get(n) is None and np.isfinite(m):
                    ax.axhspan(m - s, m + s, color=colour, alpha=0.18)
                    ax.axhline(m, color=colour, ls=":", lw=1.2, label=f"{n}: {label}")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.invert_xaxis()
        ax.set_xlabel("TC time (s), shorter to the right")
        ax.set_ylabel(f"{pair} per particle (1/s)")
        ax.set_title(pair, fontsize=10)
        ax.grid(True, which="both", alpha=0.25)
    handles, labels = axes[0][0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center", ncol=2, fontsize=8, frameon=False)
    fig.suptitle(f"{os.path.basename(chart.chart_file)}: frequencies against the TC time "
                 f"(mean ± standard error over the seeds)", fontsize=10)
    fig.tight_layout(rect=(0, 0.12, 1, 0.95))
    out = args.out or os.path.join(directory, "tc_convergence.png")
    fig.savefig(out, dpi=120)
    print(f"tc_convergence_plot.py: wrote {out}")


if __name__ == "__main__":
    main()
