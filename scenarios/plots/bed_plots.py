"""The figures of a run's bed measures (scenes with [analysis.bed]; bed_measures.hpp), used by
plot.py.

RUN_bed.png           the bed heights against time (/timeseries/bed_height: the share heights,
                      the solid-fraction surface), and with a gas the pressures: each probe's
                      gas pressure (/timeseries/bed_probe_pressure) and the part of the pressure
                      drop that carries the bed (drop - rho_g g H + momentum inflow) beside the
                      buoyant weight per area W/A; the averaging start shaded out;
RUN_bed_spectrum.png  with probes: each probe's amplitude spectrum after the start
                      (/analysis/bed/results), its dominant frequency marked, the resolution and
                      the Nyquist frequency in the title;
RUN_bed_map.png       the time-averaged mid-plane maps: solid fraction with the solids velocity
                      as arrows (the circulation), and the vertical solids mass flux.

`run` is a carom.Output (carom_reader.py): /analysis/bed and its results come from
run.analysis_data("bed"), the series from run.series.
"""
import numpy as np

AXES = "xyz"


def _text(value):
    return value.decode() if isinstance(value, bytes) else str(value)


def bed_figures(run):
    """(name, draw(path, dpi)) for each bed figure this run file supports."""
    bed = run.analysis_data("bed")
    if bed is None or "bed_height" not in run.series_names:
        return []
    figures = [("bed", lambda p, dpi: plot_bed(run, bed, p, dpi))]
    results = bed.get("results")
    if results is not None and int(results.get("samples", 0)) == 0:
        results = None  # the run ended before the averaging start: nothing averaged to draw
    if results is not None and "spectrum_amplitude" in results:
        figures.append(("bed_spectrum", lambda p, dpi: plot_bed_spectrum(bed, p, dpi)))
    if results is not None and "map_solid_fraction" in results:
        figures.append(("bed_map", lambda p, dpi: plot_bed_map(run, bed, p, dpi)))
    return figures


def _probe_labels(bed):
    labels = []
    if "probes" in bed:
        for point in np.atleast_2d(bed["probes"]):
            if point.size == 3:
                labels.append("point (" + ", ".join(f"{1e3 * x:.3g}" for x in point) + ") mm")
    if "probe_heights" in bed:
        labels += [f"cross-section at {1e3 * h:.3g} mm" for h in np.atleast_1d(bed["probe_heights"])]
    return labels


def _shade_start(ax, t, start):
    if start > t[0]:
        ax.axvspan(t[0], start, color="0.92", lw=0, zorder=0)


def plot_bed(run, bed, path, dpi):
    import matplotlib.pyplot as plt

    import style

    names = run.series_names
    height_series = run.series("bed_height")
    t = height_series.time
    heights = np.atleast_2d(height_series.values)
    shares = np.atleast_1d(bed["height_shares"])
    start = float(bed["start"])
    threshold = float(bed["threshold"])
    up = AXES[int(bed["vertical_axis"])]
    gas = "bed_pressure" in names
    fig, axes = plt.subplots(2 if gas else 1, 1, figsize=(9.5, 6.4 if gas else 3.6), sharex=True,
                             squeeze=False)
    ax = axes[0, 0]
    colours = style.sequence_colours(len(shares) + 1, "viridis", end=0.8)
    for k, q in enumerate(shares):
        ax.plot(t, 1e3 * heights[:, k], color=colours[k], lw=1.2,
                label=f"{100 * q:.3g} % of the bead tops below")
    ax.plot(t, 1e3 * heights[:, -1], color=colours[-1], lw=1.2, ls="--",
            label=f"solid fraction falls below {threshold:.3g}")
    _shade_start(ax, t, start)
    ax.set_ylabel(f"bed height above the floor, ${up}$ (mm)")
    ax.set_ylim(bottom=0)
    ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=8)
    if gas:
        ax = axes[1, 0]
        pressure = np.atleast_2d(run.series("bed_pressure").values)
        column = float(bed["gas_density"]) * float(bed["gravity"]) * float(bed["gas_height"])
        carried = pressure[:, 0] - column + pressure[:, 1]
        ax.plot(t, carried, color="black", lw=1.2,
                label=r"bed pressure drop $\Delta p - \rho_g g H + $ inflow")
        ax.plot(t, pressure[:, 2], color=style.REFERENCE_COLOUR, lw=1.0, ls=":",
                label=r"buoyant weight per area $W/A$")
        if "bed_probe_pressure" in names:
            probes = np.atleast_2d(run.series("bed_probe_pressure").values)
            for k, (label, colour) in enumerate(zip(_probe_labels(bed),
                                                    style.sequence_colours(probes.shape[1], "plasma", 0.75))):
                ax.plot(t, probes[:, k], color=colour, lw=0.9, label=f"gas pressure, {label}")
        _shade_start(ax, t, start)
        ax.set_ylabel("pressure (Pa)")
        ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=8)
    axes[-1, 0].set_xlabel("time $t$ (s)")
    if start > t[0]:
        axes[0, 0].set_title(f"shaded: before the averaging start, {start:.3g} s", fontsize=9, loc="left")
    fig.tight_layout()
    fig.savefig(path, dpi=dpi)
    plt.close(fig)


def plot_bed_spectrum(bed, path, dpi):
    import matplotlib.pyplot as plt

    import style

    results = bed["results"]
    frequency = np.atleast_1d(results["spectrum_frequency"])
    amplitude = np.atleast_2d(results["spectrum_amplitude"])
    dominant = np.atleast_1d(results["probe_dominant_frequency"])
    peak = np.atleast_1d(results["probe_dominant_amplitude"])
    interval = np.atleast_1d(results["probe_interval"])
    labels = _probe_labels(bed)
    fig, ax = plt.subplots(figsize=(9.5, 3.8))
    colours = style.sequence_colours(amplitude.shape[0], "plasma", 0.75)
    for k in range(amplitude.shape[0]):
        ax.plot(frequency, amplitude[k], color=colours[k], lw=1.0, drawstyle="steps-mid",
                label=f"{labels[k]}: {dominant[k]:.3g} Hz, {peak[k]:.3g} Pa")
        ax.plot([dominant[k]], [peak[k]], "o", color=colours[k], ms=4)
    finite = frequency[np.isfinite(frequency)]
    if finite.size:
        resolution = finite[0]
        nyquist = 0.5 / np.nanmax(interval)
        ax.set_title(f"resolution 1/T = {resolution:.3g} Hz, Nyquist 1/(2 dt) = {nyquist:.3g} Hz",
                     fontsize=9, loc="left")
        ax.set_xlim(finite[0], finite[-1])
    # Logarithmic axes: the dominant peak and the broadband fall-off above it both show.
    ax.set_xscale("log")
    ax.set_yscale("log")
    top = np.nanmax(amplitude) if np.any(np.isfinite(amplitude)) else 1.0
    if top > 0:
        ax.set_ylim(top * 1e-3, top * 2.0)
    ax.set_xlabel("frequency $f$ (Hz)")
    ax.set_ylabel("amplitude of the gas pressure (Pa)")
    from matplotlib.ticker import FuncFormatter
    ax.xaxis.set_major_formatter(FuncFormatter(lambda v, _: f"{v:g}"))
    ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=8,
              title="probe: dominant frequency, amplitude", title_fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=dpi)
    plt.close(fig)


def plot_bed_map(run, bed, path, dpi):
    import matplotlib.pyplot as plt
    from matplotlib.colors import TwoSlopeNorm

    results = bed["results"]
    phi = np.asarray(results["map_solid_fraction"], dtype=float)
    velocity = np.asarray(results["map_velocity"], dtype=float)
    flux = np.asarray(results["map_flux"], dtype=float)
    across, up = AXES[int(bed["map_axis"])], AXES[int(bed["vertical_axis"])]
    lower, upper = float(bed["map_lower"]), float(bed["map_upper"])
    floor = float(bed["floor"])
    rows, columns = phi.shape
    vertical = int(bed["vertical_axis"])
    height = float(bed["extent"]) if "extent" in bed else \
        float(np.asarray(run.domain["upper"])[vertical] - np.asarray(run.domain["lower"])[vertical])
    x = 1e3 * np.linspace(lower, upper, columns + 1)
    z = 1e3 * (floor + np.linspace(0.0, height, rows + 1))
    # Up to two bins above the highest bin the beads reached in the mean (the freeboard beyond
    # says nothing).
    filled = np.nonzero(np.nan_to_num(phi).max(axis=1) > 1e-3)[0]
    top = min(rows, filled[-1] + 3) if filled.size else rows
    phi, velocity, flux, z = phi[:top], velocity[:top], flux[:top], z[:top + 1]
    xc, zc = 0.5 * (x[1:] + x[:-1]), 0.5 * (z[1:] + z[:-1])
    aspect = (z[-1] - z[0]) / max(x[-1] - x[0], 1e-12)
    panel_width = float(np.clip(5.0 / aspect, 1.6, 4.5))
    fig, (left, right) = plt.subplots(1, 2, figsize=(2 * panel_width + 3.0, min(8.0, panel_width * aspect + 1.6)),
                                      sharey=True, layout="constrained")
    mesh = left.pcolormesh(x, z, phi, cmap="Greys", vmin=0, vmax=max(0.6, np.nanmax(phi)), shading="flat")
    fig.colorbar(mesh, ax=left, label="solid fraction (–)", shrink=0.85)
    u, w = velocity[..., 0], velocity[..., 1]
    speed = np.hypot(u, w)
    # Arrows in the bed (solid fraction above 0.05), not for the few beads splashed above it; the
    # scale from the 90th percentile of their speeds, so that the slow downflow shows too.
    seen = np.isfinite(speed) & (phi > 0.05)
    if np.any(seen):
        X, Z = np.meshgrid(xc, zc)
        typical = float(np.percentile(speed[seen], 90))
        typical = typical if typical > 0 else 1.0
        arrows = left.quiver(X[seen], Z[seen], u[seen], w[seen], color="#d62728", angles="xy",
                             pivot="mid", scale_units="xy", minlength=0, width=0.008,
                             scale=typical / (0.9 * min(x[1] - x[0], z[1] - z[0])))
        reference = float(f"{typical:.1g}")
        left.quiverkey(arrows, 0.72, 1.03, reference, f"{1e3 * reference:.3g} mm/s", labelpos="E",
                       coordinates="axes", fontproperties={"size": 8})
        left.set_title("solid fraction and\nsolids velocity", fontsize=9, loc="left")
    vertical = flux[..., 1]
    bound = np.nanmax(np.abs(vertical)) if np.any(np.isfinite(vertical)) else 1.0
    bound = bound if bound > 0 else 1.0
    mesh = right.pcolormesh(x, z, vertical, cmap="RdBu_r", norm=TwoSlopeNorm(0.0, -bound, bound), shading="flat")
    fig.colorbar(mesh, ax=right, label="vertical solids mass flux (kg m$^{-2}$ s$^{-1}$)", shrink=0.85)
    right.set_title("vertical solids mass flux,\nred up, blue down", fontsize=9, loc="left")
    for ax in (left, right):
        ax.set_aspect("equal")
        ax.set_xlabel(f"${across}$ (mm)")
    left.set_ylabel(f"${up}$ (mm)")
    thickness, centre = float(bed["slab_thickness"]), float(bed["slab_centre"])
    depth = AXES[3 - int(bed["vertical_axis"]) - int(bed["map_axis"])]
    fig.suptitle(f"time averages after {float(bed['start']):.3g} s in the slab "
                 f"{1e3 * thickness:.3g} mm thick about ${depth}$ = {1e3 * centre:.3g} mm", fontsize=10)
    fig.savefig(path, dpi=dpi)
    plt.close(fig)
