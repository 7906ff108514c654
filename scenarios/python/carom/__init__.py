"""carom from Python: scenes, runs, simulations stepped in process, and the outputs as numpy arrays.

    import carom
    scene = carom.Scene.from_file("scenarios/scenes/fines_bed.toml")
    scene.set("gas.boundaries.z_low.velocity", 0.8)     # as `carom run --set`, validated at once
    print(scene.check())                                 # what `carom check` prints; .method, .advice
    run = carom.run(scene, out="out/fines_08")           # `carom run`, bit for bit; returns carom.open(out)
    run.series("gas_pressure_drop").values

    sim = carom.Simulation(scene)                        # stepped in process
    sim.advance(0.01); sim.positions(); sim.pressure()

The guide is scenarios/guides/python.md. After the build, Debian's Python imports the package
with PYTHONPATH=build/release/python. The compiled part (_carom) runs carom's own code; the
readers of outputs (_output.py: runs and checkpoints; _summaries.py: sweeps and charts) need only
numpy and h5py.
"""
import os

from . import _carom
from ._carom import Check, RunError, Scene, SceneError, Simulation, version
from ._output import Output, OutputError, Series, SERIES_UNITS, open
from ._summaries import Chart, Sweep, open_chart, open_sweep

__version__ = version
# carom.open is left out: `from carom import *` must not hide the built-in open.
__all__ = ["Scene", "SceneError", "RunError", "Check", "Simulation", "run", "resume", "sweep", "chart",
           "Output", "OutputError", "Series", "SERIES_UNITS", "Sweep", "Chart", "open_sweep", "open_chart",
           "executable"]

#: The `carom` binary built with this module (the cases of sweep() and chart() run it).
executable = _carom.executable

# The command line's exit codes (scenarios/run/run.hpp).
_OK, _FAILED, _USAGE, _INTERRUPTED = 0, 1, 2, 130


def _scene(scene):
    """A Scene, or a path read as one."""
    return Scene.from_file(os.fspath(scene)) if isinstance(scene, (str, os.PathLike)) else scene


def _message(errors, command):
    """What a command wrote to stderr, less the prefixes of its lines ("carom: ", "carom sweep: error: ")."""
    lines = []
    for line in errors.strip().splitlines():
        for prefix in (f"{command}: error: ", f"{command}: failed: ", f"{command}: "):
            if line.startswith(prefix):
                line = line[len(prefix):]
                break
        lines.append(line)
    return "\n".join(lines) or f"{command} failed"


def _outcome(code, errors, command):
    """The exit code of a command as Python's outcome: an exception for a stop, a bad input or a
    failure."""
    if code == _INTERRUPTED:
        raise KeyboardInterrupt(_message(errors, command))
    if code == _USAGE:
        raise SceneError(_message(errors, command))
    if code != _OK:
        raise RunError(_message(errors, command))


def run(scene, out=None, *, progress=True, overwrite=False):
    """Runs a scene (a Scene or a scene file) as `carom run` does, into the directory `out`
    (default: the scene file's name + ".out"), and returns carom.open(out).

    The same scene and seed give the same run.h5 as the command line, bit for bit. progress=False
    is --quiet. Ctrl-C stops the run with a checkpoint written (KeyboardInterrupt; continue with
    carom.resume(out)); a second Ctrl-C ends the Python process at once, as it ends `carom`.
    A run the physics stops (inelastic collapse, an unstable step) raises RunError, with
    summary.json written; a bad scene or output directory raises SceneError."""
    scene = _scene(scene)
    if out is None:
        out = os.path.splitext(os.path.basename(scene.file))[0] + ".out"
    out = os.fspath(out)
    code, errors = _carom._run(scene, out, not progress, overwrite)
    _outcome(code, errors, "carom")
    return open(out)


def resume(out, *, end=None, progress=True):
    """Continues the run in directory `out` from its checkpoint, as `carom resume` does (bit for
    bit), to `end` (s; default the scene's end), and returns carom.open(out)."""
    out = os.fspath(out)
    code, errors = _carom._resume(out, end, not progress)
    _outcome(code, errors, "carom")
    return open(out)


def sweep(file, *, out=None, jobs=1, retry_failed=False, dry_run=False, progress=True):
    """Runs a sweep file as `carom sweep` does (scenarios/sweep/SWEEPS.md): its cases are `carom
    run` processes of the binary `carom.executable`. Returns 0 when every case completed, 1 when
    some failed (the summary is still written); raises SceneError for a bad sweep file or case
    and KeyboardInterrupt when stopped (run it again to continue)."""
    code, errors = _carom._sweep(os.fspath(file), None if out is None else os.fspath(out), jobs, retry_failed,
                                 dry_run, not progress)
    if code != _FAILED:
        _outcome(code, errors, "carom sweep")
    return code


def chart(file, *, out=None, jobs=1, retry_failed=False, dry_run=False, progress=True):
    """Runs a chart file as `carom chart` does (scenarios/chart/CHARTS.md); returns and raises as
    sweep()."""
    code, errors = _carom._chart(os.fspath(file), None if out is None else os.fspath(out), jobs, retry_failed,
                                 dry_run, not progress)
    if code != _FAILED:
        _outcome(code, errors, "carom chart")
    return code
