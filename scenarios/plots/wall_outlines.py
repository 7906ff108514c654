"""The scene's walls in a snapshot picture (plot.py): where the plane of the picture cuts them.

The walls come from the scene stored in the run file ([[walls]], read by carom.open): a
cylinder or a cone (axis along z) cut by the picture's mid-plane gives two lines in a side view
and a circle seen from above; a polygon is drawn as its outline projected on the picture. Meshes
(STL files) are not drawn; the picture's note says so.
"""
import numpy as np

WALL_STYLE = dict(color="0.25", lw=1.2)


def _scene_walls(run):
    try:
        return run.scene_table.get("walls", [])
    except ValueError:  # a scene text TOML cannot read: no walls to draw rather than no picture
        return []


def _cut(radius, offset):
    """Half-width of a circle of `radius` cut by a line `offset` from its centre (NaN if none)."""
    return np.sqrt(radius * radius - offset * offset) if abs(offset) < radius else np.nan


def draw_walls(ax, run, a, b, depth, middle):
    """Draws the walls of the run's scene (`run`: a carom.Output) cut by the plane (axes a, b;
    `depth` axis at `middle`, m). Returns the names of the walls it could not draw."""
    domain = run.domain
    lower, upper = domain["lower"], domain["upper"]
    skipped = []
    for wall in _scene_walls(run):
        kind = wall.get("type")
        name = wall.get("name", kind)
        if kind in ("cylinder", "cone"):
            centre = np.asarray(wall.get("axis", [0.0, 0.0, 0.0]), dtype=float)
            z = np.linspace(lower[2], upper[2], 50)
            if kind == "cylinder":
                radius = np.full_like(z, float(wall["radius"]))
            else:
                z0, z1 = float(wall["z_bottom"]), float(wall["z_top"])
                r0, r1 = float(wall["radius_bottom"]), float(wall["radius_top"])
                radius = (r0 * (z1 - z) + r1 * (z - z0)) / (z1 - z0)
            if b == 2 and a != 2:  # side view: the axis is vertical in the picture
                half = np.array([_cut(r, middle - centre[depth]) for r in radius])
                for sign in (-1, 1):
                    ax.plot(centre[a] + sign * half, z, **WALL_STYLE)
            elif {a, b} == {0, 1}:  # seen along the axis: the circle at the picture's height
                r = float(np.interp(middle, z, radius))
                phi = np.linspace(0, 2 * np.pi, 200)
                ax.plot(centre[a] + r * np.cos(phi), centre[b] + r * np.sin(phi), **WALL_STYLE)
            else:
                skipped.append(name)
        elif kind == "polygon":
            vertices = np.asarray(wall["vertices"], dtype=float)
            closed = np.vstack([vertices, vertices[:1]])
            ax.plot(closed[:, a], closed[:, b], **WALL_STYLE)
        else:
            skipped.append(name)
    return skipped
