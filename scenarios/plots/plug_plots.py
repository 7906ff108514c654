"""The figure of a run's plug measurement (scenes with [analysis.plugs]; plugs.hpp), used by
plot.py.

RUN_plugs.png, two panels against time:
  left:  the axial solid fraction as a space-time diagram (/timeseries/axial_solid_fraction:
         height against time, the solid fraction over the cross-section open to the particles
         in colour), with the plug threshold's contour: plugs are the dark bands, their rise
         and fall the bands' slopes;
  right: the bed top (the top of the highest run of at least min_bins bins at or above the
         threshold, as plugs.hpp defines it, to the bin) at each threshold the run reports, with
         the plug counts and lengths of summary.json in the legend.
"""
import numpy as np


def _summary_plugs(summary):
    return summary.get("plugs") if summary else None


def bed_top(profile, threshold, min_bins, bin_length, bottom):
    """Height (m) of the top of the highest run of >= min_bins bins at or above threshold in
    one axial profile, to the bin; NaN when there is none."""
    dense = profile >= threshold
    top, run = np.nan, 0
    for k, d in enumerate(dense):
        run = run + 1 if d else 0
        if run >= min_bins and (k + 1 == len(dense) or not dense[k + 1]):
            top = bottom + (k + 1) * bin_length
    return top


def plot_plugs(run, summary, path, dpi):
    """Draws RUN_plugs.png of `run` (a carom.Output with [analysis.plugs]) at `path`; `summary`
    is summary.json's "analysis" object (its "plugs" in the legend), or None."""
    import matplotlib.pyplot as plt

    import style

    solid_fraction = run.series("axial_solid_fraction")
    t, phi = solid_fraction.time, solid_fraction.values
    plugs = _summary_plugs(summary) or {}
    setup = run.analysis_data("plugs")
    bin_length = float(plugs.get("bin", setup.get("bin", 1.0)))
    bottom = float(plugs.get("bottom", setup.get("bottom", 0.0)))
    min_bins = int(plugs.get("min_bins", 2))
    diameter = float(plugs.get("diameter", bin_length))
    thresholds = [float(x) for x in setup["thresholds"]]
    z = bottom + bin_length * np.arange(phi.shape[1] + 1)

    fig, (space, top) = plt.subplots(1, 2, figsize=(11, 4.2), gridspec_kw={"width_ratios": [3, 2]})
    edges_t = np.concatenate([t, [t[-1] + (t[-1] - t[-2] if len(t) > 1 else 1.0)]])
    mesh = space.pcolormesh(edges_t, z * 1e3, phi.T, cmap="Greys", vmin=0, vmax=max(0.65, phi.max()),
                            shading="flat", rasterized=True)
    centres = 0.5 * (z[1:] + z[:-1]) * 1e3
    # Thresholds along a sequential map (not species colours); the first is the scene's.
    colours = style.sequence_colours(len(thresholds), "plasma", end=0.7)
    if len(t) > 1:
        space.contour(t, centres, phi.T, levels=[thresholds[0]], colors=[colours[0]],
                      linewidths=0.6)
    fig.colorbar(mesh, ax=space, label="axial solid fraction (–)")
    space.set_xlabel("time $t$ (s)")
    space.set_ylabel("height $z$ (mm)")
    space.set_title(f"Plugs (contour: solid fraction {thresholds[0]:g})")

    by_threshold = {round(b["threshold"], 9): b for b in plugs.get("by_threshold", [])}
    for k, threshold in enumerate(thresholds):
        heights = np.array([bed_top(p, threshold, min_bins, bin_length, bottom) for p in phi])
        b = by_threshold.get(round(threshold, 9))
        label = f"{threshold:.2g}"
        if b and b.get("length_mean") is not None:
            label += (f": {b['plugs_mean']:.2g} plugs, $\\lambda/d$ = {b['length_mean']:.3g}"
                      f" ± {b['length_std']:.2g}")
        top.plot(t, heights * 1e3, lw=1.0 if k == 0 else 0.7, color=colours[k],
                 alpha=1.0 if k == 0 else 0.7, label=label)
    # A dense layer held at the top of the tube is the highest run of dense bins: say so, the
    # line then shows that layer, not the bed below it.
    heights = np.array([bed_top(p, thresholds[0], min_bins, bin_length, bottom) for p in phi])
    pinned = np.isclose(heights, z[-1])
    if len(t) and pinned.mean() > 0.5:
        top.text(0.02, 0.9, f"a dense layer at the top of the tube\n({pinned.mean():.0%} of the "
                 "samples): the bed top is its top", transform=top.transAxes, fontsize=8,
                 color="0.3", va="top")
    top.set_xlabel("time $t$ (s)")
    top.set_ylabel("bed top (mm)")
    top.set_ylim(z[0] * 1e3, z[-1] * 1e3)
    top.set_title(f"Bed top by threshold (d = {diameter * 1e3:.3g} mm)")
    top.legend(loc="lower right", fontsize=8, title="threshold", title_fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=dpi)
    plt.close(fig)
