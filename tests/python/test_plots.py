"""The plotting scripts read run files through the package's reader (scenarios/plots/
carom_reader.py loads scenarios/python/carom/_output.py from the source tree): plot.py draws a
run's figures in a Python that cannot import the compiled module, and refuses a checkpoint or
another file with the reader's message instead of a traceback."""
import os
import pathlib
import subprocess
import sys

PLOT = pathlib.Path(__file__).resolve().parents[2] / "scenarios" / "plots" / "plot.py"


def plot(path, out):
    # No PYTHONPATH: the built module is out of reach, as for a user who never built it.
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    return subprocess.run([sys.executable, str(PLOT), str(path), "--out", str(out)], capture_output=True,
                          text=True, env=env)


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
