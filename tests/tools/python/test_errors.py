# SPDX-License-Identifier: MIT
"""Errors: the loader's one-line message as ValueError, settings that list the valid keys."""
import subprocess

import pytest

import vroc
from conftest import VROC_BIN, scene_path


def test_a_bad_scene_file_raises_value_error_with_the_programs_message(tmp_path):
    bad = tmp_path / "bad.json"
    bad.write_text('{"format": "vroc-scene/1", "name": "x", "bodies": [{"name": "a", "role": "virtual", '
                   '"shape": {"type": "sphere", "radius": -1}}]}')
    with pytest.raises(ValueError) as info:
        vroc.load_scene(bad)
    message = str(info.value)
    assert str(bad) in message
    cli = subprocess.run([VROC_BIN, "run", str(bad), "--backend", "native", "--out", str(tmp_path / "o"), "-q"],
                         capture_output=True, text=True)
    assert cli.returncode == 2
    assert message in cli.stderr     # the same one line
    with pytest.raises(ValueError) as from_json:
        vroc.Scene.from_json(bad.read_text(), "inline")
    assert "inline" in str(from_json.value)


def test_a_missing_file_and_a_wrong_type_are_clear():
    with pytest.raises(ValueError, match="nosuch.json"):
        vroc.load_scene("nosuch.json")
    with pytest.raises(ValueError, match="scene"):
        vroc.Simulation(42, "native")


def test_a_bad_setting_lists_the_valid_keys():
    with pytest.raises(ValueError) as info:
        vroc.Simulation(scene_path("ball_drop.json"), "bullet", settings={"bullet.nosuch": 1})
    message = str(info.value)
    assert "bullet.nosuch" in message
    for spec in vroc.backend("bullet").settings:
        assert spec.key in message
    with pytest.raises(ValueError, match="bullet.substeps"):
        vroc.Simulation(scene_path("ball_drop.json"), "bullet", settings={"substeps": "many"})
    with pytest.raises(ValueError, match="expected a bool, int, float or str"):
        vroc.Simulation(scene_path("ball_drop.json"), "bullet", settings={"substeps": [1]})


def test_unknown_backend_and_bad_state_shapes():
    with pytest.raises(ValueError, match="unknown backend 'nosuch'.*native"):
        vroc.Simulation(scene_path("ball_drop.json"), "nosuch")
    sim = vroc.Simulation(scene_path("ball_drop.json"), "native")
    with pytest.raises(ValueError, match=r"shape \(%d, 13\)" % sim.body_count):
        sim.set_state([[0.0] * 13])
    real = [i for i, b in enumerate(sim.scene.bodies) if b.role == "real"]
    assert real, "ball_drop has a floor"
    s = sim.state()
    s[real[0], 2] += 1.0
    with pytest.raises(ValueError, match="is real"):
        sim.set_state(s)
    with pytest.raises(ValueError, match="frames must be >= 0"):
        sim.step(-1)
    with pytest.raises(ValueError, match="out of range"):
        sim.apply_impulse(99, [0, 0, 1], [0, 0, 0])


def test_backends_describe_themselves():
    infos = {b.name: b for b in vroc.backends()}
    assert set(infos) >= {"bullet", "mujoco", "native", "ode"}
    bullet = infos["bullet"]
    assert "bullet" in bullet.version.lower()
    assert bullet.capabilities["sphere"] in ("exact", "approximated")
    assert isinstance(bullet.deviations, list) and bullet.deviations
    keys = [s.key for s in bullet.settings]
    assert "bullet.substeps" in keys
    assert bullet.defaults["bullet.substeps"] == 1
