"""Figures of a run's analysis (scene [analysis]; run_analysis.hpp), used by plot.py.

  RUN_mixing.png   (runs with [analysis.mixing]) the Lacey index against time with the fitted
                   M = 1 - (1 - M0) exp(-k t) (M0 the measured start), the time to M = 0.8
                   from the data (first reached, interpolated) beside the fit's; the axial
                   mean squared displacement with the confined-bed fit and its saturation;
                   and side views of the bed at t = 0 and at the last snapshot, the mixing
                   species in its colour (lower half at t = 0 dark, upper half light), the
                   other species pale in theirs;
  RUN_collisions.png  collision frequency per particle of every species pair, measured exactly
                   at the events beside kinetic theory from the local fields (bars in the
                   colour of the species whose frequency it is); the granular temperature of
                   each species and the segregation index against time.
  RUN_profiles.png (runs with [analysis.profiles]) across each section: the solid fraction,
                   the mean of the vertical and the cross velocity component with bands of one
                   standard deviation, and the mean spin about the third axis.
  RUN_plugs.png    (runs with [analysis.plugs]) the axial solid fraction as a space-time
                   diagram and the bed top against time (plug_plots.py).
The fitted numbers come from summary.json beside the run file (its "analysis" object); the run
file and summary.json are read through carom.open (carom_reader.py).
"""
import matplotlib.pyplot as plt
import numpy as np
from matplotlib.collections import EllipseCollection
from matplotlib.patches import Patch
from matplotlib.ticker import MaxNLocator

import style

# The mixing species in its species colour: the lower half at t = 0 (tagged) darker, the upper
# half lighter; every other species in its own colour, pale, so that it stays in the picture
# without hiding the mixing.
TAGGED_SHADE, UNTAGGED_SHADE, OTHER_SHADE = -0.35, 0.55, 0.7
FIT_COLOUR = "#7570b3"  # fits (not a species colour)


def tag_colours(mixing_species):
    """(lower half, upper half) colours of the mixing species."""
    colour = style.species_colour(mixing_species)
    return style.shade(colour, TAGGED_SHADE), style.shade(colour, UNTAGGED_SHADE)


def read_summary(run):
    """summary.json's "analysis" object beside the run file; {} without a readable one (the
    figures then show the measured data without the fits)."""
    try:
        return run.analysis or {}
    except (OSError, ValueError):
        return {}


def _side_view(ax, domain, snapshot, lower_ids, mixing_species, vertical, top):
    """One side view of `snapshot` (carom.Output.particles); `lower_ids`: the ids of the
    particles in the lower half at t = 0."""
    across = 0 if vertical != 0 else 1
    depth = 3 - across - vertical
    lower, upper = domain["lower"], domain["upper"]
    position = snapshot["position"]
    radius = snapshot["radius"]
    species = snapshot["species"]
    ids = snapshot["id"]
    tag = np.zeros(len(ids), dtype=int)
    tag[np.isin(ids, lower_ids)] = 1
    order = np.argsort(position[:, depth])
    lower_half, upper_half = tag_colours(mixing_species)
    colours = []
    for k in order:
        if species[k] != mixing_species:
            colours.append(style.shade(style.species_colour(species[k]), OTHER_SHADE))
        else:
            colours.append(lower_half if tag[k] else upper_half)
    ax.add_collection(EllipseCollection(2 * radius[order], 2 * radius[order], np.zeros(len(order)),
                                        units="xy", offsets=position[order][:, [across, vertical]],
                                        transOffset=ax.transData, facecolors=colours,
                                        edgecolors="black", linewidths=0.2))
    ax.set_xlim(lower[across], upper[across])
    ax.set_ylim(lower[vertical], min(upper[vertical], top))
    ax.set_aspect("equal")
    ax.set_xticks([])
    ax.set_yticks([])
    width = (upper[across] - lower[across]) * 1e3
    height = (min(upper[vertical], top) - lower[vertical]) * 1e3
    ax.set_xlabel(f"{'xyz'[across]}: {width:.3g} mm wide", fontsize=8)
    ax.set_ylabel(f"{'xyz'[vertical]}: {height:.3g} mm shown", fontsize=8)
    ax.set_title(f"$t$ = {snapshot['time']:.3g} s", fontsize=9)


def confined_msd(t, d, saturation, terms=2001):
    """MSD of tracers filling a bed of height H = sqrt(6 S) between reflecting ends
    (dispersion.hpp, confined_mean_squared_displacement)."""
    h2 = 6 * saturation
    m = np.arange(1, terms + 1, 2)[:, None]
    series = np.sum(np.exp(-(m * np.pi)**2 * d * np.asarray(t)[None, :] / h2) / m**4, axis=0)
    return saturation * (1 - 96 / np.pi**4 * series)


def time_to_08_from_data(t, lacey):
    """First time the Lacey index reaches 0.8, s, interpolated linearly between samples as
    mixing.hpp's time_to_08_data (for summaries without it); None if it never does."""
    lacey = np.asarray(lacey, dtype=float)
    reached = np.flatnonzero(lacey >= 0.8)
    if len(reached) == 0:
        return None
    k = reached[0]
    if k == 0 or not np.isfinite(lacey[k - 1]):
        return float(t[k])
    return float(t[k - 1] + (0.8 - lacey[k - 1]) / (lacey[k] - lacey[k - 1]) * (t[k] - t[k - 1]))


def time_staying_above_08(t, lacey):
    """Time from which the Lacey index stays at or above 0.8 to the end of the run, s
    (interpolated like time_to_08_from_data); None if the last sample is below 0.8. A start-up
    spike (a bed lifted as a slug) can reach 0.8 long before the bed is mixed."""
    lacey = np.asarray(lacey, dtype=float)
    if len(lacey) == 0 or not lacey[-1] >= 0.8:
        return None
    below = np.flatnonzero(~(lacey >= 0.8))
    if len(below) == 0:
        return float(t[0])
    k = below[-1] + 1
    if not np.isfinite(lacey[k - 1]):
        return float(t[k])
    return float(t[k - 1] + (0.8 - lacey[k - 1]) / (lacey[k] - lacey[k - 1]) * (t[k] - t[k - 1]))


def plot_mixing(run, path, dpi):
    analysis = read_summary(run)
    mixing = analysis.get("mixing", {})
    dispersion = analysis.get("dispersion", {})
    t = run.series("time").values
    lacey = run.series("lacey_index").values
    msd = run.series("axial_msd").values
    setup = run.analysis_data()
    mixing_species = int(setup["mixing_species"])
    vertical = int(setup["vertical_axis"])
    names = run.species_names

    fig = plt.figure(figsize=(11, 4.4))
    grid = fig.add_gridspec(1, 4, width_ratios=[1.3, 1.3, 0.6, 0.6], wspace=0.45)
    ax = fig.add_subplot(grid[0])
    ax.plot(t, lacey, "o", ms=3, mfc="none", color="black", label="Lacey index, measured")
    k = mixing.get("rate")
    m0 = mixing.get("fit_start") or 0.0  # the measured M(0) the fit starts from
    if k:
        tt = np.linspace(0, t.max(), 200)
        ax.plot(tt, 1 - (1 - m0) * np.exp(-k * tt), color=FIT_COLOUR,
                label=f"fit $1 - (1 - M_0)e^{{-kt}}$: $M_0$ = {m0:.2f}, $k$ = {k:.3g} 1/s")
    ax.axhline(0.8, color=style.REFERENCE_COLOUR, ls=":", lw=0.8)
    # Where M first reaches 0.8 in the data, and where the fit does: a fit over the whole run
    # can reach it later or earlier than the data.
    t08_data = mixing.get("time_to_m08")
    if t08_data is None:
        t08_data = time_to_08_from_data(t, lacey)
    if t08_data is not None:
        ax.axvline(t08_data, color="black", ls="--", lw=0.9,
                   label=f"$t_{{0.8}}$ from the data (first reach 0.8): {t08_data:.3g} s")
    else:
        ax.plot([], [], ls="", label="the data never reach $M$ = 0.8")
    t08_stay = time_staying_above_08(t, lacey)
    step = np.median(np.diff(t)) if len(t) > 1 else 0.0
    if t08_data is not None and t08_stay is not None and t08_stay - t08_data > 2 * step:
        ax.axvline(t08_stay, color="black", ls="-.", lw=0.9,
                   label=f"data at or above 0.8 from {t08_stay:.3g} s to the end")
    t08 = mixing.get("time_to_m08_fit")
    if t08 and t08 < 1.5 * t.max():
        ax.axvline(t08, color=FIT_COLOUR, ls=":", lw=1.2, label=f"$t_{{0.8}}$ from the fit: {t08:.3g} s")
    elif t08:
        ax.plot([], [], ls="", label=f"$t_{{0.8}}$ from the fit: {t08:.3g} s (beyond the run)")
    ax.set_ylim(-0.05, 1.1)
    if t08 and t08 < 1.5 * t.max():
        ax.set_xlim(right=max(t.max(), t08) * 1.04)
    ax.set_xlabel("time $t$ (s)")
    ax.set_ylabel(f"Lacey index $M$ of {names[mixing_species]} (–)")
    ax.set_title("mixing of the lower and upper half", fontsize=9)
    # Legends below the panels: above them they hid the data.
    ax.legend(loc="upper left", bbox_to_anchor=(-0.1, -0.14), fontsize=8)

    ax = fig.add_subplot(grid[1])
    ax.plot(t, msd * 1e6, "o", ms=3, mfc="none", color="black", label="measured")
    d = dispersion.get("axial_coefficient")
    saturation = dispersion.get("saturation_msd")
    if d and saturation:
        tt = np.linspace(0, t.max(), 300)
        ax.plot(tt, confined_msd(tt, d, saturation) * 1e6, color=FIT_COLOUR,
                label=f"confined-bed fit, $D$ = {d:.3g} m$^2$/s")
    if saturation:
        ax.axhline(saturation * 1e6, color=style.REFERENCE_COLOUR, ls=":", lw=1,
                   label=f"saturation 2 Var($h$) = {saturation * 1e6:.3g} mm$^2$")
    ax.set_xlabel("time $t$ (s)")
    ax.set_ylabel("axial MSD about the mean (mm$^2$)")
    ax.set_title(f"vertical dispersion of {names[mixing_species]}", fontsize=9)
    ax.legend(loc="upper left", bbox_to_anchor=(-0.1, -0.14), fontsize=8)

    lower_ids = setup["id"][setup["tagged"] != 0]
    shown = [run.particles(index=0), run.particles(index=-1)]
    # One height for both views: the highest bead of the mixing species plus a margin.
    top = max(np.percentile(s["position"][s["species"] == mixing_species, vertical], 99.5)
              for s in shown) + 4 * max(s["radius"].max() for s in shown)
    views = []
    domain = run.domain
    for column, snapshot in zip((2, 3), shown):
        views.append(fig.add_subplot(grid[column]))
        _side_view(views[-1], domain, snapshot, lower_ids, mixing_species, vertical, top)
    lower_half, upper_half = tag_colours(mixing_species)
    handles = [Patch(facecolor=lower_half, edgecolor="black", lw=0.3,
                     label=f"{names[mixing_species]}, lower half at $t$ = 0"),
               Patch(facecolor=upper_half, edgecolor="black", lw=0.3,
                     label=f"{names[mixing_species]}, upper half at $t$ = 0")]
    present = set(np.unique(np.concatenate([s["species"] for s in shown])))
    handles += [Patch(facecolor=style.shade(style.species_colour(k), OTHER_SHADE),
                      edgecolor="black", lw=0.3, label=name)
                for k, name in enumerate(names) if k != mixing_species and k in present]
    views[0].legend(handles=handles, loc="upper left", bbox_to_anchor=(-0.1, -0.14), fontsize=8)
    fig.savefig(path, dpi=dpi, bbox_inches="tight")
    plt.close(fig)


def wide_range(values, ratio=20.0):
    """Whether the positive finite values span more than `ratio` (then a log axis reads best)."""
    values = np.asarray(values, dtype=float).ravel()
    positive = values[np.isfinite(values) & (values > 0)]
    return len(positive) > 0 and positive.max() > ratio * positive.min()


def plot_collisions(run, path, dpi):
    analysis = read_summary(run)
    species = run.species
    names = [s["name"] for s in species]
    measured = analysis.get("collision_frequency", {})
    kinetic = analysis.get("kinetic_theory_frequency", {})
    series = run.series_names
    t = run.series("time").values
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    ax = axes[0]
    # Row species s (bar colour) collides with the partner: another species or the walls.
    # One particle (and no inflow) has no partner of its own species.
    single = (np.array([s["count"] for s in species]) == 1) & ("particles_present" not in series)
    pairs = [(s, f"{a}-{b}", f"{a} with {b}") for s, a in enumerate(names)
             for u, b in enumerate(names) if not (s == u and single[s])]
    if run.walls:  # no wall bars without walls
        pairs += [(s, f"{a}@walls", f"{a} with walls") for s, a in enumerate(names)]
    value = lambda table, key: table.get(key) if table.get(key) is not None else np.nan  # noqa: E731
    x = np.arange(len(pairs))
    colours = [style.species_colour(s) for s, _, _ in pairs]
    ax.bar(x - 0.2, [value(measured, key) for _, key, _ in pairs], 0.4, color=colours,
           edgecolor="black", lw=0.4)
    ax.bar(x + 0.2, [value(kinetic, key) for _, key, _ in pairs], 0.4, color="white",
           edgecolor=colours, hatch="////", lw=0.8)
    if not any(value(measured, key) > 0 for _, key, _ in pairs):
        ax.text(0.5, 0.6, "no collisions in this run", ha="center", transform=ax.transAxes,
                color="0.3")
    ax.set_xticks(x)
    ax.set_xticklabels([label for _, _, label in pairs], rotation=30, ha="right")
    ax.set_ylabel("collision frequency per particle (1/s)")
    if wide_range([value(table, key) for table in (measured, kinetic) for _, key, _ in pairs]):
        ax.set_yscale("log")
    ax.legend(handles=[Patch(facecolor="0.6", edgecolor="black", lw=0.4,
                             label="measured at the events (whole run)"),
                       Patch(facecolor="white", edgecolor="0.3", hatch="////",
                             label="kinetic theory from the local fields"
                             + (" (none for walls)" if any("@" in key for _, key, _ in pairs)
                                else ""))],
              loc="lower left", bbox_to_anchor=(0.0, 1.0), fontsize=8)
    ax.set_title("collisions of one particle of a species with its partners", fontsize=9,
                 pad=34)

    ax = axes[1]
    temperature = run.series("granular_temperature").values.reshape(len(t), -1)
    for s, name in enumerate(names):
        ax.plot(t, temperature[:, s], color=style.species_colour(s), label=f"$\\theta$ {name}")
    if wide_range(temperature):
        ax.set_yscale("log")
        # A bed at rest at the start has a temperature near zero: not worth decades.
        top = np.nanmax(temperature)
        ax.set_ylim(bottom=max(np.nanmin(temperature[temperature > 0]), 1e-5 * top) / 1.5)
    elif not np.any(np.isfinite(temperature)):
        ax.text(0.5, 0.6, "no granular temperature (one particle)",
                ha="center", transform=ax.transAxes, color="0.3")
    elif not np.any(temperature > 0):
        ax.text(0.5, 0.6, "granular temperature zero: the particles do not move", ha="center",
                transform=ax.transAxes, color="0.3")
    if len(t) > 1:
        ax.set_xlim(t[0], t[-1])
    ax.set_xlabel("time $t$ (s)")
    ax.xaxis.set_major_locator(MaxNLocator(nbins=5))
    ax.set_ylabel("granular temperature $\\theta$ (m$^2$/s$^2$)")
    if "segregation_index" in series:
        twin = ax.twinx()
        twin.plot(t, run.series("segregation_index").values, color="0.3", ls="--",
                  label="segregation index")
        twin.set_ylabel("segregation index $2(h_s - h_l)/(h_s + h_l)$ (–)")
        twin.spines["right"].set_visible(True)
        lines = ax.get_legend_handles_labels()
        more = twin.get_legend_handles_labels()
        # Below the axes: inside, the noisy curves always run under it.
        ax.legend(lines[0] + more[0], lines[1] + more[1], loc="upper center",
                  bbox_to_anchor=(0.5, -0.14), ncol=3, fontsize=8)
    else:
        ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.14), ncol=3, fontsize=8)
    ax.set_title("granular temperature of each species", fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=dpi, bbox_inches="tight")
    plt.close(fig)


def plot_profiles(run, path, dpi):
    profiles = read_summary(run).get("profiles")
    if not profiles:
        return
    axes_names = "xyz"
    across, up = profiles["axis"], profiles["vertical"]
    a, v = axes_names.index(across), axes_names.index(up)
    third = 3 - a - v
    x = np.asarray(profiles["bin_centres"], dtype=float) * 1e3
    nan = lambda values: np.array([np.nan if u is None else u for u in values], dtype=float)  # noqa: E731
    fig, axes = plt.subplots(1, 4, figsize=(15, 3.8))
    # Sections by height along a sequential map: their colours are not species colours.
    colours = style.sequence_colours(len(profiles["sections"]))
    for k, section in enumerate(profiles["sections"]):
        colour = colours[k]
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
    axes[0].set_ylabel("solid fraction (–)")
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


def analysis_figures(run):
    """(name, draw(path, dpi)) for each analysis figure `run` (a carom.Output) supports."""
    figures = []
    series = run.series_names
    analysed = run.analysis_data() is not None
    if analysed and "lacey_index" in series and len(run.snapshots) > 0:
        figures.append(("mixing", lambda p, dpi: plot_mixing(run, p, dpi)))
    if "granular_temperature" in series:
        figures.append(("collisions", lambda p, dpi: plot_collisions(run, p, dpi)))
    if "profile_sums" in series:
        figures.append(("profiles", lambda p, dpi: plot_profiles(run, p, dpi)))
    if "axial_solid_fraction" in series and analysed and run.analysis_data("plugs") is not None:
        from plug_plots import plot_plugs
        figures.append(("plugs", lambda p, dpi: plot_plugs(run, read_summary(run), p, dpi)))
    return figures
