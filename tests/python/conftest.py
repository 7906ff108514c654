"""Shared by the Python module's tests: the scenes, the `carom` binary, and exact comparisons of
two runs' outputs.

The module runs carom's own code, so its results must equal the command line's bit for bit:
every comparison here is exact (numpy.array_equal, NaN equal to NaN), never within a tolerance.
Only what measures wall-clock time (summary.json's rates per wall second, the gas's timings) and
what identifies a run (its random run id) may differ.
"""
import json
import os
import pathlib
import subprocess

import h5py
import numpy as np
import pytest

import carom

HERE = pathlib.Path(__file__).resolve().parent
SCENES = HERE / "scenes"
# Every method, the gas, inflow and outflow: one small scene each.
METHOD_SCENES = ["gas_bed.toml", "soft_box.toml", "monte_carlo_box.toml", "duct.toml"]
CAROM = os.environ.get("CAROM_BINARY", carom.executable)

# summary.json keys that measure wall-clock time (or name the run), not the physics.
WALL_CLOCK_KEYS = {"wall_seconds", "events_per_second", "collisions_per_second",
                   "simulated_seconds_per_wall_second", "mapping_seconds", "solve_seconds",
                   "interpolation_seconds", "event_seconds", "id"}


def cli(*args, check=True):
    """Runs the `carom` binary; returns the CompletedProcess (text output)."""
    result = subprocess.run([CAROM, *map(str, args)], capture_output=True, text=True)
    if check and result.returncode != 0:
        raise AssertionError(f"carom {' '.join(map(str, args))} exited {result.returncode}: {result.stderr}")
    return result


def h5_datasets(path):
    """Every dataset of an HDF5 file by name, read whole."""
    datasets = {}
    with h5py.File(path, "r", locking=False) as f:
        f.visititems(lambda name, obj: datasets.__setitem__(name, obj[()]) if isinstance(obj, h5py.Dataset) else None)
    return datasets


def assert_equal_arrays(a, b, what):
    a, b = np.asarray(a), np.asarray(b)
    assert a.shape == b.shape, f"{what}: shapes {a.shape} and {b.shape}"
    if a.dtype.kind == "f":
        assert np.array_equal(a, b, equal_nan=True), f"{what}: differs (largest difference {np.nanmax(np.abs(a - b))})"
    else:
        assert np.array_equal(a, b), f"{what}: differs"


def without_wall_clock(value):
    if isinstance(value, dict):
        return {k: without_wall_clock(v) for k, v in value.items() if k not in WALL_CLOCK_KEYS}
    if isinstance(value, list):
        return [without_wall_clock(v) for v in value]
    return value


def assert_same_run(dir_a, dir_b):
    """The two output directories hold the same run: every dataset of run.h5 equal bit for bit,
    and summary.json equal but for its wall-clock keys."""
    a, b = h5_datasets(pathlib.Path(dir_a) / "run.h5"), h5_datasets(pathlib.Path(dir_b) / "run.h5")
    assert sorted(a) == sorted(b)
    for name in a:
        assert_equal_arrays(a[name], b[name], f"run.h5 /{name}")
    summaries = [json.loads((pathlib.Path(d) / "summary.json").read_text()) for d in (dir_a, dir_b)]
    assert without_wall_clock(summaries[0]) == without_wall_clock(summaries[1])


@pytest.fixture(scope="session")
def cli_runs(tmp_path_factory):
    """`carom run` of each test scene, once per session: {scene file name: output directory}."""
    root = tmp_path_factory.mktemp("cli")
    runs = {}
    for name in METHOD_SCENES:
        out = root / name.replace(".toml", "")
        cli("run", SCENES / name, "--out", out, "--quiet")
        runs[name] = out
    return runs


@pytest.fixture(scope="session")
def sweep_and_chart(tmp_path_factory):
    """`carom sweep` (two restitutions, two seeds) and `carom chart` (two variants, two seeds) of
    the soft-sphere box, once per session: {"sweep": its output directory, "chart": the chart's}."""
    root = tmp_path_factory.mktemp("tables")
    sweep_file = root / "sweep.toml"
    sweep_file.write_text(f'[sweep]\nscene = "{SCENES / "soft_box.toml"}"\nseeds = [1, 2]\n'
                          '[[sweep.vary]]\nkey = "collisions.default.e"\nvalues = [0.7, 0.9]\n')
    chart_file = root / "chart.toml"
    chart_file.write_text(f'[chart]\nscene = "{SCENES / "soft_box.toml"}"\nseeds = [1, 2]\nreference = "e09"\n'
                          '[[chart.observable]]\nkey = "mean_temperature"\ntolerance = 0.5\n'
                          '[[chart.variant]]\nname = "e09"\n'
                          '[[chart.variant]]\nname = "e07"\nset = { "collisions.default.e" = 0.7 }\n')
    cli("sweep", sweep_file, "--out", root / "sweep", "--quiet")
    cli("chart", chart_file, "--out", root / "chart", "--quiet")
    return {"sweep": root / "sweep", "chart": root / "chart"}
