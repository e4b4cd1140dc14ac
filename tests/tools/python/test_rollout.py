# SPDX-License-Identifier: MIT
"""vroc.rollout: the same as stepping one by one, the same bits for 1 and 2 jobs."""
import numpy as np
import pytest

import vroc
from conftest import scene_path


def _perturbed(scene, members, seed):
    rng = np.random.default_rng(seed)
    base = scene.initial_state()
    states = np.repeat(base[np.newaxis], members, axis=0)
    mask = scene.virtual
    states[:, mask, 0:3] += rng.normal(scale=1e-3, size=(members, int(mask.sum()), 3))
    states[:, mask, 7:10] += rng.normal(scale=0.05, size=(members, int(mask.sum()), 3))
    return states


def test_rollout_equals_stepping_one_by_one_for_one_and_two_jobs():
    scene = vroc.load_scene(scene_path("staircase.json"))
    initial = _perturbed(scene, 4, seed=7)
    frames = 40
    backends = ["native", "bullet"]
    one = vroc.rollout(scene, backends, initial, frames=frames, jobs=1)
    two = vroc.rollout(scene, backends, initial, frames=frames, jobs=2)
    n = len(scene)
    assert one.states.shape == (2, 4, frames, n, 13)
    assert one.states.dtype == np.float64 and one.states.flags["C_CONTIGUOUS"]
    assert one.states.tobytes() == two.states.tobytes()
    assert one.state_hashes == two.state_hashes
    for k, backend in enumerate(backends):
        for b in range(4):
            sim = vroc.Simulation(scene, backend)
            sim.set_state(initial[b])
            for f in range(frames):
                sim.step(1)
                assert sim.state().tobytes() == one.states[k, b, f].tobytes(), (backend, b, f)
            assert sim.state_hash == one.state_hashes[k][b]
            events = sim.events()
            assert events.tobytes() == one.events[k][b].tobytes()
            assert two.events[k][b].tobytes() == one.events[k][b].tobytes()


def test_rollout_defaults_to_the_scene_state_and_checks_shapes():
    scene = vroc.load_scene(scene_path("ball_drop.json"))
    r = vroc.rollout(scene, "ode", frames=3)
    assert r.backends == ["ode"] and r.states.shape == (1, 1, 3, len(scene), 13)
    with pytest.raises(ValueError, match=r"shape \(B, %d, 13\)" % len(scene)):
        vroc.rollout(scene, "ode", np.zeros((2, len(scene) + 1, 13)), frames=3)
    with pytest.raises(ValueError, match="unit quaternion"):
        vroc.rollout(scene, "ode", np.zeros((1, len(scene), 13)), frames=3)
    with pytest.raises(ValueError, match="unknown backend"):
        vroc.rollout(scene, "nosuch", frames=3)
