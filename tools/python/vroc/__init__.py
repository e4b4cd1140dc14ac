# SPDX-License-Identifier: MIT
"""VROC from Python: scenes, backends, simulations with NumPy arrays, rollouts and the harness.

    import vroc
    scene = vroc.load_scene("scenes/paper/ball_drop.json")
    sim = vroc.Simulation(scene, backend="bullet")
    sim.run(1.0)
    sim.positions          # (N, 3) read-only snapshot, one call for every body
    sim.state_hash         # equal to `vroc run --duration 1`'s

Arrays follow the files: SI units, world frame, quaternions x y z w; a state row is position (3),
orientation (4), linear velocity (3), angular velocity (3): 13 numbers, one row per scene body in
scene order (real bodies included; `scene.virtual` masks the dynamic ones). Bad input raises
ValueError with the same one-line message as the `vroc` program. See docs/python.md.
"""
import os as _os
import sys as _sys

try:   # the extension's arrays are NumPy's: without it the extension cannot initialise
    import numpy as _numpy  # noqa: F401
except ImportError as _error:
    raise ImportError("vroc needs NumPy in this interpreter (%s). The module is built for Debian's python3 "
                      "(/usr/bin/python3) with python3-numpy: run that interpreter, or install NumPy here "
                      "(docs/python.md)." % _sys.executable) from _error
try:
    from . import _vroc  # noqa: F401
except ImportError as _error:
    raise ImportError("vroc: the extension vroc/_vroc*.so was not built for this interpreter (%s, Python %d.%d); "
                      "build with -DPython3_EXECUTABLE=%s (docs/python.md)"
                      % (_sys.executable, _sys.version_info[0], _sys.version_info[1], _sys.executable)) from _error

from ._vroc import (BUILD, EVENT_DTYPE, STATE_WIDTH, BackendInfo, Body, Material, Scene, SettingSpec,
                    Simulation, __version__, backend, backends)
from ._vroc import load_scene as _load_scene
from ._vroc import _rollout, _plugins
from .harness_result import HarnessResult, check, compare, ensemble, sweep, write_report
from .rollout_result import RolloutResult

__all__ = ["BUILD", "EVENT_DTYPE", "STATE_WIDTH", "BackendInfo", "Body", "HarnessResult", "Material",
           "RolloutResult", "Scene", "SettingSpec", "Simulation", "backend", "backends", "check", "compare",
           "ensemble", "load_scene", "plugins", "rollout", "sweep", "write_report", "__version__"]


def load_scene(path):
    """Loads and validates a scene file (str or os.PathLike). ValueError names file, field and what was expected."""
    return _load_scene(_os.fspath(path))


def _as_scene(scene):
    return scene if isinstance(scene, Scene) else load_scene(scene)


def rollout(scene, backends=("native",), initial_states=None, frames=1, jobs=1, settings=None, dt=None):
    """Steps every initial state on every backend for `frames` frames, on the run pool.

    scene: a Scene or a path. initial_states: (B, N, 13), default one member from the scene's own
    state. jobs: worker processes (1: in this process); the results are the same bits for any
    number. settings: {"backend.key": value}, routed to each backend by its prefix.
    Returns a RolloutResult: .states (backends, B, frames, N, 13), the states after frames
    1..frames; .events[backend][member] structured arrays; .warnings; .state_hashes.
    Member b on backend k equals Simulation(scene, k); set_state(initial_states[b]); step() x frames.
    """
    import numpy as np
    scene = _as_scene(scene)
    if isinstance(backends, str):
        backends = [backends]
    if initial_states is None:
        initial_states = scene.initial_state()[np.newaxis]
    return RolloutResult(_rollout(scene, list(backends), initial_states, int(frames), int(jobs), settings, dt))


def plugins(paths=()):
    """The device plugins found on the search path (VROC_PLUGIN_PATH, the build's or installed plugin
    folder) and those named in `paths`, as dicts; a plugin that fails negotiation is listed with
    'rejected' (one named in `paths` raises ValueError instead)."""
    here = _os.path.dirname(_os.path.abspath(__file__))
    candidates = [_os.path.join(here, "..", "..", "lib", "vroc-plugins"),   # build tree: build/python/vroc
                  _os.path.join(here, "..", "..", "..", "vroc", "plugins")]  # installed: <prefix>/lib/python3.X/dist-packages/vroc
    dirs = [_os.path.normpath(d) for d in candidates if _os.path.isdir(d)]
    return _plugins(dirs, [_os.fspath(p) for p in paths])
