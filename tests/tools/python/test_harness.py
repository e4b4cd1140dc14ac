# SPDX-License-Identifier: MIT
"""The harness from Python: the same documents as the `vroc` commands, tables as arrays, reports."""
import json
import os
import subprocess

import numpy as np
import pytest

import vroc
from conftest import VROC_BIN, scene_path


def test_check_equals_the_command_and_its_tables_are_arrays(tmp_path):
    r = vroc.check(backends=["native", "bullet"], only=["ballistic", "bounce-e0.8"], jobs=2)
    assert r.command == "check" and r.exit_code == 0 and r.report is None
    table = r.tables["checks"]
    assert isinstance(table["native measured"], np.ndarray)
    # every judged check passes on native; ballistic.euler-ratio is reported ("info"), not judged
    assert table["native result"] == ["info" if c == "ballistic.euler-ratio" else "pass" for c in table["check"]]
    cli = tmp_path / "cli"
    subprocess.run([VROC_BIN, "check", "--backends", "native,bullet", "--only", "ballistic", "--only", "bounce-e0.8",
                    "--out", str(cli), "-j", "1", "-q"], check=True, capture_output=True)
    with open(cli / "metrics.json") as f:
        doc = json.load(f)
    assert doc["tables"] == r.document["tables"]      # the same numbers, bit for bit, jobs 2 or 1
    report = r.write_report(tmp_path / "py")
    assert os.path.basename(report) == "report.html" and os.path.getsize(report) > 1000
    with open(tmp_path / "py" / "metrics.json") as f:
        assert json.load(f)["tables"] == doc["tables"]


def test_compare_writes_its_report_when_asked(tmp_path):
    r = vroc.compare(scene_path("ball_drop.json"), ["native", "ode"], duration=0.5, windows=2, window=0.1,
                     out=tmp_path / "cmp", jobs=1)
    assert r.report and os.path.exists(r.report)
    assert os.path.exists(tmp_path / "cmp" / "metrics.json")
    assert r.tables and all(isinstance(t, dict) for t in r.tables.values())
    assert r.charts
    series = next(iter(next(iter(r.charts.values())).values()))
    assert isinstance(series[0], np.ndarray) and len(series[0]) == len(series[1])


def test_sweep_and_ensemble_return_their_verdicts():
    s = vroc.sweep(scene_path("ball_drop.json"), ["native", "bullet"], dts=[1 / 60, 1 / 120], duration=0.5,
                   windows=2, window=0.1)
    assert s.command == "sweep" and isinstance(s.pareto_front, list) and s.pareto_front
    assert all(p["cost"] > 0 for p in s.pareto_front)
    e = vroc.ensemble(scene_path("ball_drop.json"), ["native", "bullet"], members=4, duration=0.5)
    assert e.command == "ensemble" and "native" in e.verdict
    assert e.tables


def test_plugins_lists_the_built_in_device_plugins():
    found = {p.get("name") for p in vroc.plugins() if p.get("rejected") is None}
    assert {"analytic", "replay"} <= found


def test_both_footings_from_python_equal_the_command():
    # Bullet steps semi-implicit Euler once per frame at its own defaults and footing_substeps times on
    # the equal footing: the ballistic check's euler-ratio (the error against the closed form, per
    # first-order step error) is 1 and 1/3. The same numbers as `vroc check --footing both`.
    r = vroc.check(backends=["bullet"], only=["ballistic"], footing="both", footing_substeps=3)
    cells = {c["id"]: c["results"] for c in r.document["results"]["checks"]}
    ratio = cells["ballistic.euler-ratio"]
    assert ratio["bullet-defaults"]["footing"] == "defaults" and ratio["bullet-equal"]["footing"] == "equal"
    assert abs(ratio["bullet-defaults"]["measured"] - 1.0) < 1e-6
    assert abs(ratio["bullet-equal"]["measured"] - 1.0 / 3.0) < 1e-6
    cli = subprocess.run([VROC_BIN, "check", "--backends", "bullet", "--only", "ballistic", "--footing", "both",
                          "--footing-substeps", "3", "-q"], check=True, capture_output=True, text=True)
    assert "bullet (equal footing)" in cli.stdout
    for bad in ({"footing": "both"}, {"footing": "level"}, {"footing": "equal", "footing_substeps": 0}):
        with pytest.raises(ValueError, match="footing"):   # bad input is the module's ValueError
            vroc.sweep(scene_path("ball_drop.json"), ["bullet"], dts=[1 / 60], duration=0.1, **bad)
