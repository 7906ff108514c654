"""The plotting scripts read run files, sweeps and charts through the package's readers
(scenarios/plots/carom_reader.py loads scenarios/python/carom/_output.py and _summaries.py from
the source tree): plot.py draws a run's figures, and sweep_plot.py and chart_plot.py a sweep's and
a chart's, in a Python that cannot import the compiled module; a wrong file is refused with the
reader's message instead of a traceback."""
import os
import pathlib
import subprocess
import sys

PLOTS = pathlib.Path(__file__).resolve().parents[2] / "scenarios" / "plots"


def script(name, *args):
    # No PYTHONPATH: the built module is out of reach, as for a user who never built it.
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    return subprocess.run([sys.executable, str(PLOTS / name), *map(str, args)], capture_output=True, text=True,
                          env=env)


def plot(path, out):
    return script("plot.py", path, "--out", out)


def test_plot_draws_a_runs_figures_without_the_compiled_module(cli_runs, tmp_path):
    result = plot(cli_runs["gas_bed.toml"] / "run.h5", tmp_path)
    assert result.returncode == 0, result.stderr
    drawn = sorted(p.name for p in tmp_path.glob("*.png"))
    for figure in ("energies", "collision_rates", "snapshot", "gas", "gas_field", "mixing"):
        assert f"run_{figure}.png" in drawn


def test_plot_refuses_a_checkpoint_and_other_files(cli_runs, tmp_path):
    result = plot(cli_runs["gas_bed.toml"] / "checkpoint.h5", tmp_path)
    assert result.returncode == 1 and "a carom checkpoint, not a run file" in result.stderr
    result = plot(cli_runs["gas_bed.toml"] / "summary.json", tmp_path)
    assert result.returncode == 1 and "not an HDF5 file" in result.stderr


def test_sweep_and_chart_figures_are_drawn_without_the_compiled_module(sweep_and_chart, tmp_path):
    summary = sweep_and_chart["sweep"] / "summary.h5"
    listed = script("sweep_plot.py", summary, "--list")
    assert listed.returncode == 0 and "varied keys: collisions.default.e" in listed.stdout
    line = script("sweep_plot.py", summary, "--x", "collisions.default.e", "--y", "mean_temperature",
                  "--out", tmp_path / "line.png")
    assert line.returncode == 0, line.stderr
    chart = script("chart_plot.py", sweep_and_chart["chart"], "--out", tmp_path)
    assert chart.returncode == 0, chart.stderr
    assert sorted(p.name for p in tmp_path.glob("*.png")) == ["line.png", "pareto_mean_temperature.png"]
    wrong = script("sweep_plot.py", sweep_and_chart["chart"] / "chart.h5", "--list")
    assert wrong.returncode == 1 and "carom.open_chart reads it" in wrong.stderr
