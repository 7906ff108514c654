"""carom.open for the plotting scripts: the reader of run files and checkpoints of the Python
package (scenarios/python/carom/_output.py), loaded from the source tree, so that the scripts
need numpy and h5py only, with or without the compiled module.

    from carom_reader import open_run, OutputError
    run = open_run("out/run.h5")        # carom.Output: snapshots, particles(t), series(name), ...
"""
import importlib.util
import os

_PATH = os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, "python", "carom", "_output.py")
_spec = importlib.util.spec_from_file_location("carom_output", _PATH)
_output = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(_output)

Output = _output.Output
OutputError = _output.OutputError


def open_run(path):
    """A run file (or an output directory's run.h5) as a carom.Output; a checkpoint or any other
    file raises OutputError with a message that says what it is."""
    run = _output.open(path)
    if run.kind != "run":
        raise OutputError(f"{run.path}: a carom {run.kind}, not a run file: the figures are drawn from "
                          "a run's run.h5")
    return run
