# SPDX-License-Identifier: MIT
"""The harness from Python: the same documents as the `vroc` commands, tables as arrays, reports."""
import json
import os
import subprocess

import numpy as np

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
