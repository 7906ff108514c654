"""carom.run, carom.resume, carom.sweep, carom.chart: the command line's machinery called from Python.

carom.run calls the function behind `carom run`, so the same scene and seed must give the same
run.h5 bit for bit, for every method (the comparison is exact: conftest.py). Changes made with
Scene.set must equal the same `--set` on the command line, down to the scene text stored in
run.h5.
"""
import json

import pytest

import carom
from conftest import METHOD_SCENES, SCENES, assert_same_run, cli


@pytest.mark.parametrize("name", METHOD_SCENES)
def test_run_equals_the_command_line_bit_for_bit(name, cli_runs, tmp_path):
    output = carom.run(SCENES / name, out=tmp_path / "python", progress=False)
    assert output.kind == "run"
    assert_same_run(cli_runs[name], tmp_path / "python")


def test_set_equals_the_command_lines_set(tmp_path):
    # A changed restitution and seed: the same scene text (with its list of changes) and run.
    cli("run", SCENES / "soft_box.toml", "--set", "collisions.default.e=0.8", "--set", "initial.seed=9",
        "--out", tmp_path / "cli", "--quiet")
    scene = carom.Scene.from_file(str(SCENES / "soft_box.toml"))
    scene.set("collisions.default.e", 0.8).set("initial.seed", 9)
    carom.run(scene, out=tmp_path / "python", progress=False)
    assert_same_run(tmp_path / "cli", tmp_path / "python")


def test_resume_continues_bit_for_bit(cli_runs, tmp_path):
    # The gas bed run to half its end, then resumed from Python to the end: the run file equals
    # the uninterrupted command-line run's (resume writes exactly what the whole run writes).
    scene = carom.Scene.from_file(str(SCENES / "gas_bed.toml")).set("time.end", 0.005)
    carom.run(scene, out=tmp_path / "run", progress=False)
    output = carom.resume(tmp_path / "run", end=0.01, progress=False)
    assert output.snapshots[-1] == 0.01
    cli_snapshots = carom.open(cli_runs["gas_bed.toml"]).particles()
    resumed = output.particles()
    for key in ("position", "velocity", "spin", "id"):
        assert (cli_snapshots[key] == resumed[key]).all()
    assert (output.series("gas_pressure_drop").values ==
            carom.open(cli_runs["gas_bed.toml"]).series("gas_pressure_drop").values).all()


def test_a_second_run_into_the_same_directory_is_refused(tmp_path):
    carom.run(SCENES / "soft_box.toml", out=tmp_path / "out", progress=False)
    with pytest.raises(carom.SceneError, match="already holds the outputs of a run"):
        carom.run(SCENES / "soft_box.toml", out=tmp_path / "out", progress=False)
    carom.run(SCENES / "soft_box.toml", out=tmp_path / "out", progress=False, overwrite=True)


def test_a_run_the_physics_stops_raises_run_error(tmp_path):
    # Fully inelastic, frictionless spheres without the TC model in a box under gravity collapse:
    # the run ends with exit 1 on the command line, RunError here, summary.json saying why.
    scene = carom.Scene.from_file(str(SCENES / "soft_box.toml"))
    scene.set("method.kind", "event_driven").set("collisions.default.e", 0.0).set("collisions.walls.e", 0.0)
    scene.set("time.end", 2.0)
    with pytest.raises(carom.RunError) as raised:
        carom.run(scene, out=tmp_path / "out", progress=False)
    summary = json.loads((tmp_path / "out" / "summary.json").read_text())
    assert summary["status"] != "completed"
    assert summary["message"] in str(raised.value)


def test_sweep_is_the_command_lines_sweep(tmp_path):
    # Two cases (two restitutions) through carom.sweep and through `carom sweep`: the same cases,
    # each bit for bit.
    sweep_file = tmp_path / "sweep.toml"
    sweep_file.write_text(f'[sweep]\nscene = "{SCENES / "soft_box.toml"}"\n'
                          '[[sweep.vary]]\nkey = "collisions.default.e"\nvalues = [0.7, 0.9]\n')
    assert carom.sweep(sweep_file, out=tmp_path / "python", progress=False) == 0
    cli("sweep", sweep_file, "--out", tmp_path / "cli", "--quiet")
    for case in ("0000", "0001"):
        assert_same_run(tmp_path / "cli" / "cases" / case, tmp_path / "python" / "cases" / case)


def test_a_bad_sweep_file_raises_scene_error_with_the_command_lines_message(tmp_path):
    sweep_file = tmp_path / "sweep.toml"
    sweep_file.write_text(f'[sweep]\nscene = "{SCENES / "soft_box.toml"}"\n'
                          '[[sweep.vary]]\nkey = "collisions.default.e"\nvalues = [0.7, 1.5]\n')
    expected = cli("sweep", sweep_file, "--out", tmp_path / "cli", check=False)
    assert expected.returncode == 2
    with pytest.raises(carom.SceneError) as raised:
        carom.sweep(sweep_file, out=tmp_path / "python", progress=False)
    assert "outside the allowed range [0, 1]" in str(raised.value)
    for line in str(raised.value).splitlines():  # the command's lines, less their "carom sweep: error: "
        assert line in expected.stderr


def test_chart_is_the_command_lines_chart(tmp_path):
    # Two variants of the soft-sphere box over two seeds through carom.chart and `carom chart`:
    # the same cases bit for bit, and the chart's tables written (their costs are CPU times, so
    # only the cases are compared).
    chart_file = tmp_path / "chart.toml"
    chart_file.write_text(f'[chart]\nscene = "{SCENES / "soft_box.toml"}"\nseeds = [1, 2]\nreference = "e09"\n'
                          '[[chart.observable]]\nkey = "mean_temperature"\ntolerance = 0.5\n'
                          '[[chart.variant]]\nname = "e09"\n'
                          '[[chart.variant]]\nname = "e07"\nset = { "collisions.default.e" = 0.7 }\n')
    assert carom.chart(chart_file, out=tmp_path / "python", progress=False) == 0
    cli("chart", chart_file, "--out", tmp_path / "cli", "--quiet")
    assert (tmp_path / "python" / "chart.csv").exists()
    for case in ("0000", "0001", "0002", "0003"):
        assert_same_run(tmp_path / "cli" / "cases" / case, tmp_path / "python" / "cases" / case)
