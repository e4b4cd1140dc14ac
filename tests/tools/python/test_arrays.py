# SPDX-License-Identifier: MIT
"""Arrays: shapes, dtypes, contiguity, read-only snapshots, exact state round trips."""
import numpy as np
import pytest

import vroc
from conftest import BACKENDS, scene_path


def test_batch_arrays_have_documented_shapes_dtypes_and_layout():
    scene = vroc.load_scene(scene_path("stress/pyramid10.json"))
    sim = vroc.Simulation(scene, "native")
    sim.step(5)
    n = len(scene)
    for name, width in [("positions", 3), ("orientations", 4), ("linear_velocities", 3), ("angular_velocities", 3)]:
        a = getattr(sim, name)
        assert a.shape == (n, width), name
        assert a.dtype == np.float64
        assert a.flags["C_CONTIGUOUS"]
        assert not a.flags["WRITEABLE"]
    state = sim.state()
    assert state.shape == (n, vroc.STATE_WIDTH) and state.dtype == np.float64 and state.flags["C_CONTIGUOUS"]
    assert state.flags["WRITEABLE"]
    # The views and the state agree column by column (x y z w quaternions, as in the files).
    assert np.array_equal(state[:, 0:3], sim.positions)
    assert np.array_equal(state[:, 3:7], sim.orientations)
    assert np.array_equal(state[:, 7:10], sim.linear_velocities)
    assert np.array_equal(state[:, 10:13], sim.angular_velocities)
    assert np.allclose(np.linalg.norm(sim.orientations, axis=1), 1.0, atol=1e-12)


def test_views_are_read_only_and_a_held_snapshot_never_changes():
    sim = vroc.Simulation(scene_path("ball_drop.json"), "native")
    p = sim.positions
    with pytest.raises(ValueError, match="read-only"):
        p[0, 2] = 5.0
    held = p.copy()
    sim.step(10)
    assert np.array_equal(p, held)            # the array handed out is a snapshot
    assert not np.array_equal(sim.positions, held)   # a new one after the step
    # Writes go through set_state, and reach the simulation.
    s = sim.state()
    ball = sim.scene.find_body("ball")
    s[ball, 2] = 3.0
    s[ball, 7:10] = 0.0
    sim.set_state(s)
    assert sim.positions[ball, 2] == 3.0
    sim.step(1)
    g = sim.scene.gravity[2]
    assert sim.linear_velocities[ball, 2] == pytest.approx(g * sim.dt, rel=1e-9)   # from rest: v = g dt


def test_initial_state_matches_the_scene_and_the_first_read():
    scene = vroc.load_scene(scene_path("stress/pyramid10.json"))
    sim = vroc.Simulation(scene, "native")
    assert np.array_equal(sim.state(), scene.initial_state())


@pytest.mark.parametrize("backend", BACKENDS)
def test_set_state_of_state_changes_no_bit_and_restore_is_exact(backend):
    sim = vroc.Simulation(scene_path("stress/pyramid10.json"), backend)
    sim.step(20)
    s = sim.state()
    sim.set_state(s)
    assert sim.state().tobytes() == s.tobytes()
    snap = sim.snapshot()
    sim.step(20)
    later = sim.state_hash
    after = sim.state()
    sim.restore(snap)
    assert sim.state().tobytes() == s.tobytes()
    assert sim.frames == 20
    sim.step(20)
    assert sim.state_hash == later
    assert sim.state().tobytes() == after.tobytes()


@pytest.mark.parametrize("backend", BACKENDS)
def test_a_state_set_through_the_backend_comes_back_within_rounding(backend):
    sim = vroc.Simulation(scene_path("stress/pyramid10.json"), backend)
    sim.step(20)
    s = sim.state()
    moved = s.copy()
    moved[1:, 0] += 1e-3        # every box 1 mm along x: the backend takes the states through its setter
    sim.set_state(moved)
    back = sim.state()
    assert np.allclose(back, moved, rtol=0, atol=1e-14)


def test_events_are_a_structured_array_taken_once():
    sim = vroc.Simulation(scene_path("ball_drop.json"), "native")
    sim.run(1.0)
    e = sim.events()
    assert e.dtype == vroc.EVENT_DTYPE
    assert e.dtype.names == ("time", "body_a", "body_b", "point", "normal", "impulse")
    assert len(e) >= 1
    assert np.all(np.diff(e["time"]) >= 0) and np.all(e["impulse"] >= 0)
    assert e["point"].shape == (len(e), 3)
    # The first impact of a ball dropped from rest at height h: t = sqrt(2 (h - r) / g).
    scene = sim.scene
    ball = scene.bodies[scene.find_body("ball")]
    h = ball.position[2] - ball.radius
    t = np.sqrt(2 * h / -scene.gravity[2])
    assert e["time"][0] == pytest.approx(t, abs=2e-3)
    assert len(sim.events()) == 0        # taken


def test_statistics_warnings_and_settings_are_dicts():
    sim = vroc.Simulation(scene_path("ball_drop.json"), "bullet", settings={"substeps": 4})
    sim.step(3)
    assert sim.settings["bullet.substeps"] == 4
    assert isinstance(sim.warnings(), dict)
    st = sim.statistics()
    assert st["frames"] == 3
    assert len(sim.step_times) == 3 and np.all(sim.step_times > 0)
