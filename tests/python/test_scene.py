"""carom.Scene: changes validated as `--set` validates them, with the command line's messages,
and `carom check` as data. The messages are compared with the binary's own output, so that the
module can never word an error differently from the command line.
"""
import pytest

import carom
from conftest import SCENES, cli

SOFT = SCENES / "soft_box.toml"


def cli_error(*args):
    """The message `carom check` prints for a refused scene, less its "carom: error: "."""
    result = cli("check", *args, check=False)
    assert result.returncode == 2
    return result.stderr.strip().removeprefix("carom: error: ")


@pytest.mark.parametrize("key, value, text", [
    ("collisions.default.e", 1.5, "1.5"),                  # out of its range
    ("collisions.default.q", 0.5, "0.5"),                  # an unknown key, with a suggestion
    ("method.kind", "hard", '"hard"'),                     # not one of the choices
    ("domain.gravity", [0.0, 0.0], "[0.0, 0.0]"),         # an array of the wrong length
])
def test_a_refused_change_raises_the_command_lines_message(key, value, text):
    scene = carom.Scene.from_file(str(SOFT))
    with pytest.raises(carom.SceneError) as raised:
        scene.set(key, value)
    assert str(raised.value) == cli_error(SOFT, "--set", f"{key}={text}")
    # The refused change is forgotten: the scene is as it was.
    assert scene.changes == [] and scene.to_toml() == SOFT.read_text()


def test_scene_errors_are_value_errors_naming_file_and_line(tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text(SOFT.read_text().replace("contact_time = 1.0e-4", "contact_time = -1.0"))
    with pytest.raises(ValueError) as raised:
        carom.Scene.from_file(str(bad))
    assert isinstance(raised.value, carom.SceneError)
    assert str(raised.value) == cli_error(bad)
    assert f"{bad}:" in str(raised.value)


def test_changes_are_applied_in_order_and_written_out():
    scene = carom.Scene.from_file(str(SOFT))
    assert scene.set("collisions.default.e", 0.8) is scene
    scene.set("species.small.diameter", 0.8e-3).set("meta.name", "changed")
    assert scene.changes == ["collisions.default.e=0.8", "species.small.diameter=0.0008", "meta.name=\"changed\""]
    assert scene.name == "changed"
    # The text as run records the changes, as the command line's --set does, and reads back the same.
    text = scene.to_toml()
    assert text.startswith(f"# {SOFT} with --set collisions.default.e=0.8")
    again = carom.Scene.from_text(text, file=str(SOFT))
    assert again.to_toml() == text and again.name == "changed"


def test_values_of_every_toml_kind_are_accepted():
    scene = carom.Scene.from_file(str(SOFT))
    scene.set("domain.gravity", [0, 0, -9.0])             # an array of numbers (ints too)
    scene.set("collisions.walls", {"e": 0.5, "mu": 0.1, "beta0": 0.0})  # an inline table
    assert scene.changes[-1] == "collisions.walls={ e = 0.5, mu = 0.1, beta0 = 0.0 }"
    with pytest.raises(carom.SceneError, match="unknown key 'collisions.walls.e.x'"):
        scene.set("collisions.walls", {"e.x": 0.5})  # a key that needs quotes: not a dotted path
    scene.set("time.end", 0.002)
    scene.set("initial.seed", 7)
    assert scene.end_time == 0.002 and scene.seed == 7
    with pytest.raises(TypeError):
        scene.set("time.end", object())


def test_check_is_carom_check_as_data():
    report = carom.Scene.from_file(str(SOFT)).check()
    assert report.text == cli("check", SOFT).stdout
    assert str(report) == report.text
    assert report.method in ("event_driven", "soft_sphere", "monte_carlo")
    assert report.advice[0]["topic"] == "method" and report.advice[0]["choice"] == report.method
    assert report.numbers["solid_fraction"] > 0 and len(report.numbers["species"]) == 2


def test_a_missing_scene_file_is_a_scene_error(tmp_path):
    with pytest.raises(carom.SceneError, match="cannot open the scene file"):
        carom.Scene.from_file(str(tmp_path / "none.toml"))
