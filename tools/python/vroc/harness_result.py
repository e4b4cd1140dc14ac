# SPDX-License-Identifier: MIT
"""The harness commands from Python: compare, check, sweep, ensemble, each returning a HarnessResult.

Every command runs on the project's run pool (`jobs` worker processes; the metrics are the same bits
for any number), exactly as `vroc compare/check/sweep/ensemble` does, and returns the metrics
document its report is rendered from. With `out` the command also writes metrics.json and
report.html there (and compare its CSVs); without, nothing is left on disk, and
HarnessResult.write_report(folder) writes the same report later.
"""
import json
import os

from . import _vroc


class HarnessResult:
    """A harness command's result.

    document: the metrics document (dict), as metrics.json holds it.
    tables: {table id: {column: numpy array (numbers; NaN where a cell is empty) or list (text)}}.
    charts: {chart id: {series name: (x array, y array)}}.
    report: path of report.html when `out` was given, else None.
    Plus what the command prints: check's exit_code and text, sweep's pareto_front, ensemble's verdict.
    """

    def __init__(self, raw):
        self.document = json.loads(raw.pop("document"))
        self.report = raw.pop("report")
        self.command = self.document.get("command")
        self.extras = dict(raw)
        for key, value in raw.items():
            setattr(self, key, value)
        self.tables = {t["id"]: _columns(t) for t in self.document.get("tables", [])}
        self.table_titles = {t["id"]: t["title"] for t in self.document.get("tables", [])}
        self.charts = {c["id"]: _series(c) for c in self.document.get("charts", [])}

    def write_report(self, out):
        """Writes metrics.json and report.html into folder `out` (created); returns the report's path."""
        return _vroc._write_report(json.dumps(self.document, allow_nan=False), os.fspath(out))

    def __repr__(self):
        return "<vroc.HarnessResult %s: tables %s>" % (self.command, ", ".join(self.tables))


def _columns(table):
    import numpy as np
    out = {}
    for i, name in enumerate(table["columns"]):
        cells = [row[i] if i < len(row) else None for row in table["rows"]]
        numeric = all(c is None or (isinstance(c, (int, float)) and not isinstance(c, bool)) for c in cells)
        if numeric and any(c is not None for c in cells):
            out[name] = np.array([np.nan if c is None else c for c in cells], dtype=float)
        else:
            out[name] = cells
    return out


def _series(chart):
    import numpy as np
    return {s["name"]: (np.asarray(s["x"], dtype=float), np.asarray(s["y"], dtype=float)) for s in chart["series"]}


def _names(backends):
    if backends is None:
        return []
    return [backends] if isinstance(backends, str) else list(backends)


def _out(out):
    return None if out is None else os.fspath(out)


def compare(scene, backends=None, settings=None, duration=5.0, dt=None, windows=10, window=0.25, out=None, jobs=1,
            footing="defaults", footing_substeps=4):
    """One scene on several backends (`vroc compare`): divergence, events, invariants, timings.
    backends: names, the first is the reference (default: all); settings {"backend.key": value};
    footing: "defaults", "equal" (footing_substeps internal steps per frame) or "both" (`--footing`)."""
    return HarnessResult(_vroc._compare(os.fspath(scene), _names(backends), settings, float(duration), dt,
                                        int(windows), float(window), _out(out), int(jobs), str(footing),
                                        int(footing_substeps)))


def check(backends=None, settings=None, only=(), long=False, stress=False, scenes_dir="", out=None, jobs=1,
          footing="defaults", footing_substeps=4):
    """The closed-form checks (`vroc check`), optionally only some scenarios or with the stress section;
    footing: "defaults", "equal" or "both" (`--footing`)."""
    return HarnessResult(_vroc._check(_names(backends), settings, list(only), bool(long), bool(stress),
                                      os.fspath(scenes_dir), _out(out), int(jobs), str(footing), int(footing_substeps)))


def sweep(scene, backends=None, settings=None, dts=(), duration=2.0, windows=10, window=0.1, vary=(), out=None, jobs=1,
          footing="defaults", footing_substeps=4):
    """Cost against accuracy over frame steps (`vroc sweep`); vary: ["backend.key=v1,v2", ...];
    footing: "defaults" or "equal" (`--footing`)."""
    return HarnessResult(_vroc._sweep(os.fspath(scene), _names(backends), settings, [float(d) for d in dts],
                                      float(duration), int(windows), float(window), list(vary), _out(out), int(jobs),
                                      str(footing), int(footing_substeps)))


def ensemble(scene, backends=None, settings=None, members=32, perturb="", duration=4.0, dt=None, seed=1, out=None,
             jobs=1, footing="defaults", footing_substeps=4):
    """Perturbed members per backend and two-sample tests between backends (`vroc ensemble`);
    footing: "defaults" or "equal" (`--footing`)."""
    return HarnessResult(_vroc._ensemble(os.fspath(scene), _names(backends), settings, int(members), perturb,
                                         float(duration), dt, int(seed), _out(out), int(jobs), str(footing),
                                         int(footing_substeps)))


def write_report(result, out):
    """Writes a HarnessResult's metrics.json and report.html into `out`; returns the report's path."""
    return result.write_report(out)
