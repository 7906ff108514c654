"""Figures of a run's analysis (scene [analysis]; run_analysis.hpp), used by plot.py.

  RUN_mixing.png   (runs with [analysis.mixing]) the Lacey index against time with the fitted
                   M = 1 - (1 - M0) exp(-k t) (M0 the measured start) and the time to
                   M = 0.8; the axial mean squared
                   displacement with the confined-bed fit and its saturation; and side
                   views of the bed at t = 0 and at the last snapshot with the tagged (lower
                   half) and untagged beads in two colours;
  RUN_collisions.png  collision frequency per particle of every species pair, measured exactly
                   at the events beside kinetic theory from the local fields; the granular
                   temperature of each species and the segregation index against time.
  RUN_profiles.png (runs with [analysis.profiles]) across each section: the solid fraction,
                   the mean of the vertical and the cross velocity component with bands of one
                   standard deviation, and the mean spin about the third axis.
  RUN_plugs.png    (runs with [analysis.plugs]) the axial solid fraction as a space-time
                   diagram and the bed top against time (plug_plots.py).
The fitted numbers come from summary.json beside the run file (its "analysis" object).
"""
import json
import os

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.collections import EllipseCollection

TAG_COLOURS = ("#1f77b4", "#ff7f0e")  # lower half (tagged), upper half
OTHER_COLOUR = "0.8"


def _text(value):
    return value.decode("utf-8") if isinstance(value, bytes) else str(value)


def read_summary(run_path):
    path = os.path.join(os.path.dirname(os.path.abspath(run_path)), "summary.json")
    try:
        with open(path) as f:
            return json.load(f).get("analysis", {})
    except (OSError, ValueError):
        return {}


def _side_view(ax, run, snapshot, tagged, mixing_species, vertical, top):
    across = 0 if vertical != 0 else 1
    depth = 3 - across - vertical
    lower, upper = run["domain/lower"][()], run["domain/upper"][()]
    position = snapshot["position"][()]
    radius = snapshot["radius"][()]
    species = snapshot["species"][()]
    ids = snapshot["id"][()]
    tag_ids = run["analysis/id"][()]
    tag = np.zeros(len(ids), dtype=int)
    tag[np.isin(ids, tag_ids[tagged != 0])] = 1
    order = np.argsort(position[:, depth])
    colours = []
    for k in order:
        if species[k] != mixing_species:
            colours.append(OTHER_COLOUR)
        else:
            colours.append(TAG_COLOURS[0] if tag[k] else TAG_COLOURS[1])
    ax.add_collection(EllipseCollection(2 * radius[order], 2 * radius[order], np.zeros(len(order)),
                                        units="xy", offsets=position[order][:, [across, vertical]],
                                        transOffset=ax.transData, facecolors=colours,
                                        edgecolors="black", linewidths=0.2))
    ax.set_xlim(lower[across], upper[across])
    ax.set_ylim(lower[vertical], min(upper[vertical], top))
    ax.set_aspect("equal")
    ax.set_xticks([])
    ax.set_yticks([])
    ax.set_title(f"$t$ = {snapshot.attrs['time']:.3g} s", fontsize=9)


def confined_msd(t, d, saturation, terms=2001):
    """MSD of tracers filling a bed of height H = sqrt(6 S) between reflecting ends
    (dispersion.hpp, confined_mean_squared_displacement)."""
    h2 = 6 * saturation
    m = np.arange(1, terms + 1, 2)[:, None]
    series = np.sum(np.exp(-(m * np.pi)**2 * d * np.asarray(t)[None, :] / h2) / m**4, axis=0)
    return saturation * (1 - 96 / np.pi**4 * series)


def plot_mixing(run, run_path, path, dpi):
    analysis = read_summary(run_path)
    mixing = analysis.get("mixing", {})
    dispersion = analysis.get("dispersion", {})
    series = run["timeseries"]
    t = series["time"][()]
    lacey = series["lacey_index"][()]
    msd = series["axial_msd"][()]
    mixing_species = int(run["analysis"].attrs["mixing_species"])
    vertical = int(run["analysis"].attrs["vertical_axis"])
    names = [_text(n) for n in run["species/name"][()]]

    fig = plt.figure(figsize=(10, 4.2))
    grid = fig.add_gridspec(1, 4, width_ratios=[1.3, 1.3, 0.6, 0.6], wspace=0.4)
    ax = fig.add_subplot(grid[0])
    ax.plot(t, lacey, "o", ms=3, color="0.2", label="Lacey index")
    k = mixing.get("rate")
    m0 = mixing.get("fit_start") or 0.0  # the measured M(0) the fit starts from
    if k:
        tt = np.linspace(0, t.max(), 200)
        ax.plot(tt, 1 - (1 - m0) * np.exp(-k * tt), color="C3",
                label=f"$1 - (1 - M_0)e^{{-kt}}$: $M_0$ = {m0:.2f}, $k$ = {k:.3g}/s")
    ax.axhline(0.8, color="0.6", ls=":", lw=1)
    t08 = mixing.get("time_to_m08_fit")
    if t08 and t08 < 1.5 * t.max():
        ax.axvline(t08, color="C3", ls=":", lw=1)
        ax.text(t08, 0.0, f"$t_{{0.8}}$ = {t08:.2g} s ", color="C3", fontsize=8, ha="right")
    ax.set_ylim(-0.05, 1.1)
    ax.set_xlabel("$t$ (s)")
    ax.set_ylabel(f"Lacey index $M$ ({names[mixing_species]}, lower/upper half)")
    # Legends below the panels: above them they hid the data.
    ax.legend(loc="upper left", bbox_to_anchor=(0.0, -0.16), fontsize=8)

    ax = fig.add_subplot(grid[1])
    ax.plot(t, msd * 1e6, "o", ms=3, color="0.2", label="measured")
    d = dispersion.get("axial_coefficient")
    saturation = dispersion.get("saturation_msd")
    if d and saturation:
        tt = np.linspace(0, t.max(), 300)
        ax.plot(tt, confined_msd(tt, d, saturation) * 1e6, color="C0",
                label=f"confined-bed fit, $D$ = {d:.3g} m$^2$/s")
    if saturation:
        ax.axhline(saturation * 1e6, color="0.6", ls=":", lw=1, label="saturation 2 Var($h$)")
    ax.set_xlabel("$t$ (s)")
    ax.set_ylabel("axial MSD about the mean (mm$^2$)")
    ax.legend(loc="upper left", bbox_to_anchor=(0.0, -0.16), fontsize=8)

    snapshots = sorted(run["snapshots"].keys())
    tagged = run["analysis/tagged"][()]
    shown = [run["snapshots"][snapshots[0]], run["snapshots"][snapshots[-1]]]
    # One height for both views: the highest bead of the mixing species plus a margin.
    top = max(np.percentile(s["position"][()][s["species"][()] == mixing_species, vertical], 99.5)
              for s in shown) + 4 * max(s["radius"][()].max() for s in shown)
    for column, snapshot in zip((2, 3), shown):
        _side_view(fig.add_subplot(grid[column]), run, snapshot, tagged, mixing_species, vertical, top)
    fig.text(0.75, 0.02, "blue: lower half at $t$ = 0, orange: upper half, grey: other species",
             ha="center", fontsize=8)
    fig.savefig(path, dpi=dpi, bbox_inches="tight")
    plt.close(fig)


def plot_collisions(run, run_path, path, dpi):
    analysis = read_summary(run_path)
    names = [_text(n) for n in run["species/name"][()]]
    measured = analysis.get("collision_frequency", {})
    kinetic = analysis.get("kinetic_theory_frequency", {})
    series = run["timeseries"]
    t = series["time"][()]
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    ax = axes[0]
    pairs = [f"{a}-{b}" for a in names for b in names] + [f"{a}@walls" for a in names]
    x = np.arange(len(pairs))
    value = lambda table, key: table.get(key) if table.get(key) is not None else np.nan  # noqa: E731
    ax.bar(x - 0.2, [value(measured, p) for p in pairs], 0.4, color="C0", label="measured (events)")
    ax.bar(x + 0.2, [value(kinetic, p) for p in pairs], 0.4, color="C1",
           label="kinetic theory (local fields)")
    ax.set_xticks(x)
    ax.set_xticklabels(pairs, rotation=30, ha="right")
    ax.set_ylabel("collisions per particle per s")
    ax.set_yscale("log")
    ax.legend()
    ax.set_title("row species collides with column species", fontsize=9)

    ax = axes[1]
    temperature = series["granular_temperature"][()].reshape(len(t), -1)
    for s, name in enumerate(names):
        ax.semilogy(t, temperature[:, s], color=f"C{s}", label=f"$\\theta$ {name}")
    ax.set_xlabel("$t$ (s)")
    ax.set_ylabel("granular temperature $\\theta$ (m$^2$/s$^2$)")
    if "segregation_index" in series:
        twin = ax.twinx()
        twin.plot(t, series["segregation_index"][()], color="0.3", ls="--", label="segregation index")
        twin.set_ylabel("segregation index $2(h_s - h_l)/(h_s + h_l)$")
        twin.spines["right"].set_visible(True)
        lines = ax.get_legend_handles_labels()
        more = twin.get_legend_handles_labels()
        ax.legend(lines[0] + more[0], lines[1] + more[1], loc="best")
    else:
        ax.legend()
    fig.tight_layout()
    fig.savefig(path, dpi=dpi)
    plt.close(fig)


def plot_profiles(run, run_path, path, dpi):
    profiles = read_summary(run_path).get("profiles")
    if not profiles:
        return
    axes_names = "xyz"
    across, up = profiles["axis"], profiles["vertical"]
    a, v = axes_names.index(across), axes_names.index(up)
    third = 3 - a - v
    x = np.asarray(profiles["bin_centres"], dtype=float) * 1e3
    nan = lambda values: np.array([np.nan if u is None else u for u in values], dtype=float)  # noqa: E731
    fig, axes = plt.subplots(1, 4, figsize=(15, 3.8))
    for k, section in enumerate(profiles["sections"]):
        colour = f"C{k}"
        label = f"{up} = {section['height'] * 1e3:.4g} mm"
        axes[0].plot(x, nan(section["solid_fraction"]), "o-", color=colour, label=label)
        mean = np.array([nan(m) for m in section["mean_velocity"]])
        spread = np.array([nan(m) for m in section["std_velocity"]])
        for ax, c in ((axes[1], v), (axes[2], a)):
            ax.plot(x, mean[:, c], "o-", color=colour, label=label)
            ax.fill_between(x, mean[:, c] - spread[:, c], mean[:, c] + spread[:, c], color=colour,
                            alpha=0.15, lw=0)
        spin = np.array([nan(m) for m in section["mean_spin"]])
        axes[3].plot(x, spin[:, third], "o-", color=colour, label=label)
    axes[0].set_ylabel("solid fraction")
    axes[1].set_ylabel(f"$v_{up}$ (m/s): mean, band $\\pm$ one std")
    axes[2].set_ylabel(f"$v_{across}$ (m/s): mean, band $\\pm$ one std")
    axes[3].set_ylabel(f"mean spin $\\omega_{axes_names[third]}$ (rad/s)")
    for ax in axes:
        ax.set_xlabel(f"{across} (mm)")
    axes[0].set_ylim(bottom=0)
    axes[0].legend(fontsize=8)
    window = (f"{profiles['samples']} samples, t = {profiles['first']:.3g} to {profiles['last']:.3g} s"
              if profiles["samples"] else "no samples in the window")
    fig.suptitle(f"Profiles across sections {profiles['thickness'] * 1e3:.3g} mm thick ({window})",
                 fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=dpi)
    plt.close(fig)


def analysis_figures(run, run_path):
    """(name, draw(path, dpi)) for each analysis figure this run file supports."""
    figures = []
    series = run["timeseries"]
    if "analysis" in run and "lacey_index" in series and len(run["snapshots"]) > 0:
        figures.append(("mixing", lambda p, dpi: plot_mixing(run, run_path, p, dpi)))
    if "granular_temperature" in series:
        figures.append(("collisions", lambda p, dpi: plot_collisions(run, run_path, p, dpi)))
    if "profile_sums" in series:
        figures.append(("profiles", lambda p, dpi: plot_profiles(run, run_path, p, dpi)))
    if "axial_solid_fraction" in series and "analysis" in run and "plugs" in run["analysis"]:
        from plug_plots import plot_plugs
        figures.append(("plugs", lambda p, dpi: plot_plugs(run, read_summary(run_path), p, dpi)))
    return figures
