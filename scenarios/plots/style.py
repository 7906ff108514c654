"""The look shared by carom's figures: one colour per species, the same in every figure of a run
(snapshot, mixing, collisions, flow), and the fonts and frames of plot.py's figures.

A species is coloured by its index in the run's /species table (the order of [[species]] in the
scene). Quantities that are not species (energies, sections, thresholds, fits) take colours
from neutral_colour or a sequential map, so that no curve borrows a species' colour.
"""
import textwrap

import matplotlib.colors as mcolors
import matplotlib.pyplot as plt

DPI = 150

# Species colours: tab10 without its grey (index 7), kept for walls and references.
SPECIES_COLOURS = ("#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2",
                   "#bcbd22", "#17becf")
WALL_COLOUR = "0.45"       # collisions with walls, walls in pictures
REFERENCE_COLOUR = "0.3"   # reference levels (W/A, saturation, M = 0.8)
FIT_COLOUR = "black"       # fits and theory curves that are not per species


def apply():
    """The rcParams of carom's run figures."""
    plt.rcParams.update({
        "font.size": 10,
        "axes.labelsize": 10,
        "legend.fontsize": 9,
        "legend.frameon": False,
        "axes.spines.top": False,
        "axes.spines.right": False,
    })


def species_colour(index):
    """The colour of species `index` in every figure of a run."""
    return SPECIES_COLOURS[int(index) % len(SPECIES_COLOURS)]


def shade(colour, amount):
    """`colour` mixed with white (amount > 0, up to 1) or black (amount < 0)."""
    rgb = mcolors.to_rgb(colour)
    target = 1.0 if amount > 0 else 0.0
    a = abs(amount)
    return tuple((1 - a) * c + a * target for c in rgb)


# Markers for the partner species of a collision frequency (row species by colour, partner by
# marker and line style).
PARTNER_MARKERS = ("o", "s", "^", "v", "D", "P", "X", "*", "h")
PARTNER_LINES = ("-", "--", "-.", ":", (0, (5, 1)), (0, (3, 1, 1, 1, 1, 1)))


def partner_marker(index):
    return PARTNER_MARKERS[int(index) % len(PARTNER_MARKERS)]


def partner_line(index):
    return PARTNER_LINES[int(index) % len(PARTNER_LINES)]


def sequence_colours(count, cmap="viridis", end=0.85):
    """`count` colours along a sequential map from 0.1 to `end` of it (short of its light end,
    which is hard to see on white), for ordered quantities that are not species (section
    heights, thresholds)."""
    colours = plt.get_cmap(cmap)
    if count <= 1:
        return [colours(0.35)]
    return [colours(0.1 + (end - 0.1) * k / (count - 1)) for k in range(count)]


def wrap(text, width):
    """`text` broken into lines of at most `width` characters, never inside $...$ (mathtext)."""
    parts = text.split("$")
    joined = "$".join(part.replace(" ", "\x00") if k % 2 else part for k, part in enumerate(parts))
    return "\n".join(textwrap.wrap(joined, width)).replace("\x00", " ")


# A picture whose sides differ by more than this factor is drawn stretched (not to scale).
STRETCH = 25.0


def stretched(width, height):
    return max(width, height) > STRETCH * min(width, height)


def length_axes(ax, width, height, names):
    """Label the x and y axes of a picture `width` by `height` (m) with `names` (e.g. "xz"):
    ticks in mm when its largest extent is under 0.5 m (each axis by its own extent in a
    stretched picture), fewer ticks across a narrow axis."""
    from matplotlib.ticker import FuncFormatter, MaxNLocator

    x_ticks = 2 if width < 0.2 * height else 4
    for axis, name, ticks, extent in ((ax.xaxis, names[0], x_ticks, width),
                                      (ax.yaxis, names[1], 7, height)):
        extent = extent if stretched(width, height) else max(width, height)
        factor, unit = (1e3, "mm") if extent < 0.5 else (1.0, "m")
        axis.set_major_formatter(FuncFormatter(lambda v, _, f=factor: f"{v * f:.4g}"))
        axis.set_major_locator(MaxNLocator(nbins=ticks, steps=[1, 2, 2.5, 5, 10]))
        axis.set_label_text(f"${name}$ ({unit})")
    if width < 0.1 * height and not stretched(width, height):
        # A narrow column: one tick at its middle and its width in the label.
        factor, unit = (1e3, "mm") if max(width, height) < 0.5 else (1.0, "m")
        left, right = ax.get_xlim()
        ax.set_xticks([0.5 * (left + right)])
        ax.xaxis.set_label_text(f"${names[0]}$ ({unit}), {width * factor:.3g} {unit} wide")
