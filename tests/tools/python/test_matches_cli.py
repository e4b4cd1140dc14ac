# SPDX-License-Identifier: MIT
"""A simulation stepped from Python ends where `vroc run` ends: the same state hash, and every
recorded frame of trajectory.csv the same numbers, on every backend, for two scenes."""
import numpy as np
import pytest

import vroc
from conftest import BACKENDS, scene_path, vroc_run

SCENES = ["ball_drop.json", "staircase.json"]


@pytest.mark.parametrize("backend", BACKENDS)
@pytest.mark.parametrize("scene_name", SCENES)
def test_state_hash_and_trajectory_equal_vroc_run(tmp_path, backend, scene_name):
    path = scene_path(scene_name)
    duration = 0.5
    run, rows = vroc_run(path, backend, duration, tmp_path / "run")
    sim = vroc.Simulation(path, backend)
    names = sim.scene.body_names
    frames = run["steps"]
    # trajectory.csv: frame 0 and every frame after it, bodies in scene order.
    by_time = {}
    for r in rows:
        by_time.setdefault(r["t"], []).append(r)
    times = list(by_time)
    assert len(times) == frames + 1
    columns = ["x", "y", "z", "qx", "qy", "qz", "qw", "vx", "vy", "vz", "wx", "wy", "wz"]
    for f, t in enumerate(times):
        if f > 0:
            sim.step(1)
        assert float(t) == sim.time
        state = sim.state()
        for r in by_time[t]:
            i = names.index(r["body"])
            expected = np.array([float(r[c]) for c in columns])
            assert np.array_equal(state[i], expected), (f, r["body"])   # the CSV's numbers round-trip doubles
    assert sim.state_hash == run["state_hash"]
    assert sim.frames == frames
