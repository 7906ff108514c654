"""carom.open for the plotting scripts: the readers of run files, checkpoints, sweeps and charts of
the Python package (scenarios/python/carom/_output.py and _summaries.py), loaded from the source
tree, so that the scripts need numpy and h5py only, with or without the compiled module.

    from carom_reader import open_run, OutputError
    run = open_run("out/run.h5")        # carom.Output: snapshots, particles(t), series(name), ...
    sweep = open_sweep("sweep.out")     # carom.Sweep: groups, mean, std, cases
    chart = open_chart("chart.out")     # carom.Chart: variants, observables, cases
"""
import importlib
import os
import sys
import types

# The package's pure-Python modules under a name of their own, without its __init__.py (which
# imports the compiled part): _summaries.py imports _output.py as its sibling.
_PACKAGE = "carom_readers"
if _PACKAGE not in sys.modules:
    _package = types.ModuleType(_PACKAGE)
    _package.__path__ = [os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, "python", "carom")]
    sys.modules[_PACKAGE] = _package
_output = importlib.import_module(f"{_PACKAGE}._output")
_summaries = importlib.import_module(f"{_PACKAGE}._summaries")

Output = _output.Output
OutputError = _output.OutputError
open_sweep = _summaries.open_sweep
open_chart = _summaries.open_chart


def open_run(path):
    """A run file (or an output directory's run.h5) as a carom.Output; a checkpoint or any other
    file raises OutputError with a message that says what it is."""
    run = _output.open(path)
    if run.kind != "run":
        raise OutputError(f"{run.path}: a carom {run.kind}, not a run file: the figures are drawn from "
                          "a run's run.h5")
    return run
