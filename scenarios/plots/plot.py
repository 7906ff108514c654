#!/usr/bin/python3
"""Figures of one carom run file.

    /usr/bin/python3 scenarios/plots/plot.py RUN.h5 [--out DIR] [--snapshot K] [--axes xy] [--slab W]

Writes, as 150 dpi PNGs named after the run file:
  RUN_energies.png         kinetic (translational, rotational), potential, elastic, dissipated,
                           the gas's work and the total
                           energy against time (/timeseries);
  RUN_collision_rates.png  collision frequency per particle (how often one particle of species s
                           collides with particles of t, 1/s) for every species pair, measured
                           over each sample interval, beside kinetic theory: Enskog from the
                           global density and temperature when the run is a homogeneous gas
                           (every axis periodic, no gravity, no walls), else the analysis'
                           kinetic_collision_rate from the local fields (runs with
                           [analysis]); without either the figure says so;
  RUN_snapshot.png         one snapshot (the last by default) as circles of the particles' radii
                           in a slab around the box's mid-plane, coloured by species;
  RUN_gas.png              runs with a gas: the bed pressure drop against time and against the
                           inlet velocity, with the buoyant weight per area W/A of the particles
                           (the level a fluidized bed's pressure drop must reach) and the
                           predicted U_mf; the measured U_mf only where the inlet ramp resolves
                           it (at least 2 bed relaxation times tau_b = U_mf / (eps_mf g) and 20
                           samples from rest to the predicted U_mf), else a note says why not;
  RUN_gas_field.png        runs with a gas: porosity and gas velocity of the snapshot;
  RUN_flow.png             runs with inflow or outflow: mass in and out against the set rates,
                           particles present (flow_plots.py);
  RUN_mixing.png, RUN_collisions.png   the run's analysis (analysis_plots.py);
  RUN_bed.png, RUN_bed_spectrum.png, RUN_bed_map.png   runs with [analysis.bed]: bed heights and
                           pressures against time, the probes' spectra, the mid-plane maps
                           (bed_plots.py).
Every figure colours a species alike (style.py: by its index in /species).

Needs numpy, h5py and matplotlib (Debian: python3-numpy python3-h5py python3-matplotlib); the run
file is read through carom.open (carom_reader.py), without the compiled module.
Enskog frequency of s-t collisions of one s particle in a mixture at granular temperature T
(k = 1):
    omega_st = 4 n_t sigma_st^2 g_st sqrt(pi T / (2 mu_st)),  mu_st = m_s m_t / (m_s + m_t),
with g_st the Boublik-Mansoori-Carnahan-Starling-Leland contact value; for one species this is
omega = 4 n sigma^2 g0 sqrt(pi T / m) with the Carnahan-Starling g0 = (1 - phi/2) / (1 - phi)^3.
T = 2 K / (3 (N - 1)) from the translational kinetic energy K (total momentum is zero).
"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import EllipseCollection  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402
from matplotlib.ticker import MaxNLocator  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from analysis_plots import analysis_figures  # noqa: E402
from bed_plots import bed_figures  # noqa: E402
from carom_reader import OutputError, open_run  # noqa: E402
from flow_plots import plot_flow  # noqa: E402
from wall_outlines import WALL_STYLE, draw_walls  # noqa: E402
import style  # noqa: E402

DPI = style.DPI
style.apply()
# Energies are not species: their own palette, so that no curve looks like a species.
ENERGY_COLOURS = plt.get_cmap("Dark2").colors


def species_values(run, key):
    """One column of the run's species table (carom.Output.species) as an array: name,
    diameter (m), density (kg/m^3), mass (kg) or count (at the start)."""
    return np.array([species[key] for species in run.species])


def contact_values(diameter, number_density):
    """BMCSL contact values g_st of a hard-sphere mixture, and the volume fraction."""
    xi2 = np.pi / 6 * np.sum(number_density * diameter**2)
    phi = np.pi / 6 * np.sum(number_density * diameter**3)
    ratio = np.outer(diameter, diameter) / np.add.outer(diameter, diameter)
    g = 1 / (1 - phi) + 3 * xi2 * ratio / (1 - phi)**2 + 2 * xi2**2 * ratio**2 / (1 - phi)**3
    return g, phi


def is_homogeneous_gas(run):
    domain = run.domain
    return (bool(np.all(domain["periodic"])) and not np.any(domain["gravity"])
            and len(run.walls) == 0)


def enskog_frequencies(run, temperature, species_temperature=None):
    """Enskog collision frequencies per particle (1/s) at each sample, array (samples, S, S):
    [s, t] is how often one s particle collides with t particles. `temperature` is the common
    granular temperature T (J) of each sample; `species_temperature` (samples, S), each
    species' own theta_s = T_s / m_s (m^2/s^2, the analysis' granular_temperature), replaces it
    where given: omega_st = 4 n_t sigma_st^2 g_st sqrt(pi (theta_s + theta_t) / 2), which is
    sqrt(pi T / (2 mu_st)) at a common T."""
    diameter = species_values(run, "diameter")
    mass = species_values(run, "mass")
    count = species_values(run, "count").astype(float)
    volume = run.domain["volume"]
    density = count / volume
    g, _ = contact_values(diameter, density)
    sigma = 0.5 * np.add.outer(diameter, diameter)
    prefactor = 4 * density[None, :] * sigma**2 * g
    if species_temperature is None:
        theta = np.maximum(temperature, 0)[:, None] / mass[None, :]
    else:
        theta = np.maximum(species_temperature, 0)
    return prefactor[None, :, :] * np.sqrt(np.pi / 2 * (theta[:, :, None] + theta[:, None, :]))


def energy_unit(largest):
    """(factor, unit) that writes energies up to `largest` J with numbers between 0.1 and 1000."""
    for factor, unit in ((1.0, "J"), (1e3, "mJ"), (1e6, "µJ"), (1e9, "nJ"), (1e12, "pJ")):
        if largest * factor >= 0.1:
            return factor, unit
    return 1e15, "fJ"


def plot_energies(run, path):
    series = run.series_names
    t = run.series("time").values
    fig, ax = plt.subplots(figsize=(8.4, 4.0))
    unit = "J"
    if len(t) == 0:
        ax.text(0.5, 0.5, "no samples", ha="center", transform=ax.transAxes)
    else:
        curves = [("kinetic_translational", "kinetic, translational", "-"),
                  ("kinetic_rotational", "kinetic, rotational", "-"),
                  ("potential", "potential", "-"),
                  ("elastic", "elastic (soft-sphere contacts)", "-"),
                  ("dissipated", "dissipated", "--"),
                  ("gas_work", "work done by the gas", "-."),
                  ("total_energy", "total (kinetic + potential\n+ elastic + dissipated\n- gas work)",
                   ":")]
        scale = np.max(np.abs(run.series("total_energy").values)) or 1.0
        shown = []
        for k, (name, label, line_style) in enumerate(curves):
            if name not in series:
                continue  # run files written before the column existed
            values = run.series(name).values
            if name in ("kinetic_rotational", "potential", "elastic", "gas_work") and \
                    np.max(np.abs(values)) < 1e-12 * scale:
                continue  # zero up to round-off (smooth spheres, no gravity): only clutter
            shown.append((k, label, line_style, values, name))
        factor, unit = energy_unit(max(np.max(np.abs(v)) for _, _, _, v, _ in shown) or 1.0)
        for k, label, line_style, values, name in shown:
            ax.plot(t, values * factor, line_style, color=ENERGY_COLOURS[k % len(ENERGY_COLOURS)],
                    lw=1.6 if name == "total_energy" else 1.2, label=label)
        # Beside the axes: inside, the curves of some run always run under it.
        ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0))
    ax.set_xlabel("time $t$ (s)")
    ax.set_ylabel(f"energy ({unit})")
    ax.set_title("Energies")
    fig.tight_layout()
    fig.savefig(path, dpi=DPI)
    plt.close(fig)


def species_counts(run, samples):
    """Particles of each species at each sample, array (samples, S): particles_present where the
    run has inflow or outflow, else the fixed counts of /species."""
    if "particles_present" in run.series_names:
        return run.series("particles_present").values.reshape(samples, -1).astype(float)
    return np.tile(species_values(run, "count").astype(float), (samples, 1))


def plot_collision_rates(run, path):
    """Collision frequency per particle, [s, t]: collisions of one s particle with t particles per
    second, measured over each sample interval from /timeseries/pair_collisions, beside kinetic
    theory: Enskog from the global density and temperature for a homogeneous gas, else the
    analysis' kinetic_collision_rate from the local fields (runs with [analysis]). With an impact
    speed (summary.json impact_speed > 0) a second panel: the impacts, the collisions faster than
    it (/timeseries/pair_impacts), beside kinetic theory's (kinetic_impact_rate)."""
    series = run.series_names
    t = run.series("time").values
    summary = run.summary or {}
    impacts = "pair_impacts" in series and (summary.get("impact_speed") or 0) > 0
    fig, axes = plt.subplots(2 if impacts else 1, 1, figsize=(8.8, 7.6 if impacts else 4.2),
                             sharex=True, squeeze=False)
    panels = [(axes[0, 0], "pair_collisions", "kinetic_collision_rate")]
    if impacts:
        panels.append((axes[1, 0], "pair_impacts", "kinetic_impact_rate"))
    for ax, counts_name, theory_name in panels:
        if len(t) < 2:
            ax.text(0.5, 0.5, "fewer than two samples", ha="center", transform=ax.transAxes)
        else:
            _rate_panel(run, ax, t, series, counts_name, theory_name)
        if len(t) > 1:
            ax.set_xlim(t[0], t[-1])
        ax.xaxis.set_major_locator(MaxNLocator(nbins=6))
    ax = axes[0, 0]
    ax.set_ylabel("collision frequency per particle (1/s)")
    ax.set_title("Collisions of one particle of a species with the partner species", fontsize=10)
    if impacts:
        ax = axes[1, 0]
        ax.set_ylabel("impact frequency per particle (1/s)")
        ax.set_title(f"Impacts: collisions with a normal approach speed above "
                     f"v* = {summary['impact_speed'] * 1e3:.3g} mm/s", fontsize=10)
    axes[-1, 0].set_xlabel("time $t$ (s)")
    fig.tight_layout()
    fig.savefig(path, dpi=DPI)
    plt.close(fig)


def _rate_panel(run, ax, t, series, counts_name, theory_name):
    """One panel of plot_collision_rates: the per-particle rates of `counts_name` over each
    sample interval (markers) beside kinetic theory (lines): Enskog for a homogeneous gas's
    collisions, else the analysis series `theory_name`."""
    names = run.species_names
    s_count = len(names)
    counts = run.series(counts_name).values.astype(float)  # (samples, S, S)
    dt = np.diff(t)
    keep = dt > 0
    middle = 0.5 * (t[1:] + t[:-1])[keep]
    present = species_counts(run, len(t))
    present = 0.5 * (present[1:] + present[:-1])[keep]  # mean over each interval
    collisions = np.diff(counts, axis=0)[keep]
    # A collision of two s particles is one for each of them.
    collisions[:, np.arange(s_count), np.arange(s_count)] *= 2
    with np.errstate(divide="ignore", invalid="ignore"):
        measured = collisions / (dt[keep, None, None] * present[:, :, None])
    measured[~np.isfinite(measured)] = np.nan
    theory, theory_t, theory_label = None, None, None
    if counts_name == "pair_collisions" and is_homogeneous_gas(run):
        kinetic = run.series("kinetic_translational").values
        n = float(np.sum(species_values(run, "count")))
        temperature = 2 * kinetic / (3 * max(n - 1, 1))
        if "granular_temperature" in series and s_count > 1:
            # A mixture: each species at its own temperature (the analysis'), else a species
            # that carries the kinetic energy (a sphere moving through a cloud) would heat
            # the others. One species keeps the global T: the local temperatures leave out
            # each cell's mean velocity and would lower T by a few per cent.
            theta = run.series("granular_temperature").values.reshape(len(t), s_count)
            theory = enskog_frequencies(run, None, theta)
            theory_t = t
            theory_label = "lines: Enskog (global density, each species' temperature)"
        else:
            # Mean temperature over each interval (exact for a linear change).
            theory = enskog_frequencies(run, 0.5 * (temperature[1:] + temperature[:-1])[keep])
            theory_t = middle
            theory_label = "lines: Enskog (global density and temperature)"
    elif theory_name in series:
        theory = run.series(theory_name).values.reshape(len(t), s_count, s_count)
        theory_t = t
        theory_label = "lines: kinetic theory from the local fields ([analysis])"
    handles = []
    single = species_values(run, "count") == 1
    for s in range(s_count):
        for u in range(s_count):
            if s == u and single[s] and "particles_present" not in series:
                continue  # one particle of a species: it has no partner of its own kind
            colour = style.species_colour(s)
            label = f"{names[s]} with {names[u]}"
            ax.plot(middle, measured[:, s, u], style.partner_marker(u), ms=2.5, color=colour,
                    alpha=0.45, ls="", zorder=2)
            if theory is not None:  # over the markers, with a white edge to stand out
                ax.plot(theory_t, theory[:, s, u], ls=style.partner_line(u), lw=2.6,
                        color="white", zorder=3)
                ax.plot(theory_t, theory[:, s, u], ls=style.partner_line(u), lw=1.5,
                        color=style.shade(colour, -0.3), zorder=4)
            handles.append(Line2D([], [], color=colour, marker=style.partner_marker(u), ms=4,
                                  ls=style.partner_line(u) if theory is not None else "",
                                  label=label))
    handles.append(Line2D([], [], ls="", label="markers: measured over each sample interval"))
    if theory is not None:
        handles.append(Line2D([], [], ls="", label=theory_label))
    positive = measured[np.isfinite(measured) & (measured > 0)]
    if len(positive) == 0:
        ax.text(0.5, 0.6, "no collisions in this run", ha="center", transform=ax.transAxes,
                color="0.3")
    if theory is not None:
        theory_positive = theory[np.isfinite(theory) & (theory > 0)]
        positive = np.concatenate([positive, theory_positive])
    if len(positive) and positive.max() > 10 * np.percentile(positive, 5):
        ax.set_yscale("log")
        # A bed at rest at the start has a kinetic-theory rate near zero: not worth decades.
        ax.set_ylim(bottom=max(positive.min(), 1e-4 * positive.max()) / 1.5)
    else:
        ax.set_ylim(bottom=0)
    ax.legend(handles=handles, loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=8,
              handlelength=2.5)
    if theory is None:
        ax.text(0.02, 0.98, "no kinetic-theory line: not a homogeneous gas (Enskog needs\n"
                "periodic axes, no gravity, no walls) and no [analysis] (local fields)",
                transform=ax.transAxes, va="top", fontsize=7, color="0.3")


def plot_snapshot(run, path, index, axes, slab):
    snapshots = run.snapshots
    domain = run.domain
    lower, upper = domain["lower"], domain["upper"]
    a, b = ("xyz".index(axes[0]), "xyz".index(axes[1]))
    aspect = (upper[b] - lower[b]) / (upper[a] - lower[a])
    # A column much taller than wide (or a slab much wider than tall) is drawn stretched: to
    # scale it would be a line.
    stretch = style.stretched(upper[a] - lower[a], upper[b] - lower[b])
    height = 5.2 if aspect >= 1 else max(2.5, 4.0 * aspect + 1.2)
    width = min(max(4.0 / max(aspect, 1) + 1.8, 3.5), 9.0) if aspect >= 1 else 6.4
    if stretch:
        height, width = (5.2, 4.0) if aspect > 1 else (3.0, 7.0)
    fig, ax = plt.subplots(figsize=(width, height))
    if not len(snapshots):
        ax.text(0.5, 0.5, "no snapshots", ha="center", transform=ax.transAxes)
        fig.savefig(path, dpi=DPI)
        plt.close(fig)
        return
    snapshot = run.particles(index=index)
    position = snapshot["position"]
    radius = snapshot["radius"]
    species = snapshot["species"]
    names = run.species_names
    depth_axis = 3 - a - b
    middle = 0.5 * (lower[depth_axis] + upper[depth_axis])
    if slab is None:
        slab = 4 * radius.max() if len(radius) else 0.0
    chosen = (np.abs(position[:, depth_axis] - middle) <= 0.5 * slab) if slab > 0 else \
        np.ones(len(radius), bool)
    # Nearer particles drawn last; a rare species (under 1 % of the particles: a tracer, a
    # large sphere in a cloud) over all others, so that the slab's front does not hide it.
    counts = np.bincount(species, minlength=len(names))
    rare = counts[species[chosen]] < 0.01 * len(species)
    order = np.lexsort((position[chosen, depth_axis], rare))
    p, r, s = position[chosen][order], radius[chosen][order], species[chosen][order]
    colours = [style.species_colour(k) for k in s]
    # Edges only where the circles are large enough in the picture to keep their colour.
    extent = max(upper[a] - lower[a], upper[b] - lower[b])
    edge = 0.3 if len(r) and 2 * np.max(r) > extent / 120 else 0.0
    # Particles under about a pixel at this size (a duct a metre tall) are drawn as markers.
    tiny = len(r) > 0 and 2 * np.median(r) < extent / 250
    if stretch or tiny:  # circles would be lines or dots: markers at the centres
        ax.scatter(p[:, a], p[:, b], s=25 if stretch else 6, c=colours, edgecolors="black",
                   linewidths=0.3 if stretch else 0.0, zorder=3)
    else:
        ax.add_collection(EllipseCollection(2 * r, 2 * r, np.zeros_like(r), units="xy",
                                            offsets=p[:, [a, b]], transOffset=ax.transData,
                                            facecolors=colours, edgecolors="black",
                                            linewidths=edge))
    ax.add_patch(plt.Rectangle((lower[a], lower[b]), upper[a] - lower[a], upper[b] - lower[b],
                               fill=False, lw=0.8, color="0.3"))
    margin = 0.03 * max(upper[a] - lower[a], upper[b] - lower[b])
    if stretch:
        ax.set_xlim(lower[a] - 0.03 * (upper[a] - lower[a]), upper[a] + 0.03 * (upper[a] - lower[a]))
        ax.set_ylim(lower[b] - 0.03 * (upper[b] - lower[b]), upper[b] + 0.03 * (upper[b] - lower[b]))
    else:
        ax.set_xlim(lower[a] - margin, upper[a] + margin)
        ax.set_ylim(lower[b] - margin, upper[b] + margin)
        ax.set_aspect("equal")
    style.length_axes(ax, upper[a] - lower[a], upper[b] - lower[b], axes)
    handles = [Line2D([], [], marker="o", ls="", ms=8, markerfacecolor=style.species_colour(k),
                      markeredgecolor="black", label=name) for k, name in enumerate(names)]
    handles.append(Line2D([], [], color="0.3", lw=0.8, label="domain"))
    before = len(ax.lines)
    skipped = draw_walls(ax, run, a, b, depth_axis, middle)
    box = plt.Rectangle((lower[a], lower[b]), upper[a] - lower[a], upper[b] - lower[b],
                        transform=ax.transData, fill=False, visible=False)
    ax.add_patch(box)
    for line in ax.lines[before:]:
        line.set_clip_path(box)  # a cone's wall beyond the domain is no wall
    if len(ax.lines) > before:
        handles.append(Line2D([], [], **WALL_STYLE, label="walls (mid-plane)"))
    if skipped:
        handles.append(Line2D([], [], ls="", label="not drawn:\n" + ", ".join(skipped)))
    ax.legend(handles=handles, loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=8)
    # The slab in the unit of the picture's axes.
    factor, unit = (1e3, "mm") if max(upper - lower) < 0.5 else (1.0, "m")
    what = (f"slab $|{'xyz'[depth_axis]} - {middle * factor:.3g}| \\leq {0.5 * slab * factor:.3g}$"
            f" {unit}" if slab > 0 else "all particles")
    if stretch:
        what += ";\nnot to scale: particles as markers"
    elif tiny:
        what += ";\nparticles drawn larger than to scale"
    ax.set_title(f"$t$ = {snapshot['time']:.4g} s: {len(r)} of {len(radius)} particles\n"
                 f"({what})", fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=DPI, bbox_inches="tight")
    plt.close(fig)


def buoyant_weight_per_area(run, counts=None):
    """W/A = sum m_i |g| (1 - rho_g/rho_p) / (area normal to gravity), Pa, of the particles
    of /species (or of `counts`, array (samples, S): then one value per sample)."""
    domain = run.domain
    lower, upper = domain["lower"], domain["upper"]
    gravity = np.asarray(domain["gravity"])
    down = int(np.argmax(np.abs(gravity)))
    area = np.prod([upper[k] - lower[k] for k in range(3) if k != down])
    rho_g = run.gas_grid["density"]
    per_particle = (species_values(run, "mass") * np.linalg.norm(gravity)
                    * (1 - rho_g / species_values(run, "density")))
    counts = species_values(run, "count") if counts is None else counts
    return np.asarray(counts, dtype=float) @ per_particle / area


def measured_minimum_fluidization(inlet, drop, weight):
    """U_mf of a ramp: where the packed-bed branch (Ergun's form a U + b U^2, least squares over
    the points below 70 % of W/A) reaches the plateau W/A. None without such points."""
    packed = (inlet > 0) & (drop < 0.7 * weight)
    if packed.sum() < 5 or drop.max() < 0.9 * weight:
        return None
    u, p = inlet[packed], drop[packed]
    (a, b), *_ = np.linalg.lstsq(np.column_stack([u, u * u]), p, rcond=None)
    if b <= 0:
        return weight / a if a > 0 else None
    return (-a + np.sqrt(a * a + 4 * b * weight)) / (2 * b)


def carrying_pressure_drop(run):
    """The part of the gas pressure drop that carries the particles, Pa: gas_pressure_drop less
    the gas's own weight per area (rho_g |g| H) plus the net momentum per area the gas brings in
    (gas_momentum_inflow; absent from files of older carom versions)."""
    domain = run.domain
    lower, upper = domain["lower"], domain["upper"]
    gravity = np.asarray(domain["gravity"])
    height = upper[2] - lower[2]
    gas_column = run.gas_grid["density"] * abs(gravity[2]) * height
    drop = run.series("gas_pressure_drop").values - gas_column
    if "gas_momentum_inflow" in run.series_names:
        drop = drop + run.series("gas_momentum_inflow").values
    return drop


# A ramp resolves U_mf when it takes at least RAMP_RELAXATION_TIMES bed relaxation times and
# RAMP_SAMPLES samples to go from rest to the predicted U_mf (see ramp_resolves_minimum_fluidization).
RAMP_RELAXATION_TIMES = 2.0
RAMP_SAMPLES = 20
# Colours of the gas figure: none is a species' colour.
GAS_DROP_COLOUR, GAS_INLET_COLOUR = "black", "#1b9e77"
PREDICTION_COLOURS = ("#7570b3", "#d95f02")


def ramp_resolves_minimum_fluidization(run, t, inlet):
    """(slow, why): whether the inlet ramp is slow enough to measure U_mf, and a sentence that
    says why (or why not).

    The bed relaxes towards its new state on tau_b = U_mf / (eps_mf g): the time in which gravity
    alone changes a bead's velocity by the interstitial gas velocity at minimum fluidization
    (near U_mf drag and weight balance, so this is the beads' drag relaxation time there). The
    ramp resolves U_mf when it takes at least RAMP_RELAXATION_TIMES tau_b from its start to the
    predicted U_mf (the closure's, for a uniform bed at eps_mf = 0.4), so that the bed follows
    the gas instead of lagging it, and at least RAMP_SAMPLES samples, so that the packed branch
    has points enough for the fit."""
    gas = run.gas_grid
    if "closure_minimum_fluidization" not in gas:
        return False, "no predicted $U_{mf}$ in the run file (no gravity?)"
    predicted = float(gas["closure_minimum_fluidization"])
    eps_mf = 0.4
    g = float(np.linalg.norm(run.domain["gravity"]))
    reach = np.flatnonzero(inlet >= predicted)
    if len(reach) == 0:
        return False, f"the inlet never reaches the predicted $U_{{mf}}$ = {predicted:.3g} m/s"
    reach = reach[0]
    moving = np.flatnonzero(inlet > 0)
    start = max(moving[0] - 1, 0) if len(moving) else 0
    duration, samples = t[reach] - t[start], reach - start
    tau = predicted / (eps_mf * g)
    why = (f"the inlet reaches the predicted $U_{{mf}}$ = {predicted:.3g} m/s in {duration:.3g} s = "
           f"{duration / tau:.2g} bed relaxation times $\\tau_b = U_{{mf}}/(\\varepsilon_{{mf}} g)$"
           f" = {tau:.3g} s, over {samples} samples")
    slow = duration >= RAMP_RELAXATION_TIMES * tau and samples >= RAMP_SAMPLES
    if not slow:
        why = (f"the ramp is too fast to resolve it: {why}; it needs $\\geq$ "
               f"{RAMP_RELAXATION_TIMES:g} $\\tau_b$ and {RAMP_SAMPLES} samples")
    return slow, why


def plot_gas(run, path):
    series = run.series_names
    t = run.series("time").values
    drop = carrying_pressure_drop(run)
    inlet = run.series("gas_inlet_velocity").values.max(axis=1)
    fig, (left, right) = plt.subplots(1, 2, figsize=(10.4, 4.0))
    left.plot(t, drop, color=GAS_DROP_COLOUR, lw=1.0, label="pressure drop carrying the particles")
    if "particles_present" in series:  # inflow, outflow: the weight of those present
        weights = buoyant_weight_per_area(run, species_counts(run, len(t)))
        weight = weights[-1] if len(weights) else 0.0
        left.plot(t, weights, color=style.REFERENCE_COLOUR, ls="--", lw=0.8,
                  label="buoyant weight per area W/A of the particles present")
    else:
        weight = buoyant_weight_per_area(run)
        left.axhline(weight, color=style.REFERENCE_COLOUR, ls="--", lw=0.8,
                     label=f"buoyant weight per area W/A = {weight:.4g} Pa")
    left.set_xlabel("time $t$ (s)")
    left.set_ylabel(r"pressure drop $\Delta p$ (Pa)")
    twin = left.twinx()
    twin.plot(t, inlet, color=GAS_INLET_COLOUR, lw=1.0, label="inlet superficial velocity $U$")
    twin.set_ylabel("inlet superficial velocity $U$ (m/s)", color=GAS_INLET_COLOUR)
    twin.tick_params(axis="y", colors=GAS_INLET_COLOUR)
    twin.set_ylim(bottom=0)
    twin.spines["right"].set_visible(True)
    # The legends sit below the axes: inside, wherever they go, some run's curve runs under them.
    lines = left.get_legend_handles_labels()
    twin_lines = twin.get_legend_handles_labels()
    left.legend(lines[0] + twin_lines[0], lines[1] + twin_lines[1], loc="upper center",
                bbox_to_anchor=(0.5, -0.2), ncol=1, fontsize=8, frameon=False)
    if not np.any(inlet > 0):  # still gas: nothing to plot against the inlet velocity
        right.axis("off")
        right.text(0.5, 0.5, "no inlet flow: no pressure drop against the inlet velocity,\n"
                   "no minimum fluidization velocity", ha="center", va="center",
                   transform=right.transAxes, fontsize=9, color="0.3")
        fig.tight_layout()
        fig.savefig(path, dpi=DPI, bbox_inches="tight")
        plt.close(fig)
        return
    right.plot(inlet, drop, ".", ms=2, color=GAS_DROP_COLOUR, label="carom, every sample")
    right.axhline(weight, color=style.REFERENCE_COLOUR, ls="--", lw=0.8, label="W/A")
    slow, why = ramp_resolves_minimum_fluidization(run, t, inlet)
    measured = measured_minimum_fluidization(inlet, drop, weight) if slow else None
    if measured is not None:
        right.axvline(measured, color=GAS_DROP_COLOUR, lw=0.8,
                      label=f"measured $U_{{mf}}$ = {measured:.3f} m/s (packed branch meets W/A)")
    attrs = run.gas_grid
    if "closure_minimum_fluidization" in attrs:
        right.axvline(attrs["closure_minimum_fluidization"], color=PREDICTION_COLOURS[0], ls=":",
                      lw=1.0, label=f"predicted $U_{{mf}}$, closure at $\\varepsilon_{{mf}}$ = 0.4: "
                                    f"{attrs['closure_minimum_fluidization']:.3f} m/s")
        right.axvline(attrs["wen_yu_minimum_fluidization"], color=PREDICTION_COLOURS[1], ls="-.",
                      lw=1.0, label=f"predicted $U_{{mf}}$, Wen-Yu correlation: "
                                    f"{attrs['wen_yu_minimum_fluidization']:.3f} m/s")
    if slow and measured is None:
        note = f"$U_{{mf}}$ not measured: no packed branch below 0.7 W/A to fit ({why})"
    elif not slow:
        note = f"$U_{{mf}}$ not measured: {why}"
    else:
        note = f"ramp slow enough: {why}"
    right.legend(loc="upper center", bbox_to_anchor=(0.5, -0.2), ncol=1, fontsize=8,
                 frameon=False)
    right.set_xlabel("inlet superficial velocity $U$ (m/s)")
    right.set_ylabel(r"pressure drop $\Delta p$ (Pa)")
    right.set_title(f"drag closure: {attrs['closure']}", fontsize=9)
    fig.tight_layout()
    fig.text(0.5, -0.02, style.wrap(note, 150), ha="center", va="top",
             fontsize=8, color="0.25", transform=fig.transFigure)
    fig.savefig(path, dpi=DPI, bbox_inches="tight")
    plt.close(fig)


def plot_gas_field(run, path, index):
    grid = run.gas_grid
    cells, lower, spacing = grid["cells"], grid["lower"], grid["spacing"]
    snapshot = run.gas(index=index)
    porosity = snapshot["porosity"]        # (nz, ny, nx)
    velocity = snapshot["velocity"]        # (nz, ny, nx, 3)
    mid = cells[1] // 2
    extent = [lower[0], lower[0] + cells[0] * spacing[0], lower[2], lower[2] + cells[2] * spacing[2]]
    stretch = style.stretched(extent[1] - extent[0], extent[3] - extent[2])
    aspect = "auto" if stretch else "equal"
    fig, (left, right) = plt.subplots(1, 2, figsize=(7.2, 5.0))
    # Porosity from 0.3 (or its least, down to 0.8 at most: an almost empty gas keeps a scale).
    image = left.imshow(porosity[:, mid, :], origin="lower", extent=extent, cmap="viridis",
                        vmin=min(max(0.3, porosity.min()), 0.8), vmax=1.0, aspect=aspect)
    fig.colorbar(image, ax=left, label="porosity (–)")
    speed = velocity[:, mid, :, 2]
    low, high = float(np.min(speed)), float(np.max(speed))
    if high - low < 1e-6 * max(1.0, abs(high)):  # a uniform field: a scale around its value
        low, high = low - 0.05, high + 0.05
    image = right.imshow(speed, origin="lower", extent=extent, cmap="magma", aspect=aspect,
                         vmin=low, vmax=high)
    bar = fig.colorbar(image, ax=right, label="gas velocity $u_z$ (m/s)")
    bar.formatter.set_useOffset(False)
    for ax in (left, right):
        style.length_axes(ax, extent[1] - extent[0], extent[3] - extent[2], "xz")
    y_mid = lower[1] + (mid + 0.5) * spacing[1]
    fig.suptitle(f"gas cells at $t$ = {snapshot['time']:.4g} s, slice $y$ = {y_mid:.3g} m"
                 + ("\n(not to scale)" if stretch else ""), fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=DPI)
    plt.close(fig)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("run", help="the run's HDF5 file")
    parser.add_argument("--out", help="directory for the PNGs (default: beside the run file)")
    parser.add_argument("--snapshot", type=int, default=-1, help="snapshot index (default: last)")
    parser.add_argument("--axes", default=None, choices=["xy", "xz", "yz", "yx", "zx", "zy"],
                        help="projection plane of the snapshot picture (default: a side view "
                             "with gravity pointing down, or xy without gravity)")
    parser.add_argument("--slab", type=float, default=None,
                        help="thickness (m) of the slab drawn around the mid-plane; 0 draws all "
                             "particles (default: 2 largest diameters)")
    args = parser.parse_args(argv)

    out = args.out or os.path.dirname(os.path.abspath(args.run))
    os.makedirs(out, exist_ok=True)
    stem = os.path.splitext(os.path.basename(args.run))[0]
    try:
        # A checkpoint or another file is refused with a message saying what it is.
        run = open_run(args.run)
    except OutputError as error:
        sys.exit(str(error))
    if args.axes is None:
        gravity = np.asarray(run.domain["gravity"])
        if np.any(gravity != 0):
            down = int(np.argmax(np.abs(gravity)))  # vertical axis of the picture
            across = 0 if down != 0 else 1
            args.axes = "xyz"[across] + "xyz"[down]
        else:
            args.axes = "xy"
    written = []
    figures = [("energies", lambda p: plot_energies(run, p)),
               ("collision_rates", lambda p: plot_collision_rates(run, p)),
               ("snapshot", lambda p: plot_snapshot(run, p, args.snapshot, args.axes, args.slab))]
    if "particles_present" in run.series_names:
        figures.append(("flow", lambda p: plot_flow(run, p, DPI)))
    if run.gas_grid is not None:
        figures += [("gas", lambda p: plot_gas(run, p)),
                    ("gas_field", lambda p: plot_gas_field(run, p, args.snapshot))]
    figures += [(name, lambda p, draw=draw: draw(p, DPI)) for name, draw in analysis_figures(run)]
    figures += [(name, lambda p, draw=draw: draw(p, DPI)) for name, draw in bed_figures(run)]
    for name, draw in figures:
        path = os.path.join(out, f"{stem}_{name}.png")
        try:
            draw(path)
        except OutputError as error:  # a --snapshot the file does not hold
            sys.exit(str(error))
        written.append(path)
    print("\n".join(written))


if __name__ == "__main__":
    main()
