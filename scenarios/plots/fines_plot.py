#!/usr/bin/python3
"""The figures of the fines sweep (scenarios/scenes/fines_sweep.toml).

    /usr/bin/python3 scenarios/plots/fines_plot.py fines_sweep.out [--out DIR]

Reads OUT/summary.h5 (carom sweep) and writes OUT/fines_sweep.png, three panels against the
fines mass fraction, one line per fines diameter, each point the mean over seeds with the
standard deviation over seeds as error bars:
  (a) the large beads' mixing rate k (fit of the Lacey index, M = 1 - (1 - M0) exp(-k t) from
      the measured start M0);
  (b) the two candidate mechanisms: the vertical interstitial gas velocity the large beads see
      (fines take pore volume), and the collision impulse per second a large bead receives from
      fines, per its weight;
  (c) the collision frequency of one large bead, split by partner (large, fines, walls).
Needs numpy, h5py and matplotlib (Debian: python3-numpy python3-h5py python3-matplotlib); the
sweep's tables are read by carom.open_sweep (carom_reader.py).
"""
import argparse
import os
import sys

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import style  # noqa: E402
from carom_reader import OutputError, open_sweep  # noqa: E402

DIAMETER = "species.fines.diameter"
FRACTION = "species.fines.fill.mass_fraction"
LARGE_DIAMETER = 1.0e-3  # m, fines_bed.toml


def metric(sweep, statistic, name):
    """The groups' mean or std (`statistic`) of a metric; NaN where the sweep lacks it."""
    table = sweep.mean if statistic == "mean" else sweep.std
    return table[name] if name in table else np.full(len(sweep.groups["group"]), np.nan)


def by_diameter(sweep):
    """(label, mask over groups sorted by fraction, order) for each fines diameter."""
    diameters = sweep.groups[DIAMETER]
    fractions = sweep.groups[FRACTION]
    out = []
    for d in sorted(set(diameters)):
        mask = np.where(diameters == d)[0]
        mask = mask[np.argsort(fractions[mask])]
        out.append((f"fines 1:{LARGE_DIAMETER / d:.0f} ({d * 1e3:.2g} mm)", mask))
    return fractions, out


def line(ax, sweep, name, scale=1.0, ylabel="", marker="o"):
    fractions, lines = by_diameter(sweep)
    mean, std = metric(sweep, "mean", name), metric(sweep, "std", name)
    # Fines diameters along a sequential map: not the species colours of the run figures.
    colours = style.sequence_colours(len(lines))
    for k, (label, idx) in enumerate(lines):
        ax.errorbar(100 * fractions[idx], scale * mean[idx], yerr=scale * np.nan_to_num(std[idx]),
                    marker=marker, capsize=3, color=colours[k], label=label)
    ax.set_xlabel("fines mass fraction (%)")
    ax.set_ylabel(ylabel)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("sweep", help="the sweep's output directory (holding summary.h5)")
    parser.add_argument("--out", help="where to write fines_sweep.png (default: the sweep directory)")
    args = parser.parse_args(argv)
    path = os.path.join(args.sweep, "summary.h5")
    out = os.path.join(args.out or args.sweep, "fines_sweep.png")
    try:
        sweep = open_sweep(path)
    except OutputError as error:
        sys.exit(str(error))
    n_completed = sweep.groups["n_completed"]
    fig, axes = plt.subplots(1, 4, figsize=(15, 3.8), gridspec_kw={"width_ratios": [1, 1, 1, 1.4]})
    line(axes[0], sweep, "analysis.mixing.rate", ylabel="mixing rate $k$ of the large beads (1/s)")
    axes[0].set_title("(a) mixing: $M = 1 - (1 - M_0)\,e^{-kt}$", fontsize=10)
    axes[0].legend()
    line(axes[1], sweep, "analysis.mechanism.gas_velocity_seen_large",
         ylabel="gas velocity at the large beads (m/s)")
    axes[1].set_title("(b1) interstitial gas (pore volume)", fontsize=10)
    line(axes[2], sweep, "analysis.mechanism.impulse_per_weight_large-fines",
         ylabel="impulse rate from fines / weight (-)")
    axes[2].set_title("(b2) collisions with fines", fontsize=10)

    ax = axes[3]
    fractions, lines = by_diameter(sweep)
    # Partners in the colours of their species in the run figures (large, fines: the order
    # of [[species]] in fines_bed.toml), the walls in grey.
    partners = [("large-large", "large beads", style.species_colour(0)),
                ("large-fines", "fines", style.species_colour(1)),
                ("large@walls", "walls", style.WALL_COLOUR)]
    labels, x, offset = [], [], 0
    for label, idx in lines:
        for i in idx:
            x.append(offset)
            labels.append(f"{label.split(' ')[1]}\n{100 * fractions[i]:.0f} %")
            offset += 1
        offset += 0.6
    order = [i for _, idx in lines for i in idx]
    bottom = np.zeros(len(order))
    for name, partner, colour in partners:
        values = np.nan_to_num(metric(sweep, "mean", f"analysis.collision_frequency.{name}")[order])
        ax.bar(x, values, 0.8, bottom=bottom, color=colour, label=f"with {partner}")
        bottom += values
    ax.set_xticks(x)
    ax.set_xticklabels(labels, fontsize=8)
    ax.set_ylabel("collisions per large bead per s")
    ax.set_title("(c) who a large bead collides with", fontsize=10)
    ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.0, 1.0))
    for a in axes:
        a.spines["top"].set_visible(False)
        a.spines["right"].set_visible(False)
    scene = sweep.scene
    fig.suptitle(f"{os.path.splitext(os.path.basename(scene))[0]}: mean and standard deviation over "
                 f"seeds ({int(n_completed.min())} per point)", fontsize=10)
    fig.tight_layout()
    fig.savefig(out, dpi=150)
    plt.close(fig)
    print(out)


if __name__ == "__main__":
    main()
