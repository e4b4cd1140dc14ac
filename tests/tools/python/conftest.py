# SPDX-License-Identifier: MIT
"""Shared fixtures: the source tree, the `vroc` program of the same build, and scene paths."""
import json
import os
import subprocess

import pytest

SOURCE_DIR = os.environ.get("VROC_SOURCE_DIR", os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", "..")))
VROC_BIN = os.environ.get("VROC_BIN", os.path.join(SOURCE_DIR, "build", "bin", "vroc"))
BACKENDS = ["bullet", "mujoco", "native", "ode"]


def scene_path(name):
    return os.path.join(SOURCE_DIR, "scenes", name)


def vroc_run(scene, backend, duration, out_dir, *settings):
    """`vroc run` as a user types it; returns (run.json as a dict, trajectory.csv rows as dicts)."""
    cmd = [VROC_BIN, "run", scene, "--backend", backend, "--duration", str(duration), "--out", str(out_dir), "-q"]
    for s in settings:
        cmd += ["--set", s]
    subprocess.run(cmd, check=True)
    with open(os.path.join(out_dir, "run.json")) as f:
        run = json.load(f)
    import csv
    with open(os.path.join(out_dir, "trajectory.csv")) as f:
        rows = list(csv.DictReader(f))
    return run, rows


@pytest.fixture
def ball_drop():
    return scene_path("ball_drop.json")
