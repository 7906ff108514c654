"""Reading carom's outputs: run.h5 (with summary.json and report.md beside it) and checkpoints.

    run = carom.open("out/run.h5")          # or the output directory itself
    run.snapshots                           # snapshot times, s
    run.particles(0.3)                      # the snapshot nearest 0.3 s: dict of numpy arrays
    run.series("gas_pressure_drop")         # Series(name, time, values, unit)
    run.gas(0.3)                            # porosity, pressure, velocity per gas cell
    run.summary["analysis"]                 # summary.json as a dict

The layout it reads is documented in scenarios/run/run_output.hpp; this module needs only numpy
and h5py, so the plotting scripts use it without the compiled part of the package. Files are
opened for each read and closed again, without HDF5's file lock: a run still being written (or
resumed) can be read at the same time, as of its last flush.
"""
import builtins
import collections
import json
import os

import h5py
import numpy as np

__all__ = ["Output", "OutputError", "Series", "SERIES_UNITS"]  # and open, kept out of star imports


class OutputError(ValueError):
    """A file that is not a carom run file or checkpoint of the layout this reader knows, or a
    request the file cannot answer (a snapshot of a checkpoint, a series it does not hold)."""


Series = collections.namedtuple("Series", "name time values unit")
Series.__doc__ = """One time series of a run file: its sample times (s), its values (one row per
sample, shaped as Output.series says) and the unit of the values."""

# The unit of every time series a run file may hold (scenarios/run/run_output.hpp,
# scenarios/analysis/run_analysis.hpp, tagged_bodies.hpp, plugs.hpp, section_profiles.hpp,
# scenarios/run/flow_run.hpp). "1": a pure number or a count. A test checks that every series of
# the test runs has its unit here.
SERIES_UNITS = {
    "time": "s",
    "kinetic_translational": "J", "kinetic_rotational": "J", "potential": "J", "elastic": "J",
    "dissipated": "J", "gas_work": "J", "total_energy": "J",
    "events": "1", "collisions": "1", "event_rate": "1/s", "collision_rate": "1/s",
    "virial": "J s", "kinetic_stress": "Pa", "pressure_tensor": "Pa", "pressure": "Pa",
    "pair_collisions": "1", "pair_impulse": "N s", "wall_collisions": "1", "wall_impulse": "N s",
    "pair_impacts": "1", "wall_impacts": "1", "kinetic_impact_rate": "1/s",
    "gas_pressure_drop": "Pa", "gas_inlet_velocity": "m/s", "gas_drag_force": "N",
    "gas_momentum_inflow": "Pa",
    "lacey_index": "1", "axial_msd": "m^2", "segregation_index": "1",
    "granular_temperature": "m^2/s^2", "kinetic_collision_rate": "1/s",
    "gas_velocity_seen": "m/s", "gas_force_mean": "N", "porosity_seen": "1",
    "particles_present": "1", "particle_seconds": "s", "entered": "1", "entered_mass": "kg",
    "waiting": "1", "left": "1", "left_mass": "kg", "flow_energy": "J",
    "tagged_position": "m", "tagged_velocity": "m/s", "tagged_impulse": "N s", "tagged_force": "N",
    "tagged_force_by_partner": "N", "tagged_mean_velocity": "m/s", "tagged_mean_force": "N",
    "axial_solid_fraction": "1", "plug_height": "m",
    # Sums of counts, velocities (m/s), their squares (m^2/s^2) and spins (rad/s) per section
    # and bin: scenarios/analysis/section_profiles.hpp.
    "profile_sums": "mixed",
    # [analysis.bed] (scenarios/analysis/bed_measures.hpp; the units also stand as attributes of
    # /analysis/bed): heights, the pressure balance, probe pressures, and sums of solid volume,
    # mass and momentum per map bin.
    "bed_height": "m", "bed_pressure": "Pa", "bed_probe_pressure": "Pa", "bed_map_sums": "mixed",
}

# Shapes of a row beyond (samples,): tensors as 3 x 3; per species pair S x S; per species and
# wall S x W; per wall W x 3; per species S x 3. Others stay as written.
_TENSORS = {"virial", "kinetic_stress", "pressure_tensor"}
_PAIRS = {"pair_collisions", "pair_impacts", "pair_impulse", "kinetic_collision_rate", "kinetic_impact_rate"}
_SPECIES_VECTORS = {"gas_velocity_seen", "gas_force_mean"}


def _text(value):
    """h5py gives fixed-length strings as bytes."""
    if isinstance(value, np.ndarray) and value.shape == ():
        value = value[()]
    return value.decode("utf-8") if isinstance(value, bytes) else str(value)


def _value(value):
    """An HDF5 attribute or dataset's value as Python reads it best: strings as str, one number
    as a Python number, arrays as numpy arrays (strings in them as lists of str)."""
    if isinstance(value, np.ndarray) and value.dtype.kind in "OSU":
        return [_text(v) for v in value.ravel()]
    if isinstance(value, (bytes, str)):
        return _text(value)
    if isinstance(value, np.generic):
        return value.item()
    return value


def _group_dict(group):
    """An HDF5 group as a dict: attributes and datasets by name, subgroups as dicts."""
    data = {name: _value(value) for name, value in group.attrs.items()}
    for name, item in group.items():
        data[name] = _group_dict(item) if isinstance(item, h5py.Group) else _value(item[()])
    return data


def _open_h5(path):
    # No HDF5 file lock: the writer of a run (carom run, carom resume) may hold it open.
    try:
        return h5py.File(path, "r", locking=False)
    except TypeError:  # an h5py without the locking argument
        os.environ.setdefault("HDF5_USE_FILE_LOCKING", "FALSE")
        return h5py.File(path, "r")


def open(path):  # noqa: A001 (carom.open, as the issue's examples write it)
    """A run file, checkpoint or output directory (its run.h5) as an Output."""
    return Output(path)


class Output:
    """A carom run file (kind "run") or checkpoint (kind "checkpoint"), with the summary.json and
    report.md beside it when they are there."""

    def __init__(self, path):
        path = os.fspath(path)
        if os.path.isdir(path):
            path = os.path.join(path, "run.h5")
        if not os.path.exists(path):
            raise OutputError(f"{path}: no such file (carom.open reads a run.h5, a checkpoint.h5 or an "
                              "output directory)")
        if not h5py.is_hdf5(path):
            raise OutputError(f"{path}: not an HDF5 file (carom.open reads a run.h5 or a checkpoint.h5)")
        self.path = path
        self.directory = os.path.dirname(os.path.abspath(path))
        with _open_h5(path) as f:
            kind = _text(f.attrs["kind"]) if "kind" in f.attrs else ""
            if kind not in ("carom run", "carom checkpoint"):
                what = ("a sweep's summary.h5: carom.open_sweep reads it" if "sweep_file" in f.attrs
                        else "a chart's chart.h5: carom.open_chart reads it" if "chart_file" in f.attrs
                        else "not a carom run file or checkpoint")
                raise OutputError(f"{path}: an HDF5 file, but {what} (root attribute 'kind' is "
                                  f"{repr(kind) if kind else 'missing'}); `carom info --tree {path}` lists what it holds")
            self.kind = kind.split()[1]
            needed = ["scene", "snapshots", "timeseries", "species"] if self.kind == "run" else ["scene", "state"]
            missing = [name for name in needed if name not in f]
            if missing:
                raise OutputError(f"{path}: a carom {self.kind} file of another layout (written by carom "
                                  f"{_text(f.attrs.get('carom_version', '?'))}; no /{', /'.join(missing)}); "
                                  "this reader knows the layout of scenarios/run/run_output.hpp")
            self.scene = _text(f["scene"][()])
            self.scene_name = _text(f.attrs.get("scene_name", ""))
            self.carom_version = _text(f.attrs.get("carom_version", ""))
            self.method = _text(f.attrs.get("method", ""))
            self.seed = int(f.attrs["seed"]) if "seed" in f.attrs else None
            self.run_id = f"{int(f.attrs['run_id']):016x}" if "run_id" in f.attrs else None

    def __repr__(self):
        return f"<carom.Output {self.kind} {self.path!r}: scene {self.scene_name!r}, {self.method}>"

    def _read(self, reader):
        with _open_h5(self.path) as f:
            return reader(f)

    def _need_run(self, what):
        if self.kind != "run":
            raise OutputError(f"{self.path}: a checkpoint holds each particle as of its own clock and no "
                              f"{what}; carom.Simulation.restore({self.path!r}) continues it, and gives "
                              "the particles at its time")

    # ---- beside the file ---------------------------------------------------------------------

    @property
    def summary(self):
        """summary.json beside the file as a dict (scenarios/run/SUMMARY.md), or None."""
        path = os.path.join(self.directory, "summary.json")
        if not os.path.exists(path):
            return None
        with builtins.open(path) as f:
            return json.load(f)

    @property
    def report(self):
        """report.md beside the file, or None."""
        path = os.path.join(self.directory, "report.md")
        if not os.path.exists(path):
            return None
        with builtins.open(path) as f:
            return f.read()

    @property
    def analysis(self):
        """The run's analysis conclusions: summary.json's "analysis" object (None without one)."""
        summary = self.summary
        return None if summary is None else summary.get("analysis")

    def analysis_data(self, part=None):
        """What the run's analysis wrote into the run file beside its time series (/analysis;
        run_analysis.hpp, bed_outputs.hpp) as a dict: its datasets as numpy arrays (strings as
        lists of str), its attributes as numbers, its subgroups as dicts of the same kind. None
        when the run has no analysis, or not that part.

        part None, the analysis itself: id (the particles of t = 0), tagged (1: in the lower
        half at t = 0), start_height (m), all by id; vertical_axis (0, 1, 2: x, y, z),
        mixing_species (index into species_names); mixing_grid and field_grid (lower, upper m;
        cells); with tagged bodies tagged_body_id and tagged_partner (species, then walls).
        "plugs": thresholds (solid fractions), bottom, bin (m), bins, area (m^2), diameter (m),
        min_bins. "profiles": heights, thickness, lower, upper, depth (m), start (s),
        vertical_axis, bin_axis, bins. "bed" and "bed/results": the bed measures, each value's
        unit beside it as NAME_unit."""
        self._need_run("analysis")

        def read(f):
            path = "analysis" if part is None else f"analysis/{part}"
            return _group_dict(f[path]) if path in f else None
        return self._read(read)

    # ---- the system --------------------------------------------------------------------------

    @property
    def scene_table(self):
        """The scene as run (`scene`) parsed: its tables and keys as a dict (SCENES.md), e.g.
        scene_table["walls"], the [[walls]] entries; needs Python 3.11 (tomllib)."""
        import tomllib  # here, so that reading arrays works in older Pythons too

        return tomllib.loads(self.scene)

    @property
    def species(self):
        """Per species: name, diameter (m), density (kg/m^3), mass (kg), count (at the start)."""
        self._need_run("species table")

        def read(f):
            g = f["species"]
            names = [_text(n) for n in g["name"][()]]
            return [{"name": names[k], "diameter": float(g["diameter"][k]), "density": float(g["density"][k]),
                     "mass": float(g["mass"][k]), "count": int(g["count"][k])} for k in range(len(names))]
        return self._read(read)

    @property
    def species_names(self):
        return [s["name"] for s in self.species]

    @property
    def walls(self):
        """The walls' names (the collision counters' columns)."""
        return self._read(lambda f: [_text(n) for n in f["walls/name"][()]] if "walls/name" in f else [])

    @property
    def domain(self):
        """lower, upper (m), periodic (per axis), gravity (m/s^2), volume (m^3)."""
        def read(f):
            g = f["domain"]
            return {"lower": g["lower"][()], "upper": g["upper"][()], "periodic": g["periodic"][()].astype(bool),
                    "gravity": g["gravity"][()], "volume": float(g.attrs["volume"])}
        return self._read(read)

    # ---- checkpoints -------------------------------------------------------------------------

    @property
    def time(self):
        """A checkpoint's time; a run file's last snapshot time, s."""
        if self.kind == "checkpoint":
            return self._read(lambda f: float(f["state"].attrs["time"]))
        return float(self.snapshots[-1])

    # ---- snapshots ---------------------------------------------------------------------------

    @property
    def snapshots(self):
        """The snapshot times, s, in order."""
        self._need_run("snapshots")
        return self._read(lambda f: np.array([f["snapshots"][name].attrs["time"] for name in sorted(f["snapshots"])]))

    def _snapshot_name(self, f, t, index=None):
        names = sorted(f["snapshots"])
        if not names:
            raise OutputError(f"{self.path}: no snapshots yet")
        if index is not None:
            # By position, as a list counts (negative from the end): a figure of "snapshot K".
            if not -len(names) <= index < len(names):
                raise OutputError(f"{self.path}: no snapshot {index}; it holds {len(names)} "
                                  f"(0 to {len(names) - 1}, or -1 to {-len(names)} from the end)")
            return names[index]
        if t is None:
            return names[-1]
        times = np.array([f["snapshots"][name].attrs["time"] for name in names])
        return names[int(np.argmin(np.abs(times - t)))]

    def particles(self, t=None, index=None):
        """The snapshot nearest time t (s; None: the last) as a dict of numpy arrays, rows in id
        order: position, velocity, spin (N x 3; m, m/s, rad/s), radius (m), species (index into
        species_names), id; and time, the snapshot's time (s). `index` picks the snapshot by its
        place in `snapshots` instead (0 the first, -1 the last)."""
        self._need_run("snapshots")

        def read(f):
            g = f["snapshots"][self._snapshot_name(f, t, index)]
            data = {name: g[name][()] for name in ("position", "velocity", "spin", "radius", "species", "id")}
            data["time"] = float(g.attrs["time"])
            return data
        return self._read(read)

    def gas(self, t=None, index=None):
        """The gas fields of the snapshot nearest time t (s; None: the last): porosity, pressure
        (Pa) as (nz, ny, nx), velocity (m/s) as (nz, ny, nx, 3), x varying fastest; and time (s).
        `index` picks the snapshot by its place in `snapshots` instead, as for particles."""
        self._need_run("gas fields")

        def read(f):
            g = f["snapshots"][self._snapshot_name(f, t, index)]
            if "gas" not in g:
                raise OutputError(f"{self.path}: this run has no gas fields")
            data = {name: g["gas"][name][()] for name in ("porosity", "pressure", "velocity")}
            data["time"] = float(g.attrs["time"])
            return data
        return self._read(read)

    @property
    def gas_grid(self):
        """The gas grid (None without a gas): cells (x, y, z), lower (m), spacing (m),
        open_volume (m^3, per cell), closure, and the gas's density, viscosity, time_step and
        minimum fluidization velocities (attributes of /gas)."""
        def read(f):
            if "gas" not in f:
                return None
            g = f["gas"]
            grid = {name: g[name][()] for name in ("cells", "lower", "spacing", "open_volume")}
            grid["closure"] = _text(g["closure"][()])
            grid.update({key: float(value) for key, value in g.attrs.items()})
            return grid
        return self._read(read)

    # ---- time series -------------------------------------------------------------------------

    @property
    def series_names(self):
        """Every time series the run file holds."""
        self._need_run("time series")
        return self._read(lambda f: sorted(f["timeseries"]))

    def series(self, name):
        """The time series `name` (series_names) as Series(name, time, values, unit). Rows are
        samples; per-row tensors are 3 x 3 (virial, kinetic_stress, pressure_tensor), per species
        pair S x S (pair_collisions, pair_impacts, pair_impulse, kinetic_collision_rate,
        kinetic_impact_rate), per species and wall S x W (wall_collisions, wall_impacts), per wall W x 3 (wall_impulse), per species S x 3
        (gas_velocity_seen, gas_force_mean); others as written (run_output.hpp)."""
        self._need_run("time series")

        def read(f):
            g = f["timeseries"]
            if name not in g:
                raise OutputError(f"{self.path}: no time series {name!r}; it holds {', '.join(sorted(g))}")
            values = g[name][()]
            time = g["time"][()]
            species = len(f["species/name"])
            walls = len(f["walls/name"]) if "walls/name" in f else 0
            rows = values.shape[0]
            if name in _TENSORS:
                values = values.reshape(rows, 3, 3)
            elif name in _PAIRS:
                values = values.reshape(rows, species, species)
            elif name in ("wall_collisions", "wall_impacts") and walls:
                values = values.reshape(rows, species, walls)
            elif name == "wall_impulse" and walls:
                values = values.reshape(rows, walls, 3)
            elif name in _SPECIES_VECTORS:
                values = values.reshape(rows, species, 3)
            return Series(name, time, values, SERIES_UNITS.get(name))
        return self._read(read)

