"""carom.open: run files, checkpoints and output directories read back as numpy arrays; and
carom.open_sweep, carom.open_chart: the tables of a sweep and of a chart. The readers are checked
against the files read directly with h5py, and against the units of every time series the test
runs write.
"""
import json

import h5py
import numpy as np
import pytest

import carom
from conftest import METHOD_SCENES, SCENES, assert_equal_arrays, h5_datasets


def test_particles_and_gas_are_the_snapshots(cli_runs):
    run = carom.open(cli_runs["gas_bed.toml"] / "run.h5")
    raw = h5_datasets(run.path)
    assert list(run.snapshots) == [0.0, 0.0025, 0.005, 0.0075, 0.01]
    for k, t in enumerate(run.snapshots):
        particles, gas = run.particles(t), run.gas(t)
        assert particles["time"] == gas["time"] == t
        for key in ("position", "velocity", "spin", "radius", "species", "id"):
            assert np.array_equal(particles[key], raw[f"snapshots/{k:06d}/{key}"])
        for key in ("porosity", "pressure", "velocity"):
            assert np.array_equal(gas[key], raw[f"snapshots/{k:06d}/gas/{key}"])
    # Between snapshots the nearest one; None the last.
    assert run.particles(0.0026)["time"] == 0.0025 and run.particles()["time"] == 0.01
    assert run.gas_grid["cells"].tolist() == [2, 1, 4] and run.gas_grid["closure"] == "gidaspow_blend"


def test_series_have_their_times_shapes_and_units(cli_runs):
    run = carom.open(cli_runs["gas_bed.toml"])  # the directory: its run.h5
    drop = run.series("gas_pressure_drop")
    assert drop.unit == "Pa" and drop.time.shape == drop.values.shape == (11,)
    assert run.series("pair_collisions").values.shape == (11, 2, 2)
    assert run.series("pressure_tensor").values.shape == (11, 3, 3)
    assert run.series("gas_velocity_seen").values.shape == (11, 2, 3)
    walls = len(run.walls)
    assert run.series("wall_collisions").values.shape == (11, 2, walls)
    assert run.series("wall_impulse").values.shape == (11, walls, 3)
    with pytest.raises(carom.OutputError, match="no time series 'nothing'"):
        run.series("nothing")


@pytest.mark.parametrize("name", METHOD_SCENES)
def test_every_series_written_has_a_unit(name, cli_runs):
    # A series added to the run file without its unit in carom.SERIES_UNITS fails here.
    run = carom.open(cli_runs[name])
    missing = [series for series in run.series_names if series not in carom.SERIES_UNITS]
    assert missing == []


def test_summary_report_and_analysis_are_read_beside_the_file(cli_runs):
    run = carom.open(cli_runs["gas_bed.toml"])
    summary = json.loads((cli_runs["gas_bed.toml"] / "summary.json").read_text())
    assert run.summary == summary and run.analysis == summary["analysis"]
    assert run.analysis["mixing"]["species"] == "glass"
    assert run.report == (cli_runs["gas_bed.toml"] / "report.md").read_text()
    assert run.scene == (SCENES / "gas_bed.toml").read_text()  # no changes: the file's text
    assert run.scene_name == "python_gas_bed" and run.method == "event_driven" and run.seed == 3
    assert run.species_names == ["glass", "fines"]


def test_a_checkpoint_is_read_for_what_it_holds(cli_runs):
    checkpoint = carom.open(cli_runs["soft_box.toml"] / "checkpoint.h5")
    assert checkpoint.kind == "checkpoint" and checkpoint.method == "soft_sphere"
    assert checkpoint.time == 0.004
    with pytest.raises(carom.OutputError, match="carom.Simulation.restore"):
        checkpoint.particles()


def test_other_files_are_refused_with_a_message(tmp_path):
    text = tmp_path / "notes.txt"
    text.write_text("not HDF5")
    with pytest.raises(carom.OutputError, match="not an HDF5 file"):
        carom.open(text)
    other = tmp_path / "other.h5"
    with h5py.File(other, "w") as f:
        f.attrs["kind"] = "something else"
    with pytest.raises(carom.OutputError, match="not a carom run file or checkpoint"):
        carom.open(other)
    old = tmp_path / "old.h5"
    with h5py.File(old, "w") as f:
        f.attrs["kind"] = "carom run"
        f.attrs["carom_version"] = "0.0.1"
        f["scene"] = "x"
    with pytest.raises(carom.OutputError, match="of another layout"):
        carom.open(old)
    with pytest.raises(carom.OutputError, match="no such file"):
        carom.open(tmp_path / "none")


def test_snapshots_are_read_by_their_place_as_well_as_by_time(cli_runs):
    # The plotting scripts' --snapshot K: the K-th snapshot, negative from the end.
    run = carom.open(cli_runs["gas_bed.toml"])
    times = run.snapshots
    for k, t in enumerate(times):
        for place in (k, k - len(times)):
            assert run.particles(index=place)["time"] == t and run.gas(index=place)["time"] == t
            assert np.array_equal(run.particles(index=place)["position"], run.particles(t)["position"])
    with pytest.raises(carom.OutputError, match="no snapshot 5; it holds 5"):
        run.particles(index=5)
    with pytest.raises(carom.OutputError, match="no snapshot -6"):
        run.gas(index=-6)


def test_analysis_data_is_the_analysis_group_of_the_file(cli_runs):
    # Every dataset and attribute under /analysis, at its place in the nested dicts.
    run = carom.open(cli_runs["gas_bed.toml"])
    data = run.analysis_data()
    raw = h5_datasets(run.path)
    datasets = [name for name in raw if name.startswith("analysis/")]
    assert datasets
    for name in datasets:
        value = data
        for part in name.split("/")[1:]:
            value = value[part]
        # NaN stands for "not measured" (bed measures before their start): equal to itself here.
        assert np.array_equal(value, raw[name], equal_nan=np.asarray(value).dtype.kind == "f")
    with h5py.File(run.path, "r") as f:
        for key, value in f["analysis"].attrs.items():
            assert data[key] == value and type(data[key]) in (int, float)
    assert run.species_names[data["mixing_species"]] == run.analysis["mixing"]["species"] == "glass"
    assert data["vertical_axis"] == 2 and data["mixing_grid"]["cells"].shape == (3,)
    # A part the scene did not ask for is None, as is the analysis of a checkpoint refused.
    assert run.analysis_data("plugs") is None
    with pytest.raises(carom.OutputError, match="carom.Simulation.restore"):
        carom.open(cli_runs["gas_bed.toml"] / "checkpoint.h5").analysis_data()


def test_scene_table_is_the_scene_as_run_parsed(cli_runs):
    import tomllib

    run = carom.open(cli_runs["duct.toml"])
    assert run.scene_table == tomllib.loads(run.scene) == tomllib.loads((SCENES / "duct.toml").read_text())
    assert [entry["species"] for entry in run.scene_table["inflow"]] == run.species_names



def _texts(values):
    return [v.decode() if isinstance(v, bytes) else str(v) for v in values]


def test_a_sweeps_tables_are_the_files_columns(sweep_and_chart):
    sweep = carom.open_sweep(sweep_and_chart["sweep"])  # the directory: its summary.h5
    raw = h5_datasets(sweep.path)
    assert sweep.varied_keys == ["collisions.default.e"] == _texts(raw["varied_keys"])
    assert sweep.metrics == _texts(raw["metrics"]) and "mean_temperature" in sweep.metrics
    for table, columns in (("cases", sweep.cases), ("groups", sweep.groups), ("groups/mean", sweep.mean),
                           ("groups/std", sweep.std)):
        stored = {name.split("/")[-1] for name in raw if name.rsplit("/", 1)[0] == table}
        assert set(columns) == stored
        for name in stored:
            expected = raw[f"{table}/{name}"]
            if expected.dtype.kind in "OS":  # strings come as str
                assert list(columns[name]) == _texts(expected)
            else:
                assert_equal_arrays(columns[name], expected, f"{table}/{name}")
    assert list(sweep.cases["status"]) == ["completed"] * 4 and sweep.groups["n_completed"].tolist() == [2, 2]
    assert sweep.groups["collisions.default.e"].tolist() == [0.7, 0.9]
    assert sweep.mean["mean_temperature"].shape == (2,) and sweep.scene.endswith("soft_box.toml")


def test_a_charts_tables_are_the_files_columns(sweep_and_chart):
    chart = carom.open_chart(sweep_and_chart["chart"])
    raw = h5_datasets(chart.path)
    assert chart.reference == "e09" and chart.observable_keys == ["mean_temperature"]
    assert list(chart.variants["name"]) == ["e09", "e07"] and chart.variants["reference"].tolist() == [True, False]
    assert_equal_arrays(chart.variants["cost"], raw["variants/cost"], "variants/cost")
    observable = chart.observables["mean_temperature"]
    for name in ("mean", "stderr", "error", "uncertainty", "noise"):
        assert_equal_arrays(observable[name], raw[f"observables/mean_temperature/{name}"], name)
    for flag in ("within_noise", "within_tolerance", "pareto", "pareto_within_noise"):
        assert observable[flag].dtype == bool
        assert observable[flag].tolist() == (raw[f"observables/mean_temperature/{flag}"] != 0).tolist()
    assert observable["tolerance"] == 0.5 and observable["key"] == "mean_temperature"
    assert observable["error_measure"] in ("relative", "absolute")
    assert_equal_arrays(chart.cases["observables"]["mean_temperature"], raw["cases/observables/mean_temperature"],
                        "cases/observables/mean_temperature")
    assert list(chart.cases["status"]) == ["completed"] * 4


def test_each_table_reader_refuses_the_other_files_with_a_message(sweep_and_chart, cli_runs):
    with pytest.raises(carom.OutputError, match="a chart's chart.h5: carom.open_chart reads it"):
        carom.open_sweep(sweep_and_chart["chart"] / "chart.h5")
    with pytest.raises(carom.OutputError, match="a carom run file: carom.open reads it"):
        carom.open_chart(cli_runs["duct.toml"] / "run.h5")
    with pytest.raises(carom.OutputError, match="no such file"):
        carom.open_chart(sweep_and_chart["sweep"])
    with pytest.raises(carom.OutputError, match="a sweep's summary.h5: carom.open_sweep reads it"):
        carom.open(sweep_and_chart["sweep"] / "summary.h5")
