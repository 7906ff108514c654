"""carom.Simulation: a scene stepped in process by the method `carom run` uses.

Stepping must not change the run: the event-driven method's stop touches no particle, Monte
Carlo finishes the step it stopped in, and soft spheres stopped on their step boundaries take
the same steps. So advancing in pieces equals one advance to the end, and stepping through a
run's snapshot times gives its snapshots, bit for bit (exact comparisons: conftest.py). A
checkpoint restored continues bit for bit.
"""
import numpy as np
import pytest

import carom
from conftest import METHOD_SCENES, SCENES, assert_equal_arrays


def scene(name):
    return carom.Scene.from_file(str(SCENES / name))


def state(sim):
    """Everything a Simulation reports, by name."""
    values = {"time": sim.time, "positions": sim.positions(), "velocities": sim.velocities(), "spins": sim.spins(),
              "radii": sim.radii(), "species": sim.species(), "ids": sim.ids()}
    values.update({f"energy {k}": v for k, v in sim.energies().items()})
    values.update({f"collisions {k}": v for k, v in sim.collisions().items()})
    if sim.has_gas:
        values.update(porosity=sim.porosity(), pressure=sim.pressure(), gas_velocity=sim.gas_velocity(),
                      pressure_drop=sim.pressure_drop())
    return values


def assert_same_state(a, b):
    assert a.keys() == b.keys()
    for key in a:
        assert_equal_arrays(a[key], b[key], key)


# Stops between the outputs: any time for the event-driven and Monte Carlo methods (stop_time(t)
# is t), the next step boundary for soft spheres (stop_time), where stopping changes nothing.
PIECES = [0.0013, 0.0021, 0.0037]


@pytest.mark.parametrize("name", METHOD_SCENES)
def test_advancing_in_pieces_equals_one_advance(name):
    whole = carom.Simulation(scene(name))
    end = scene(name).end_time
    whole.advance(end)
    pieces = carom.Simulation(scene(name))
    for t in PIECES:
        if pieces.method != "soft_sphere":  # these stop anywhere: the pieces end at t itself
            assert pieces.stop_time(t) == t
        while pieces.time < t:  # stop_time may first be a synchronising action (a fluid step)
            assert pieces.advance(pieces.stop_time(t)) == pieces.time
    pieces.advance(end)
    assert pieces.time == whole.time == end
    assert_same_state(state(pieces), state(whole))


@pytest.mark.parametrize("name", METHOD_SCENES)
def test_stepping_through_a_runs_snapshot_times_gives_its_snapshots(name, cli_runs):
    run = carom.open(cli_runs[name])
    sim = carom.Simulation(scene(name))
    for t in run.snapshots:
        sim.advance(t)
        snapshot = run.particles(t)
        assert snapshot["time"] == sim.time
        for key, ours in (("position", sim.positions()), ("velocity", sim.velocities()), ("spin", sim.spins()),
                          ("radius", sim.radii()), ("species", sim.species()), ("id", sim.ids())):
            assert_equal_arrays(ours, snapshot[key], f"{key} at t = {t}")
        if sim.has_gas:
            gas = run.gas(t)
            for key, ours in (("porosity", sim.porosity()), ("pressure", sim.pressure()),
                              ("velocity", sim.gas_velocity())):
                assert_equal_arrays(ours, gas[key], f"gas {key} at t = {t}")


@pytest.mark.parametrize("name", METHOD_SCENES)
def test_a_checkpoint_restored_continues_bit_for_bit(name, tmp_path):
    end = scene(name).end_time
    whole = carom.Simulation(scene(name))
    whole.advance(end)
    first = carom.Simulation(scene(name))
    first.advance(first.stop_time(end / 2))
    first.checkpoint(str(tmp_path / "half.h5"))
    restored = carom.Simulation.restore(str(tmp_path / "half.h5"))
    assert restored.time == first.time and restored.method == first.method
    restored.advance(end)
    assert_same_state(state(restored), state(whole))


def test_the_state_has_the_documented_shapes_and_units():
    sim = carom.Simulation(scene("gas_bed.toml"))
    n = sim.particle_count
    assert n == 36 and sim.species_names == ["glass", "fines"] and sim.method == "event_driven"
    assert sim.positions().shape == sim.velocities().shape == sim.spins().shape == (n, 3)
    assert sim.radii().shape == sim.species().shape == sim.ids().shape == (n,)
    assert (np.diff(sim.ids()) > 0).all()  # id order, as the run file's rows
    assert sorted(set(sim.radii())) == [0.3e-3, 0.5e-3]
    collisions = sim.collisions()
    assert collisions["pair"].shape == (2, 2) and collisions["wall"].shape == (2, len(sim.wall_names))
    assert sim.porosity().shape == sim.pressure().shape == (4, 1, 2)  # (nz, ny, nx) as in run.h5
    assert sim.gas_velocity().shape == (4, 1, 2, 3)
    sim.advance(0.005)
    energies = sim.energies()
    assert energies["total"] == pytest.approx(sum(energies[k] for k in ("translational", "rotational", "potential",
                                                                        "elastic", "dissipated"))
                                              - energies["gas_work"] - energies["flow"], rel=1e-12)
    # The copies are the caller's: changing them changes nothing in the simulation.
    positions = sim.positions()
    positions[:] = 0
    assert (sim.positions() != 0).any()


def test_particles_entering_and_leaving_are_followed_by_id():
    sim = carom.Simulation(scene("duct.toml"))
    assert sim.particle_count == 0
    sim.advance(0.02)
    entered = sim.ids()
    assert len(entered) > 0 and (np.diff(entered) > 0).all()


def test_a_scene_without_gas_has_no_gas_fields():
    sim = carom.Simulation(scene("soft_box.toml"))
    assert not sim.has_gas
    with pytest.raises(ValueError, match="no coupled gas"):
        sim.pressure()


def test_a_soft_sphere_run_reports_its_quantities():
    sim = carom.Simulation(scene("soft_box.toml"))
    sim.advance(0.001)
    assert sim.method == "soft_sphere"
    assert "coordination_number" in sim.quantities()
