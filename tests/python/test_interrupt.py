"""Ctrl-C from Python, as on the command line: carom.run stops at a consistent state with a
checkpoint written, raises KeyboardInterrupt, and carom.resume continues the run to the same
result as a run never interrupted, bit for bit; Simulation.advance stops and goes on the same.

The runs are separate Python processes (a signal to this one would stop pytest), sent SIGINT
once they are under way. The soft-sphere box is run for 4 s of simulated time: about 4 s of wall
time, long enough that the signal always comes before the end.
"""
import json
import os
import signal
import subprocess
import sys
import time

import numpy as np

import carom
from conftest import SCENES, assert_equal_arrays, cli

LONG = ["time.end=4.0", "output.snapshot_every=0.5", "output.sample_every=0.05"]


def long_scene():
    scene = carom.Scene.from_file(str(SCENES / "soft_box.toml"))
    for change in LONG:
        key, value = change.split("=")
        scene.set(key, float(value))
    return scene


def start_python(code, tmp_path):
    """A Debian Python running `code` with this test's import path; its stdout and stderr in files."""
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path))
    stdout, stderr = open(tmp_path / "stdout", "w"), open(tmp_path / "stderr", "w")
    return subprocess.Popen([sys.executable, "-c", code], env=env, stdout=stdout, stderr=stderr)


def interrupt_when(process, ready, seconds=0.5):
    """Sends SIGINT `seconds` after ready() first holds, and waits for the process."""
    deadline = time.monotonic() + 60
    while not ready():
        assert process.poll() is None, "the process ended before it was interrupted"
        assert time.monotonic() < deadline, "the run never started"
        time.sleep(0.05)
    time.sleep(seconds)
    assert process.poll() is None, "the process ended before it was interrupted"
    process.send_signal(signal.SIGINT)
    return process.wait(timeout=60)


def test_run_interrupted_writes_a_checkpoint_and_resumes_bit_for_bit(tmp_path):
    out = tmp_path / "run"
    code = (f"import carom\nscene = carom.Scene.from_file({str(SCENES / 'soft_box.toml')!r})\n"
            f"for key, value in {[c.split('=') for c in LONG]!r}: scene.set(key, float(value))\n"
            f"carom.run(scene, out={str(out)!r}, progress=False)\n")
    process = start_python(code, tmp_path)
    interrupt_when(process, lambda: (out / "run.h5").exists())
    assert "KeyboardInterrupt" in (tmp_path / "stderr").read_text()
    summary = json.loads((out / "summary.json").read_text())
    assert summary["status"] == "interrupted" and summary["end_time"] < 4.0
    assert (out / "checkpoint.h5").exists()

    resumed = carom.resume(out, progress=False)
    cli("run", SCENES / "soft_box.toml", *[a for c in LONG for a in ("--set", c)], "--out", tmp_path / "cli",
        "--quiet")
    whole = carom.open(tmp_path / "cli")
    assert list(resumed.snapshots) == list(whole.snapshots)
    for t in whole.snapshots:
        ours, theirs = resumed.particles(t), whole.particles(t)
        for key in ("position", "velocity", "spin", "id"):
            assert_equal_arrays(ours[key], theirs[key], f"{key} at t = {t}")
    for name in ("time", "kinetic_translational", "pair_collisions", "wall_collisions", "dissipated"):
        assert_equal_arrays(resumed.series(name).values, whole.series(name).values, name)


def test_simulation_interrupted_stops_and_goes_on_unchanged(tmp_path):
    # The stopped simulation prints its time, advances again to the end and saves its state;
    # a simulation never stopped must end in the same state.
    code = (f"import carom, numpy\nscene = carom.Scene.from_file({str(SCENES / 'soft_box.toml')!r})\n"
            f"for key, value in {[c.split('=') for c in LONG]!r}: scene.set(key, float(value))\n"
            "sim = carom.Simulation(scene)\nprint('started', flush=True)\n"
            "try:\n    sim.advance(4.0)\nexcept KeyboardInterrupt:\n    print('stopped at', sim.time, flush=True)\n"
            "sim.advance(4.0)\n"
            f"numpy.savez({str(tmp_path / 'end.npz')!r}, positions=sim.positions(), velocities=sim.velocities(),"
            " spins=sim.spins())\n")
    process = start_python(code, tmp_path)
    assert interrupt_when(process, lambda: "started" in (tmp_path / "stdout").read_text()) == 0
    stopped = (tmp_path / "stdout").read_text().split("stopped at")[1].split()[0]
    assert 0 < float(stopped) < 4.0
    whole = carom.Simulation(long_scene())
    whole.advance(4.0)
    end = np.load(tmp_path / "end.npz")
    for key, ours in (("positions", whole.positions()), ("velocities", whole.velocities()), ("spins", whole.spins())):
        assert_equal_arrays(end[key], ours, key)
