"""Reading the tables of many runs: a sweep's summary.h5 (`carom sweep`, SWEEPS.md) and a chart's
chart.h5 (`carom chart`, CHARTS.md), as numpy arrays.

    sweep = carom.open_sweep("fines_sweep.out")         # the output directory or its summary.h5
    sweep.varied_keys, sweep.metrics                    # names, in the tables' column order
    sweep.groups["species.fines.diameter"]              # one value per group
    sweep.mean["analysis.mixing.rate"]                  # its mean over each group's completed cases
    sweep.cases["status"]                               # one value per case

    chart = carom.open_chart("dilute_gas_chart.out")    # the output directory or its chart.h5
    chart.variants["name"], chart.variants["cost"]      # one value per variant
    chart.observables["mean_temperature"]["error"]      # one value per variant

Every column is a numpy array: numbers as written (NaN: missing), strings as str, flags as bool.
A `/` in a name is written `_` in the files; the tables here are keyed by the names as the files
list them. Needs only numpy and h5py, like the reader of run files (_output.py).
"""
import os

import numpy as np

from ._output import OutputError, _open_h5, _text

__all__ = ["Sweep", "Chart"]  # and open_sweep, open_chart


def _column(dataset):
    """One column of a table: strings as an array of str, int8 flags as bools, else as written."""
    values = dataset[()]
    if values.dtype.kind in "OSU":
        return np.array([_text(v) for v in values], dtype=str)
    return values


def _table(group, names=()):
    """The datasets of an HDF5 group as {name: column}; `names` (the keys and metrics the file
    lists) replace the names their `/` was written `_` in."""
    table = {name: _column(item) for name, item in group.items() if not hasattr(item, "keys")}
    for name in names:
        stored = name.replace("/", "_")
        if stored != name and stored in table:
            table[name] = table.pop(stored)
    return table


def _summary_file(path, file_name, kind, marker, other):
    """The path of a sweep's or chart's table file (`path`: the file or its output directory),
    checked to be one: its root carries the attribute `marker`."""
    path = os.fspath(path)
    if os.path.isdir(path):
        path = os.path.join(path, file_name)
    if not os.path.exists(path):
        raise OutputError(f"{path}: no such file (the {kind}'s output directory holds {file_name})")
    try:
        f = _open_h5(path)
    except OSError:
        raise OutputError(f"{path}: not an HDF5 file (a {kind}'s tables are its {file_name})") from None
    with f:
        if marker not in f.attrs:
            what = (f"a {_text(f.attrs['kind'])} file: carom.open reads it" if "kind" in f.attrs
                    else other[1] if other[0] in f.attrs else "not a carom table file")
            raise OutputError(f"{path}: not a {kind}'s {file_name} ({what})")
    return path


def open_sweep(path):
    """A sweep's summary.h5 (or its output directory) as a Sweep."""
    return Sweep(path)


def open_chart(path):
    """A chart's chart.h5 (or its output directory) as a Chart."""
    return Chart(path)


class Sweep:
    """The tables of `carom sweep` (summary.h5; SWEEPS.md "Outputs").

    varied_keys, metrics: the names, in column order. cases: per case, case, group, seed,
    exit_code, attempts, status, message, elapsed_seconds (s), each varied key and each metric.
    groups: per group, group, n_cases, n_completed and each varied key. mean, std: per metric,
    its mean and sample standard deviation over each group's completed cases (NaN: none).
    carom_version, sweep_file, scene: the root attributes."""

    def __init__(self, path):
        self.path = _summary_file(path, "summary.h5", "sweep", "sweep_file",
                                  ("chart_file", "a chart's chart.h5: carom.open_chart reads it"))
        with _open_h5(self.path) as f:
            self.carom_version = _text(f.attrs.get("carom_version", ""))
            self.sweep_file = _text(f.attrs["sweep_file"])
            self.scene = _text(f.attrs.get("scene", ""))
            self.varied_keys = [_text(k) for k in f["varied_keys"][()]]
            self.metrics = [_text(m) for m in f["metrics"][()]]
            names = self.varied_keys + self.metrics
            self.cases = _table(f["cases"], names)
            self.groups = _table(f["groups"], self.varied_keys)
            self.mean = _table(f["groups/mean"], self.metrics)
            self.std = _table(f["groups/std"], self.metrics)

    def __repr__(self):
        return (f"<carom.Sweep {self.path!r}: {len(self.cases['case'])} cases in "
                f"{len(self.groups['group'])} groups, varying {', '.join(self.varied_keys) or 'nothing'}>")


class Chart:
    """The tables of `carom chart` (chart.h5; CHARTS.md "Outputs").

    observable_keys: in file order. variants: per variant, name, reference (bool), n_cases,
    n_completed, cost (CPU s per simulated s) and cost_stderr. observables: per key, a dict of
    per-variant columns (mean, stderr, error, uncertainty, noise; the flags within_noise,
    within_tolerance, pareto, pareto_within_noise as bools) and its attributes key, tolerance,
    error_measure, cheapest_within_tolerance (variant index, -1: none). cases: per case, case,
    variant (index), seed, status, cpu_seconds, simulated_seconds (s), cost, and observables
    ({key: column}). carom_version, chart_file, scene, reference (the reference variant's name):
    the root attributes."""

    _FLAGS = ("within_noise", "within_tolerance", "pareto", "pareto_within_noise")

    def __init__(self, path):
        self.path = _summary_file(path, "chart.h5", "chart", "chart_file",
                                  ("sweep_file", "a sweep's summary.h5: carom.open_sweep reads it"))
        with _open_h5(self.path) as f:
            self.carom_version = _text(f.attrs.get("carom_version", ""))
            self.chart_file = _text(f.attrs["chart_file"])
            self.scene = _text(f.attrs.get("scene", ""))
            self.reference = _text(f.attrs["reference"])
            self.observable_keys = [_text(k) for k in f["observable_keys"][()]]
            self.variants = _table(f["variants"])
            self.variants["reference"] = self.variants["reference"].astype(bool)
            self.observables = {key: self._observable(f["observables"][key.replace("/", "_")], key)
                                for key in self.observable_keys}
            self.cases = _table(f["cases"])
            if "observables" in f["cases"]:
                self.cases["observables"] = _table(f["cases/observables"], self.observable_keys)

    def _observable(self, group, key):
        data = _table(group)
        for flag in self._FLAGS:
            if flag in data:
                data[flag] = data[flag].astype(bool)
        for name, value in group.attrs.items():
            value = _text(value) if isinstance(value, (bytes, str)) else value
            data[name] = value.item() if isinstance(value, np.generic) else value
        return data

    def __repr__(self):
        return (f"<carom.Chart {self.path!r}: {len(self.variants['name'])} variants, reference "
                f"{self.reference!r}, observables {', '.join(self.observable_keys)}>")
